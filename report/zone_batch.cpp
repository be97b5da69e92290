#include "report/zone_batch.h"

#include "wld/doom/wad_file.h"
#include "wld/doom/doom_map.h"
#include "wld/zone_file.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>

namespace pvs {

namespace {

namespace fs = std::filesystem;

std::string lower_extension(const fs::path& path)
{
    std::string e = path.extension().string();
    for (char& c : e)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

bool is_zone_file(const fs::path& path)
{
    const std::string e = lower_extension(path);
    return e == ".bsp" || e == ".s3d" || e == ".wad" || e == ".obj";
}

void add_file(const std::string& path, std::vector<BatchItem>& items)
{
    if (!doom::file_looks_like_wad(path)) {
        items.push_back({path, {}, {}});
        return;
    }
    try {
        const doom::WadFile wad = doom::read_wad(path);
        const std::vector<std::string> maps = doom::map_names(wad);
        if (maps.empty())
            items.push_back({path, {}, "no map in this WAD"});
        for (const std::string& map : maps)
            items.push_back({path, map, {}});
    } catch (const std::exception& e) {
        items.push_back({path, {}, e.what()});
    }
}

} // namespace

std::vector<BatchItem> batch_items(const std::vector<std::string>& inputs)
{
    std::vector<BatchItem> items;
    for (const std::string& input : inputs) {
        std::error_code ec;
        if (fs::is_directory(input, ec)) {
            std::vector<std::string> found;
            for (auto it = fs::recursive_directory_iterator(input, fs::directory_options::skip_permission_denied, ec);
                 !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
                if (it->is_regular_file(ec) && is_zone_file(it->path()))
                    found.push_back(it->path().string());
            std::sort(found.begin(), found.end());
            for (const std::string& path : found)
                add_file(path, items);
        } else if (fs::exists(input, ec)) {
            add_file(input, items);
        } else {
            items.push_back({input, {}, "no such file or folder"});
        }
    }
    return items;
}

LoadedZone load_batch_item(const BatchItem& item)
{
    LoadedZone out;
    if (!item.error.empty()) {
        out.error = item.error;
        return out;
    }
    const auto start = std::chrono::steady_clock::now();
    try {
        ZoneLoadOptions options;
        options.map = item.map;
        out.zone = load_zone(item.path, options);
    } catch (const std::exception& e) {
        out.error = e.what();
    }
    out.load_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace pvs
