// The whole-frame times of a scripted `inspect --report-fps` run, and the summary it prints:
// the frame as mean, median and p95, and where it goes (the median of each phase: cull, the
// picture, the overlays, the panels, ImGui's GL draw, the wait for the last swap, and the swap
// itself, which runs on a thread of its own while the next frame is drawn), with the picture's
// cost per drawn face. With a flight (`--cameras N`) each timed frame is drawn from the next of
// N seeded cameras (random_cameras_in_regions) after the warm-up frames, and the summary names
// the slowest camera, so a slow view can be opened again with --camera.
#pragma once

#include "visibility/camera.h"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pvs::gui {

class InspectorState;

class FpsReport {
public:
    // `warmup` frames (the windows are sized and the scene built) are drawn but not reported.
    explicit FpsReport(size_t warmup) : warmup_(warmup) {}

    // The camera flight, made on the open zone from its view camera's lens; none when count is 0.
    void plan_flight(const InspectorState& state, uint32_t count, uint64_t seed);
    bool flying() const { return !flight_.empty(); }
    // The camera for the frame about to be drawn (the first one during the warm-up).
    const Camera& next_camera() const;
    // Frames to draw in all: the warm-up and one a camera, or the warm-up and `frames`.
    size_t frames_needed(size_t frames) const { return warmup_ + (flying() ? flight_.size() : frames); }

    // The main thread's phases of one frame, in ms (InspectorState reports its own).
    struct Phases {
        double inspector_ms = 0;      // draw_inspector: the panels, and the state's frame() within them
        double inspector_wait_ms = 0; // the part of it spent waiting for the last swap (the upload)
        double gl_ms = 0;             // ImGui's draw data to GL
        double wait_ms = 0;           // waiting for the last swap in all (inspector_wait_ms and after)
        double present_ms = 0;        // the last swap and glFinish, on the presenting thread (overlapped)
    };
    // After a frame has been presented.
    void lap(const InspectorState& state, const Phases& phases);
    void print(const InspectorState& state) const;

private:
    size_t warmup_;
    std::vector<Camera> flight_;
    std::vector<double> frame_ms_, render_ms_, cull_us_, overlay_ms_, panels_ms_, gl_ms_, wait_ms_, present_ms_;
    std::vector<double> faces_; // faces the picture drew
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

} // namespace pvs::gui
