#include "tests/support/test_data.h"

#include "wld/common/read_file.h"
#include "wld/zone_file.h"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>

namespace pvs::test {

std::string shared_data_dir()
{
    if (const char* env = std::getenv("PVSCOPE_SHARED_DATA_DIR"))
        return env;
    return PVSCOPE_SHARED_DATA_DIR;
}

std::optional<std::string> find_shared_data(const std::string& relative)
{
    std::filesystem::path path = std::filesystem::path(shared_data_dir()) / relative;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return std::nullopt;
    return path.lexically_normal().string();
}

bool shared_data_required()
{
    const char* env = std::getenv("PVSCOPE_REQUIRE_SHARED_DATA");
    return env && std::string(env) == "1";
}

std::vector<uint8_t> read_bytes(const std::string& path) { return read_whole_file(path); }

const Zone* shared_zone(const std::string& relative)
{
    static std::map<std::string, std::unique_ptr<Zone>> loaded;
    auto& slot = loaded[relative];
    if (!slot) {
        if (auto path = find_shared_data(relative))
            slot = std::make_unique<Zone>(load_zone(*path));
    }
    return slot.get();
}

std::string param_name(const std::string& relative_path)
{
    std::string name = std::filesystem::path(relative_path).stem().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)))
            c = '_';
    return name;
}

} // namespace pvs::test
