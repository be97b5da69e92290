#include "render/culled_frame.h"

#include "render/overlay_lines.h"

namespace pvs::ui {

CulledFrame render_culled(SoftwareRenderer& renderer, Culler& culler, const Camera& view,
                          const std::optional<Camera>& locked_cull_camera, const CullOptions& cull_options,
                          RenderMode mode)
{
    CulledFrame frame;
    const Camera& cull_camera = locked_cull_camera ? *locked_cull_camera : view;
    frame.cull = culler.cull(cull_camera, cull_options, frame.visible);
    frame.image = renderer.render(culler.zone(), view, frame.visible, mode);
    if (locked_cull_camera && mode != RenderMode::IdBuffer)
        draw_frustum(frame.image, view, *locked_cull_camera, kLockedFrustumColor);
    return frame;
}

} // namespace pvs::ui
