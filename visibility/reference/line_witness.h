// What a line through open space proves, and the rows that collect it (the reference's core).
//
// A line through a point p in open space, traced both ways from p (tree_trace.h) until each
// direction is stopped, gives its open stretch: the regions it crosses, in order. Any two regions
// X and Y of the stretch see each other: the part of the line between a point of X and a point of
// Y is a segment in open space, and the content rule is symmetric (media.h). So one line sets
// every pair of its stretch, both ways: every bit it sets has a witness.
//
// WitnessRows is the dense bit matrix the bits go into, shared by the sampling threads: a set is
// a relaxed atomic OR after a relaxed read (late in a bake nearly every pair is already set), so
// the rows are the same whatever the order of the sets. Each row holds its own region from the
// start.
#pragma once

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
    // Sets every pair of `stretch` (regions, repeats allowed). Returns whether a pair was missing
    // from `before` (a snapshot() of these rows): the line found something new since then.
    bool set_all_pairs(std::span<const uint32_t> stretch, std::span<const uint64_t> before);
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
    double t_begin = 0.0, t_end = 0.0;
};

// The open stretch of the line through `point` along ±`direction` (unit), out to `reach` each
// way. Returns false (and an empty stretch) when `point` is not in open space.
bool open_stretch(const TreeTracer& tracer, const glm::dvec3& point, const glm::dvec3& direction, double reach,
                  TreeTracer::Scratch& scratch, Stretch& stretch);

} // namespace pvs
