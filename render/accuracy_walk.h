// Image-space accuracy over a set of cameras: for each camera, cull, render the whole zone into
// the exact ID buffer (what is really on screen), and measure what the culled set would pop or
// overdraw (visibility/eval/image_accuracy.h). Optionally time the culled frame's textured render.
//
// Popping that cannot be fooled: a raster pixel whose face was not drawn counts as confirmed
// popping only when the sight line from the camera to the point of that face is open in the
// zone's geometry (visibility/eval/sight_check.h: traced through the BSP tree's leaves). A
// rasteriser shows, here and there, a pixel of a face behind a crack between two triangles of a
// wall (T-junction gaps); those pixels are Blocked by the wall's solid leaf and are counted apart
// as cracks; pixels seen across a boundary the zone's vis counts opaque by its content rule but
// no face closes (Quake 2: translucent slime against plain slime) are "unfaced": the raster shows
// what is beyond, the game's engine draws a hole, no PVS of that rule owes it; pixels the check cannot decide (no tree, a face seen edge-on) are counted apart as
// unknown. Pixels whose
// line is open but passes within kSightMargin of a wall's edge are grazing, counted apart too.
// A confirmed pixel's line ends in a region the culler dropped (the PVS's failure); an open line
// that ends in a region it kept, at a face none of the kept regions lists, is "unlisted": the
// zone's face-to-region lists failed there (Quake's marksurfaces), not the PVS. Every popping
// pixel is checked; the check is a walk down the tree, about a microsecond.
//
// Translucent faces (Quake 2 glass, translucent water) hide nothing: in a zone that has any, each
// camera also gets the ID picture without them, and the face seen through a translucent one is
// measured as the face in front is (needed, may pop, its sight line checked); a pixel pops once,
// by the face in front when that was not drawn, else by the face behind. Behind several
// translucent layers only the first opaque face is measured.
//
// Several PVSs can be measured over the same cameras in one pass (run_accuracy_walks): each
// camera's ID buffer is rendered once and each pixel's sight line traced at most once, whatever
// the number of PVSs (pvscope compare measures every method this way).
#pragma once

#include "visibility/camera.h"
#include "visibility/culler.h"
#include "visibility/eval/image_accuracy.h"
#include "visibility/portal/media.h"
#include "visibility/zone.h"

#include <functional>
#include <span>
#include <vector>

namespace pvs::ui {

struct WalkRow {
    Camera camera;
    CullStats cull;
    double render_ms = 0; // textured render of the culled frame; 0 unless timed
    ImageAccuracy accuracy; // raster popping (accuracy.popping_pixels) and overdraw
    uint64_t popping_confirmed = 0; // raster popping pixels whose sight line is open: true popping
    uint64_t popping_cracks = 0;    // raster popping pixels whose sight line is blocked
    uint64_t popping_unknown = 0;   // raster popping pixels the sight check cannot decide (Sight::Unknown)
    uint64_t popping_unlisted = 0;  // open sight lines that end in a region the culler kept, at a
                                    // face no kept region lists: the zone's face lists, not the PVS
    uint64_t popping_grazing = 0;   // raster popping pixels whose sight line is open by less than
                                    // kSightMargin (sight_check.h): hair-thin lines vis drops
    uint64_t popping_unfaced = 0;   // raster popping pixels seen across a boundary the content rule
                                    // makes opaque but no face closes (Sight::Unfaced): the map's hole
    // Regions the confirmed sight lines end in (where the popped faces were seen), ascending:
    // each must be in the PVS row of the camera's region and is not.
    std::vector<uint32_t> confirmed_regions;
};

struct WalkOptions {
    CullMode mode = CullMode::PvsFrustum;
    uint32_t width = 320, height = 240;
    bool time_culled_render = false;
    bool distance_stage = false; // CullOptions::distance_stage (the cameras' far_distance is the far clip)
    SkyPortals sky = SkyPortals::SkyToSky; // the content rule of the sight-line check
    // One region per camera to cull from instead of the culler's own tree walk (CullOptions::
    // forced_region): a stale region cache being measured. Empty: the culler's walk.
    std::span<const int32_t> forced_regions;
    // Called after each camera with (done, total); return false to stop early.
    std::function<bool(size_t, size_t)> progress;
};

// `pvs` may be null (frustum only). Camera aspects are set to width/height.
std::vector<WalkRow> run_accuracy_walk(const Zone& zone, const Pvs* pvs, std::span<const Camera> cameras,
                                       const WalkOptions& options);

// One walk per PVS (null entries: frustum only) over the same cameras: result[p][camera].
std::vector<std::vector<WalkRow>> run_accuracy_walks(const Zone& zone, std::span<const Pvs* const> pvss,
                                                     std::span<const Camera> cameras, const WalkOptions& options);

} // namespace pvs::ui
