#include "visibility/reference/line_witness.h"

#include "visibility/bit_row.h"

#include <algorithm>
#include <limits>

namespace pvs {

WitnessRows::WitnessRows(uint32_t regions) : regions_(regions), words_(bits::words_for(regions))
{
    bits_.assign(size_t(regions) * words_, 0);
    for (uint32_t r = 0; r < regions; ++r)
        bits_[size_t(r) * words_ + (r >> 6)] |= uint64_t{1} << (r & 63);
}

uint64_t WitnessRows::count() const { return bits::count(bits_); }

Pvs WitnessRows::to_pvs() const
{
    return Pvs::build(regions_, [&](uint32_t r, std::span<uint64_t> out) {
        std::copy_n(bits_.begin() + std::ptrdiff_t(size_t(r) * words_), words_, out.begin());
        return true;
    });
}

namespace {

bool open_stretch_between(const TreeTracer& tracer, const glm::dvec3& point, const glm::dvec3& direction,
                          double reach_back, double reach_forward, TreeTracer::Scratch& scratch, Stretch& stretch);

// How far the line from `point` (inside `box`) runs along `direction` before it leaves the box.
double exit_distance(const Aabb& box, const glm::dvec3& point, const glm::dvec3& direction)
{
    double t = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        if (direction[k] > 0.0)
            t = std::min(t, (double(box.max[k]) - point[k]) / direction[k]);
        else if (direction[k] < 0.0)
            t = std::min(t, (double(box.min[k]) - point[k]) / direction[k]);
    }
    return std::max(t, 0.0);
}

} // namespace

bool open_stretch(const TreeTracer& tracer, const glm::dvec3& point, const glm::dvec3& direction, const Aabb& world,
                  TreeTracer::Scratch& scratch, Stretch& stretch)
{
    const bool inside = !world.empty() && point.x >= world.min.x && point.y >= world.min.y && point.z >= world.min.z &&
                        point.x <= world.max.x && point.y <= world.max.y && point.z <= world.max.z;
    if (!inside) {
        stretch.regions.clear();
        stretch.t_mid.clear();
        stretch.t_begin = stretch.t_end = 0.0;
        return false;
    }
    return open_stretch_between(tracer, point, direction, exit_distance(world, point, -direction),
                                exit_distance(world, point, direction), scratch, stretch);
}

bool open_stretch(const TreeTracer& tracer, const glm::dvec3& point, const glm::dvec3& direction, double reach,
                  TreeTracer::Scratch& scratch, Stretch& stretch)
{
    return open_stretch_between(tracer, point, direction, reach, reach, scratch, stretch);
}

namespace {

bool open_stretch_between(const TreeTracer& tracer, const glm::dvec3& point, const glm::dvec3& direction,
                          double reach_back, double reach_forward, TreeTracer::Scratch& scratch, Stretch& stretch)
{
    std::vector<uint32_t>& regions = stretch.regions;
    std::vector<double>& runs = stretch.t_mid; // first the runs' [t0, t1] pairs, then their middles
    regions.clear();
    runs.clear();
    stretch.t_begin = stretch.t_end = 0.0;
    double sign = -1.0; // t along +direction: the backward walk's t is negated
    auto push = [&](int32_t region, double t0, double t1) {
        const double a = sign * t0, b = sign * t1;
        if (regions.empty() || regions.back() != uint32_t(region)) {
            regions.push_back(uint32_t(region));
            runs.push_back(std::min(a, b));
            runs.push_back(std::max(a, b));
            return;
        }
        runs[runs.size() - 2] = std::min({runs[runs.size() - 2], a, b});
        runs.back() = std::max({runs.back(), a, b});
    };
    // Backwards first, then reversed, so the stretch runs along +direction.
    const TraceEnd back = tracer.trace(point, -direction, reach_back, scratch, push);
    if (regions.empty())
        return false;
    stretch.t_begin = -back.t;
    std::reverse(regions.begin(), regions.end());
    std::reverse(runs.begin(), runs.end()); // pairs reversed too: [t1, t0] -> fixed below
    for (size_t k = 0; k + 1 < runs.size(); k += 2)
        std::swap(runs[k], runs[k + 1]);
    // The forward walk starts in the same region (or its neighbour across p's plane).
    const uint32_t join = regions.back();
    const double join_t0 = runs[runs.size() - 2], join_t1 = runs.back();
    regions.pop_back();
    runs.resize(runs.size() - 2);
    const size_t before = regions.size();
    sign = 1.0;
    const TraceEnd forward = tracer.trace(point, direction, reach_forward, scratch, push);
    // Where p lies on a plane between two regions the two walks start on either side of it;
    // they see each other only when the content rule says so. A forward walk blocked at once
    // leaves the backward part alone.
    if (regions.size() == before || !tracer.passes(int32_t(join), int32_t(regions[before]))) {
        regions.resize(before);
        runs.resize(2 * before);
        regions.push_back(join);
        runs.push_back(join_t0);
        runs.push_back(join_t1);
    } else {
        stretch.t_end = forward.t;
        if (regions[before] != join) {
            regions.insert(regions.begin() + std::ptrdiff_t(before), join);
            runs.insert(runs.begin() + std::ptrdiff_t(2 * before), {join_t0, join_t1});
        } else
            runs[2 * before] = join_t0; // the run continues across p
    }
    for (size_t k = 0; k < regions.size(); ++k)
        runs[k] = 0.5 * (runs[2 * k] + runs[2 * k + 1]);
    runs.resize(regions.size());
    return true;
}

} // namespace

uint64_t witness_pairs(const TreeTracer& tracer, const glm::dvec3& point, const glm::dvec3& direction,
                       const Stretch& stretch, WitnessRows& rows, TreeTracer::Scratch& scratch)
{
    uint64_t set = 0;
    const std::vector<uint32_t>& regions = stretch.regions;
    for (size_t i = 0; i < regions.size(); ++i)
        for (size_t j = i + 1; j < regions.size(); ++j) {
            const uint32_t a = regions[i], b = regions[j];
            if (a == b || rows.test(a, b))
                continue;
            const double t0 = stretch.t_mid[i], t1 = stretch.t_mid[j];
            if (!tracer.open_beam(point + t0 * direction, direction, t1 - t0, kBeamMargin, scratch))
                continue;
            rows.set(a, b);
            rows.set(b, a);
            set += 2;
        }
    return set;
}

} // namespace pvs

namespace pvs {

void witness_source_pairs(const TreeTracer& tracer, const glm::dvec3& point, const glm::dvec3& direction,
                          const Stretch& stretch, uint32_t source, WitnessRows& proven, TreeTracer::Scratch& scratch)
{
    const std::vector<uint32_t>& regions = stretch.regions;
    for (size_t i = 0; i < regions.size(); ++i) {
        if (regions[i] != source)
            continue;
        for (size_t j = 0; j < regions.size(); ++j) {
            const uint32_t other = regions[j];
            if (other == source || proven.test(source, other))
                continue;
            const double t0 = std::min(stretch.t_mid[i], stretch.t_mid[j]),
                         t1 = std::max(stretch.t_mid[i], stretch.t_mid[j]);
            if (tracer.open_beam(point + t0 * direction, direction, t1 - t0, kBeamMargin, scratch))
                proven.set(source, other);
        }
    }
}

} // namespace pvs
