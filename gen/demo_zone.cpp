#include "gen/demo_zone.h"

#include "visibility/file_error.h"
#include "wld/common/read_file.h"
#include "wld/eq/eq_zone_reader.h"
#include "wld/eq/eq_zone_writer.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <unistd.h>

namespace pvs::gen {

namespace {

namespace fs = std::filesystem;

// A cache file is usable when it loads and carries a full PVS (a generated demo zone always
// has regions; an unbaked file written with bake off is usable too when bake is off).
bool usable(const Zone& zone, const GenParams& params)
{
    if (zone.region_count() == 0)
        return false;
    return !params.bake || (zone.baked_pvs && zone.baked_pvs->region_count() == zone.region_count());
}

std::optional<Zone> read_cache(const std::string& path, const GenParams& params, DemoZoneSource& source)
{
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        return std::nullopt;
    try {
        Zone zone = eq::load_eq_zone(read_whole_file(path), path);
        if (usable(zone, params))
            return zone;
        source.problem = path + ": no full PVS in the cached zone; made again";
    } catch (const std::exception& e) { // FileError for a corrupt file; bad_alloc and the like too
        source.problem = std::string(e.what()) + "; made again";
    }
    return std::nullopt;
}

// Writes through a temporary name and renames, so readers never see half a file.
bool write_cache(const std::string& dir, const std::string& path, const std::vector<uint8_t>& bytes,
                 DemoZoneSource& source)
{
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) {
        source.problem = "cannot make the cache directory " + dir + ": " + ec.message();
        return false;
    }
    const std::string temporary = path + ".tmp" + std::to_string(::getpid());
    try {
        write_whole_file(temporary, bytes);
    } catch (const FileError& e) {
        source.problem = std::string("cannot write the cache: ") + e.what();
        fs::remove(temporary, ec);
        return false;
    }
    fs::rename(temporary, path, ec);
    if (ec) {
        source.problem = "cannot move the cache file into place: " + ec.message();
        fs::remove(temporary, ec);
        return false;
    }
    return true;
}

} // namespace

std::string default_demo_cache_dir()
{
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return (fs::path(xdg) / "pvscope").string();
    if (const char* home = std::getenv("HOME"); home && *home)
        return (fs::path(home) / ".cache" / "pvscope").string();
    return {};
}

std::string demo_cache_file_name(const GenParams& params)
{
    std::string name = "demo-" + std::to_string(params.rooms) + "-" + std::to_string(params.seed) + "-v" +
                       std::to_string(kDemoCacheVersion);
    if (params.cell_size != 32.0f)
        name += "-c" + std::to_string(std::lround(params.cell_size * 1000.0f)) + "m";
    if (!params.bake)
        name += "-nopvs";
    return name + ".s3d";
}

Zone load_or_make_demo_zone(const GenParams& params, const std::string& cache_dir, DemoZoneSource* source_out)
{
    DemoZoneSource source;
    const std::string name = demo_cache_file_name(params);
    if (!cache_dir.empty())
        source.cache_path = (fs::path(cache_dir) / name).string();
    std::optional<Zone> zone;
    if (!source.cache_path.empty())
        zone = read_cache(source.cache_path, params, source);
    source.from_cache = zone.has_value();
    if (!zone) {
        const Zone made = generate_zone(params);
        const std::vector<uint8_t> bytes = eq::write_eq_zone(made, "demo");
        if (!source.cache_path.empty())
            source.cached = write_cache(cache_dir, source.cache_path, bytes, source);
        else
            source.problem = "no cache directory ($XDG_CACHE_HOME and $HOME are not set)";
        // Read back from the bytes, so that this run shows exactly what later runs will read.
        zone = eq::load_eq_zone(bytes, source.cached ? source.cache_path : name);
    }
    zone->source.notes.push_back("demo zone: " + std::to_string(params.rooms) + " rooms, seed " +
                                 std::to_string(params.seed) +
                                 (params.bake ? ", PVS baked with portal-full (level 4) when made"
                                              : ", made without a PVS"));
    zone->source.notes.push_back(source.from_cache ? "read from the cache " + source.cache_path
                                 : source.cached   ? "made now and cached in " + source.cache_path
                                                   : "made now, not cached: " + source.problem);
    if (source_out)
        *source_out = source;
    return std::move(*zone);
}

Zone demo_zone() { return load_or_make_demo_zone(demo_zone_params(), default_demo_cache_dir()); }

} // namespace pvs::gen
