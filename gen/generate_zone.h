// Procedural demo zones: `pvscope gen --rooms N --seed S`. An indoor zone on a grid (see
// voxel_level.h) with a proper BSP tree (kd_bsp.h), one region per open convex box, meshes on
// the boundaries between open and solid space with procedural textures (gen_textures.h), and
// region flags for the water pool, lava pit, slime channel, PvP arena and zone-line doorway.
//
// PVS: with GenParams::bake the zone is baked when it is made, portal-full at test level 4 from
// the portals of its own tree (build_zone_portals, visibility/portal/portal_vis.h), and its notes
// say so ("PVS baked with portal-full ..."); without it the zone has no PVS (the culler falls
// back to the frustum) and the notes say that. bake is off in a plain GenParams{rooms, seed,
// cell} (tests and benchmarks that only want geometry stay fast) and on in demo_zone_params(),
// which `pvscope gen` and the inspector's demo zone start from. The bake is deterministic (the
// same rows for any thread count), so the whole zone still is.
// N runs from 5 to 5000 so benchmarks can show how costs grow with the size of a zone.
// Deterministic: the same (rooms, seed, cell_size, bake) gives the same zone.
#pragma once

#include "visibility/portal/portal_vis.h"
#include "visibility/zone.h"

#include <cstdint>
#include <functional>

namespace pvs::gen {

struct GenParams {
    int rooms = 40;
    uint64_t seed = 1;
    float cell_size = 32.0f; // world units per grid cell (a room is 3 cells high)
    bool bake = false;       // bake a portal-full PVS when the zone is made (see above)
    unsigned bake_threads = 0; // the bake's worker threads, 0 = all cores (no effect on the result)
    // Called during the bake as VisParams::progress is (fraction done; return false to cancel:
    // the zone then has no PVS and its notes say the bake was cancelled). Optional.
    std::function<bool(double fraction)> bake_progress = nullptr;
};

// Throws std::invalid_argument for rooms outside [5, 5000] or a non-positive cell size.
Zone generate_zone(const GenParams& params);

// Bakes a generated zone's PVS from portals built from its tree with `method` (Full at level 4,
// as GenParams::bake does; Fast for outdoor zones); the zone's notes say how it was made, or that
// the bake was cancelled (progress returned false: then the zone has no PVS). `enclosed`: open
// leaves touching the world box are a leak worth a warning (indoor zones); outdoor zones are open
// up to the box (the sky, the edges) by design.
void bake_generated_pvs(Zone& zone, unsigned threads, const std::function<bool(double)>& progress,
                        VisParams::Method method, bool enclosed);

// The built-in demo zone (the README's first command opens it), baked.
inline GenParams demo_zone_params() { return {60, 2026, 32.0f, true}; }

} // namespace pvs::gen
