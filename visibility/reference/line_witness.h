// What a line through open space proves, and the rows that collect it (the reference's core).
//
// A line through a point p in open space, traced both ways from p (tree_trace.h) until each
// direction is stopped, gives its open stretch: the regions it crosses, in order. Any two regions
// X and Y of the stretch see each other: the part of the line between a point of X and a point of
// Y is a segment in open space, and the content rule is symmetric (media.h). A pair is set, both
// ways, when that segment (from the middle of the line's run through X to the middle of its run
// through Y) is also open as a beam (TreeTracer::open_beam, kBeamMargin): a line that joins two
// regions only by grazing a wall's corner or slipping through a gap thinner than the margin
// proves nothing a vis tool or a viewer would call visible (found on end.bsp: a line crossing
// from one room to the next 0.0007 units from a wall, where the portal builder had no portal).
// Only pairs not yet set are checked, so late in a bake the beams cost next to nothing.
//
// WitnessRows is the dense bit matrix the bits go into, shared by the sampling threads: a set is
// a relaxed atomic OR after a relaxed read (late in a bake nearly every pair is already set), so
// the rows are the same whatever the order of the sets. Each row holds its own region from the
// start.
#pragma once

#include "visibility/math/aabb.h"
#include "visibility/pvs.h"
#include "visibility/reference/tree_trace.h"

#include <atomic>
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace pvs {

class WitnessRows {
public:
    explicit WitnessRows(uint32_t regions);

    uint32_t region_count() const { return regions_; }
    size_t words_per_row() const { return words_; }
    std::span<const uint64_t> row(uint32_t r) const { return {bits_.data() + size_t(r) * words_, words_}; }
    bool test(uint32_t a, uint32_t b) const
    {
        std::atomic_ref<uint64_t> word(bits_[size_t(a) * words_ + (b >> 6)]);
        return (word.load(std::memory_order_relaxed) >> (b & 63)) & 1u;
    }
    void set(uint32_t a, uint32_t b)
    {
        std::atomic_ref<uint64_t> word(bits_[size_t(a) * words_ + (b >> 6)]);
        const uint64_t bit = uint64_t{1} << (b & 63);
        if (!(word.load(std::memory_order_relaxed) & bit))
            word.fetch_or(bit, std::memory_order_relaxed);
    }
    uint64_t count() const;
    Pvs to_pvs() const;
    // A copy of the bits (the state a round's decisions are made on).
    std::vector<uint64_t> snapshot() const { return bits_; }
    size_t memory_bytes() const { return bits_.capacity() * sizeof(uint64_t); }

private:
    uint32_t regions_;
    size_t words_;
    mutable std::vector<uint64_t> bits_; // mutable: test() reads through std::atomic_ref
};

// The open stretch of a line through a point: its regions in order along +direction
// (consecutive repeats collapsed) and the extent point + t * direction, t in [t_begin, t_end].
struct Stretch {
    std::vector<uint32_t> regions;
    std::vector<double> t_mid; // per entry of regions: the middle of the line's run through it
    double t_begin = 0.0, t_end = 0.0;
};

// The open stretch of the line through `point` along ±`direction` (unit), out to `reach` each
// way. Returns false (and an empty stretch) when `point` is not in open space.
bool open_stretch(const TreeTracer& tracer, const glm::dvec3& point, const glm::dvec3& direction, double reach,
                  TreeTracer::Scratch& scratch, Stretch& stretch);
// The same, ending where the line leaves `world` each way (the box the portals and the region
// sampler take regions in, zone_portal_world): a leaf open to the sky or the edge of the map runs
// on without end in the tree, and a line must not prove a pair through its part beyond the world
// (from there it would look over every hill). False when `point` is outside `world`.
bool open_stretch(const TreeTracer& tracer, const glm::dvec3& point, const glm::dvec3& direction, const Aabb& world,
                  TreeTracer::Scratch& scratch, Stretch& stretch);

// Sets the pairs of the line's stretch that are not set yet and whose segment is open as a beam
// (above). Returns the number of bits set.
uint64_t witness_pairs(const TreeTracer& tracer, const glm::dvec3& point, const glm::dvec3& direction,
                       const Stretch& stretch, WitnessRows& rows, TreeTracer::Scratch& scratch);

// The pairs (source, X) of the line's stretch that this line proves (the same beam test), set in
// `proven`'s row `source` only, whatever other lines found: what one region's own lines prove,
// which depends on that region's lines alone (reference_vis.h, "Sources").
void witness_source_pairs(const TreeTracer& tracer, const glm::dvec3& point, const glm::dvec3& direction,
                          const Stretch& stretch, uint32_t source, WitnessRows& proven, TreeTracer::Scratch& scratch);

} // namespace pvs
