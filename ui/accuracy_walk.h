// Image-space accuracy over a set of cameras: for each camera, cull, render the whole zone into
// the exact ID buffer (what is really on screen), and measure what the culled set would pop or
// overdraw (visibility/eval/image_accuracy.h). Optionally time the culled frame's textured render.
#pragma once

#include "visibility/camera.h"
#include "visibility/culler.h"
#include "visibility/eval/image_accuracy.h"
#include "visibility/zone.h"

#include <functional>
#include <span>
#include <vector>

namespace pvs::ui {

struct WalkRow {
    Camera camera;
    CullStats cull;
    double render_ms = 0; // textured render of the culled frame; 0 unless timed
    ImageAccuracy accuracy;
    // Popping pixels re-checked by an exact ray cast through the pixel centre (up to
    // WalkOptions::max_rays_per_camera of them, evenly spread): confirmed when the first face the
    // ray hits was not drawn. A rasteriser shows, here and there, a pixel of a face behind a
    // T-junction crack in the level's geometry; the ray tells those apart from true popping.
    uint64_t popping_checked = 0;
    uint64_t popping_confirmed = 0;
};

struct WalkOptions {
    CullMode mode = CullMode::PvsFrustum;
    uint32_t width = 320, height = 240;
    bool time_culled_render = false;
    uint32_t max_rays_per_camera = 64;
    // Called after each camera with (done, total); return false to stop early.
    std::function<bool(size_t, size_t)> progress;
};

// `pvs` may be null (frustum only). Camera aspects are set to width/height.
std::vector<WalkRow> run_accuracy_walk(const Zone& zone, const Pvs* pvs, std::span<const Camera> cameras,
                                       const WalkOptions& options);

} // namespace pvs::ui
