#include "ui/gui/fps_report.h"

#include "ui/gui/inspector_state.h"
#include "visibility/eval/camera_set.h"

#include <algorithm>
#include <array>
#include <cstdio>

namespace pvs::gui {

namespace {

// Mean, median and p95 of `v`.
std::array<double, 3> spread(std::vector<double> v)
{
    if (v.empty())
        return {0.0, 0.0, 0.0};
    std::sort(v.begin(), v.end());
    double sum = 0;
    for (double x : v)
        sum += x;
    return {sum / double(v.size()), v[v.size() / 2], v[v.size() * 95 / 100]};
}

std::vector<double> after(const std::vector<double>& v, size_t skip)
{
    return {v.begin() + long(std::min(skip, v.size())), v.end()};
}

} // namespace

void FpsReport::plan_flight(const InspectorState& state, uint32_t count, uint64_t seed)
{
    flight_.clear();
    if (count > 0 && state.has_zone())
        flight_ = random_cameras_in_regions(state.zone(), count, seed, state.view_camera());
}

const Camera& FpsReport::next_camera() const
{
    const size_t drawn = frame_ms_.size();
    return flight_[drawn < warmup_ ? 0 : std::min(drawn - warmup_, flight_.size() - 1)];
}

void FpsReport::lap(const InspectorState& state, const Phases& phases)
{
    const auto now = std::chrono::steady_clock::now();
    frame_ms_.push_back(std::chrono::duration<double, std::milli>(now - last_).count());
    last_ = now;
    const double cull_ms = state.last_cull().cull_us() / 1000.0;
    render_ms_.push_back(state.last_render().draw_ms);
    cull_us_.push_back(state.last_cull().cull_us());
    overlay_ms_.push_back(state.last_overlay_ms());
    const double panels = phases.inspector_ms - phases.inspector_wait_ms - cull_ms - state.last_render().draw_ms -
                          state.last_overlay_ms();
    panels_ms_.push_back(std::max(0.0, panels));
    gl_ms_.push_back(phases.gl_ms);
    wait_ms_.push_back(phases.wait_ms);
    present_ms_.push_back(phases.present_ms);
    faces_.push_back(double(state.last_render().faces_drawn));
}

void FpsReport::print(const InspectorState& state) const
{
    const std::vector<double> frames = after(frame_ms_, warmup_);
    if (frames.empty())
        return;
    const auto f = spread(frames), r = spread(after(render_ms_, warmup_)), c = spread(after(cull_us_, warmup_));
    const auto median = [&](const std::vector<double>& v) { return spread(after(v, warmup_))[1]; };
    double render_sum = 0, faces_sum = 0;
    for (size_t i = warmup_; i < faces_.size(); ++i) {
        render_sum += render_ms_[i];
        faces_sum += faces_[i];
    }
    std::printf("pvscope: %zu frames timed (%zu warm-up left out), viewport %ux%u, cull %s%s\n"
                "  frame  mean %.2f ms (%.1f fps), median %.2f ms (%.1f fps), p95 %.2f ms (%.1f fps)\n"
                "  render mean %.2f ms, median %.2f ms; cull mean %.1f us; %u of %u regions drawn (last frame)\n"
                "  where it goes (medians): cull %.3f ms, picture %.2f ms, overlays %.2f ms, panels %.2f ms, "
                "GL draw %.2f ms, waiting for the last swap %.2f ms, the swap %.2f ms (overlapped)\n"
                "  picture: %.0f faces drawn a frame (mean), %.2f us a face\n",
                frames.size(), std::min(warmup_, frame_ms_.size()), state.image().width, state.image().height,
                cull_mode_name(state.cull_mode), flying() ? ", one seeded camera a frame" : "", f[0], 1000.0 / f[0],
                f[1], 1000.0 / f[1], f[2], 1000.0 / f[2], r[0], r[1], c[0], state.last_cull().regions_after_frustum,
                state.last_cull().regions_total, c[1] / 1000.0, r[1], median(overlay_ms_), median(panels_ms_),
                median(gl_ms_), median(wait_ms_), median(present_ms_), faces_sum / double(frames.size()),
                faces_sum > 0 ? 1000.0 * render_sum / faces_sum : 0.0);
    if (!flying())
        return;
    const size_t worst = size_t(std::max_element(frames.begin(), frames.end()) - frames.begin());
    const Camera& cam = flight_[std::min(worst, flight_.size() - 1)];
    std::printf("  slowest: camera %zu, %.2f ms: --camera=%.1f,%.1f,%.1f,%.1f,%.1f\n", worst, frames[worst],
                double(cam.position.x), double(cam.position.y), double(cam.position.z), double(cam.yaw_degrees),
                double(cam.pitch_degrees));
}

} // namespace pvs::gui
