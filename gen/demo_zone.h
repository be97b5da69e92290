// The built-in demo zone (the inspector's "open demo", `pvscope` with no file): made once, then
// read from a cache, because baking its PVS (portal-full) takes longer than reading it.
//
// Cache: <dir>/demo-<rooms>-<seed>-v<kDemoCacheVersion>.s3d (plus "-c<cell>" when the cell size
// is not 32), an EverQuest archive written by write_eq_zone. <dir> is $XDG_CACHE_HOME/pvscope,
// else $HOME/.cache/pvscope. kDemoCacheVersion goes up whenever the generator, the baker or the
// writer would make different bytes, so an old file is simply not found.
//
// Behaviour: a readable cache file (it loads and has one PVS row per region) is used as it is.
// Otherwise the zone is generated (GenParams::bake as given: demo_zone_params() bakes), written
// to the cache through a temporary file renamed into place (an interrupted write never leaves a
// half file under the real name), and read back from those bytes — so the zone returned is the
// same on the first run and on every later one. A cache directory that cannot be made or
// written is not an error: the zone is returned all the same and DemoZoneSource says why it
// was not cached. A corrupt cache file is replaced.
// The zone's notes say where it came from (cache hit or made now, and how its PVS was made).
#pragma once

#include "visibility/zone.h"
#include "gen/generate_zone.h"

#include <string>

namespace pvs::gen {

inline constexpr int kDemoCacheVersion = 1;

struct DemoZoneSource {
    std::string cache_path;  // the file used or written; empty when there is no cache directory
    bool from_cache = false; // read from an existing cache file
    bool cached = false;     // written to the cache now
    std::string problem;     // why the cache was not used or not written, if so
};

// $XDG_CACHE_HOME/pvscope, else $HOME/.cache/pvscope; empty when neither variable is set.
std::string default_demo_cache_dir();
std::string demo_cache_file_name(const GenParams& params);

// The demo zone of `params`, cached in `cache_dir` (empty: not cached). Throws only what
// generate_zone throws (bad params).
Zone load_or_make_demo_zone(const GenParams& params, const std::string& cache_dir, DemoZoneSource* source = nullptr);

// load_or_make_demo_zone(demo_zone_params(), default_demo_cache_dir()).
Zone demo_zone();

} // namespace pvs::gen
