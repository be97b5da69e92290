// The culler's frustum stage for rows with fewer candidates than the block stage takes
// (region_blocks.h): one box per word of a PVS row (regions 64w .. 64w + 63), so a frame reads the
// row a word at a time and tests one box for each word that holds a candidate. A word box wholly
// outside the frustum drops its candidates, one wholly inside takes them all, and only words the
// frustum's boundary crosses test their candidates' boxes, four or eight at a time, against the
// planes that cross the word's box (FrustumBoxes::intersect_mask). Quake's and EverQuest's regions
// come in tree order, so a word's regions lie together and most words are decided whole; a zone
// whose ids are scattered gets word boxes the frustum crosses, and costs a box test per word more
// than testing each candidate.
//
// Contract. collect() writes the row's regions whose boxes intersect the prepared planes, exactly
// as FrustumBoxes::intersects answers for each (FrustumBoxes::classify decides a word box with a
// round-off margin; regions with an empty or non-finite box are left out of their word's box and
// tested one by one), ascending, and counts its work (CullWork: the same counts for the
// same zone, row and camera on any machine. Read-only after construction.
#pragma once

#include "visibility/cull_work.h"
#include "visibility/math/aabb.h"
#include "visibility/math/frustum_boxes.h"

#include <cstdint>
#include <span>
#include <vector>

namespace pvs {

class RowWordBoxes {
public:
    explicit RowWordBoxes(std::span<const Aabb> region_boxes);

    // The largest absolute coordinate of a region box: prepare the planes with it.
    float coordinate_scale() const { return scale_; }

    // Writes to `out` (room for the row's set bits) the regions of `row` whose boxes intersect the
    // prepared planes (`regions`: every region's box, by id); ascending. Returns their count.
    size_t collect(std::span<const uint64_t> row, const FrustumBoxes& regions, const FrustumBoxes::PlaneGroups& planes,
                   uint32_t* out, CullWork& work) const;

    size_t memory_bytes() const
    {
        return word_boxes_.memory_bytes() + odd_.capacity() * sizeof(uint64_t);
    }

private:
    uint32_t region_count_ = 0;
    std::vector<uint64_t> odd_; // per word: the regions tested one by one (empty or non-finite box)
    std::vector<uint8_t> has_box_; // per word: whether any regular region gives it a box
    float scale_ = 0.0f;
    FrustumBoxes word_boxes_;
};

} // namespace pvs
