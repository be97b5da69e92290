#include "tests/support/freedoom.h"

#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <unistd.h>

namespace pvs::test {

namespace fs = std::filesystem;

std::optional<std::string> find_freedoom(const std::string& name)
{
    const char* env = std::getenv("PVSCOPE_FREEDOOM_DIR");
    const fs::path path = fs::path(env ? env : "/usr/share/games/doom") / name;
    std::error_code ec;
    if (!fs::exists(path, ec))
        return std::nullopt;
    return path.string();
}

const char* gl_builder_name(GlBuilder builder)
{
    switch (builder) {
    case GlBuilder::glbsp_v2: return "glbsp -v2";
    case GlBuilder::glbsp_v3: return "glbsp -v3";
    case GlBuilder::glbsp_v5: return "glbsp -v5";
    case GlBuilder::zdbsp_v2: return "zdbsp -g";
    case GlBuilder::zdbsp_v5: return "zdbsp -g -5";
    }
    return "?";
}

namespace {

fs::path scratch_dir()
{
    static const fs::path dir = [] {
        fs::path d = fs::temp_directory_path() / ("pvscope-gl-nodes-" + std::to_string(getpid()));
        fs::create_directories(d);
        return d;
    }();
    return dir;
}

std::string shell_quoted(const std::string& s) { return "'" + s + "'"; }

} // namespace

std::optional<std::string> gl_nodes_file(const std::string& wad, GlBuilder builder)
{
    static std::mutex mutex;
    static std::map<std::pair<std::string, GlBuilder>, std::optional<std::string>> made;
    std::lock_guard lock(mutex);
    auto [slot, fresh] = made.try_emplace({wad, builder});
    if (!fresh)
        return slot->second;
    const std::string stem = fs::path(wad).stem().string();
    const int tag = int(builder);
    std::string out, command;
    switch (builder) {
    case GlBuilder::glbsp_v2:
    case GlBuilder::glbsp_v3:
    case GlBuilder::glbsp_v5: {
        const char* version = builder == GlBuilder::glbsp_v2 ? "-v2" : builder == GlBuilder::glbsp_v3 ? "-v3" : "-v5";
        out = (scratch_dir() / (stem + "-" + std::to_string(tag) + ".gwa")).string();
        command = std::string("glbsp -q -xp ") + version + " " + shell_quoted(wad) + " -o " + shell_quoted(out);
        break;
    }
    case GlBuilder::zdbsp_v2:
    case GlBuilder::zdbsp_v5:
        out = (scratch_dir() / (stem + "-" + std::to_string(tag) + ".wad")).string();
        command = std::string("zdbsp -t -g ") + (builder == GlBuilder::zdbsp_v5 ? "-5 " : "") + "-o " + shell_quoted(out) +
                  " " + shell_quoted(wad);
        break;
    }
    command += " > /dev/null 2>&1";
    if (std::system(command.c_str()) == 0 && fs::exists(out))
        slot->second = out;
    return slot->second;
}

} // namespace pvs::test
