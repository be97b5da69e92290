// One frame culled and drawn, as `pvscope render` and the inspector make it.
#pragma once

#include "render/software_renderer.h"
#include "visibility/camera.h"
#include "visibility/culler.h"

#include <optional>
#include <vector>

namespace pvs::ui {

// A frame as `pvscope render` makes it: the regions are culled from the culling camera and drawn
// seen from `view`. Normally the culling camera is `view` itself; with `locked_cull_camera` set
// (an inspector's "lock culling camera", Source's r_lockpvs) culling
// stays with that camera while the view moves, so what the culler keeps can be looked at from
// outside. The stats and the visible set are then the locked camera's (exactly what culling
// from it alone gives), and its view volume is drawn over the picture in kLockedFrustumColor
// (ui/overlay_lines.h), except in IdBuffer mode, whose pixels must stay face codes.
struct CulledFrame {
    CullStats cull;
    std::vector<uint32_t> visible; // region ids, ascending
    Image image;
};
CulledFrame render_culled(SoftwareRenderer& renderer, Culler& culler, const Camera& view,
                          const std::optional<Camera>& locked_cull_camera, const CullOptions& cull_options,
                          RenderMode mode);

} // namespace pvs::ui
