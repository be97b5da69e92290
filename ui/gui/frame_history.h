// The inspector's rolling record of per-frame times: a fixed-size ring (no allocation per frame)
// of the last kFrameHistoryCapacity frames, oldest first, and the totals gathered since a zone
// was opened (what the statistics export writes).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace pvs::gui {

// One frame's costs, in the units the panels show.
struct FrameTimes {
    float lookup_us = 0, pvs_us = 0, distance_us = 0, frustum_us = 0; // the culler's stages
    float render_ms = 0; // software render (draw + read-back)

    float cull_us() const { return lookup_us + pvs_us + distance_us + frustum_us; }
};

// ~8 seconds at 30 frames per second: enough for the culling panel's plot.
inline constexpr size_t kFrameHistoryCapacity = 256;

class FrameHistory {
public:
    void push(const FrameTimes& times)
    {
        frames_[next_] = times;
        next_ = (next_ + 1) % frames_.size();
        count_ = std::min(count_ + 1, frames_.size());
    }
    void clear() { next_ = count_ = 0; }
    size_t size() const { return count_; }
    // i = 0 is the oldest frame kept, size() - 1 the newest. Precondition: i < size().
    const FrameTimes& at(size_t i) const { return frames_[(next_ + frames_.size() - count_ + i) % frames_.size()]; }
    const FrameTimes& newest() const { return at(count_ - 1); }

private:
    std::array<FrameTimes, kFrameHistoryCapacity> frames_{};
    size_t next_ = 0;  // where the next frame goes
    size_t count_ = 0; // frames kept (<= capacity)
};

// Sums and maxima over every frame since the zone was opened; means are sum / frames.
struct CullTotals {
    uint64_t frames = 0;
    double lookup_us = 0, pvs_us = 0, distance_us = 0, frustum_us = 0, render_ms = 0;
    double max_cull_us = 0, max_render_ms = 0;
    uint64_t regions_after_pvs = 0, regions_drawn = 0;
    uint64_t triangles_after_pvs = 0, triangles_drawn = 0;
    uint64_t frames_in_region = 0; // frames whose culling camera was in a region
    uint64_t frames_pvs_used = 0;  // frames in which the PVS stage ran
};

} // namespace pvs::gui
