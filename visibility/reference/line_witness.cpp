#include "visibility/reference/line_witness.h"

#include "visibility/bit_row.h"

#include <algorithm>

namespace pvs {

WitnessRows::WitnessRows(uint32_t regions) : regions_(regions), words_(bits::words_for(regions))
{
    bits_.assign(size_t(regions) * words_, 0);
    for (uint32_t r = 0; r < regions; ++r)
        bits_[size_t(r) * words_ + (r >> 6)] |= uint64_t{1} << (r & 63);
}

bool WitnessRows::set_all_pairs(std::span<const uint32_t> stretch, std::span<const uint64_t> before)
{
    uint64_t fresh = 0;
    for (const uint32_t a : stretch)
        for (const uint32_t b : stretch) {
            fresh |= ~before[size_t(a) * words_ + (b >> 6)] & (uint64_t{1} << (b & 63));
            set(a, b);
        }
    return fresh != 0;
}

uint64_t WitnessRows::count() const { return bits::count(bits_); }

Pvs WitnessRows::to_pvs() const
{
    return Pvs::build(regions_, [&](uint32_t r, std::span<uint64_t> out) {
        std::copy_n(bits_.begin() + std::ptrdiff_t(size_t(r) * words_), words_, out.begin());
        return true;
    });
}

bool open_stretch(const TreeTracer& tracer, const glm::dvec3& point, const glm::dvec3& direction, double reach,
                  TreeTracer::Scratch& scratch, Stretch& stretch)
{
    std::vector<uint32_t>& regions = stretch.regions;
    regions.clear();
    stretch.t_begin = stretch.t_end = 0.0;
    auto push = [&](int32_t region, double, double) {
        if (regions.empty() || regions.back() != uint32_t(region))
            regions.push_back(uint32_t(region));
    };
    // Backwards first, then reversed, so the stretch runs along +direction.
    const TraceEnd back = tracer.trace(point, -direction, reach, scratch, push);
    if (regions.empty())
        return false;
    stretch.t_begin = -back.t;
    std::reverse(regions.begin(), regions.end());
    const uint32_t join = regions.back();
    regions.pop_back(); // the forward walk starts in the same region (or its neighbour across p's plane)
    const size_t before = regions.size();
    const TraceEnd forward = tracer.trace(point, direction, reach, scratch, push);
    // Where p lies on a plane between two regions the two walks start on either side of it;
    // they see each other only when the content rule says so. A forward walk blocked at once
    // leaves the backward part alone.
    if (regions.size() == before || !tracer.passes(int32_t(join), int32_t(regions[before]))) {
        regions.erase(regions.begin() + std::ptrdiff_t(before), regions.end());
        regions.push_back(join);
        return true;
    }
    stretch.t_end = forward.t;
    if (regions[before] != join)
        regions.insert(regions.begin() + std::ptrdiff_t(before), join);
    return true;
}

} // namespace pvs
