// The culler's distance and frustum stages for big zones: regions grouped into blocks of 64 that
// lie close together, with a box per block and a tree of boxes over neighbouring blocks, so a
// frustum or a far-plane sphere decides a whole block, or a whole subtree, with one test where it
// can. Blocks follow the file's own numbering when it is spatial (Quake's leaves and EverQuest's
// regions come in tree order: runs of ids are compact), else the Morton order of the boxes'
// centres: the id order is taken when its blocks' boxes have at most kIdOrderSlack times the
// Morton blocks' total surface. A block that is a run of consecutive ids reads its 64 row bits
// with two word operations instead of 64 bit tests (and sets its output bits the same way);
// another block keeps its ids as (row word, mask) pairs, so taking all its regions the row holds
// is a word operation per word its ids fall in.
//
// collect() walks the tree with the camera's row: a box wholly outside the frustum drops its
// regions, a box wholly inside takes every region of it the row holds, and only blocks the
// frustum's boundary crosses test their regions, four or eight at a time
// (FrustumBoxes::intersect_mask, on the blocks' own copies of the boxes), against only the planes
// that cross the block: a run block only where the row holds one of the four, another block all
// its boxes first and the row only for those the frustum keeps (on the dense rows this stage runs
// for, gathering 64 scattered row bits costs more than the tests it saves); a node's children test only the planes crossing it (as
// Quake's clip flags). FrustumBoxes::classify decides with a round-off margin, so every region
// gets exactly the answer FrustumBoxes::intersects gives it: the output equals the per-region
// stage's, ascending. keep_near() does the same for the far-plane sphere. Regions whose box is
// empty or not finite are tested one by one, always.
//
// Both count their work (cull_work.h): nodes decided, boxes tested, row words read.
//
// Read-only after construction; the caller gives the scratch (one per thread).
#pragma once

#include "visibility/cull_work.h"
#include "visibility/math/aabb.h"
#include "visibility/math/frustum_boxes.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace pvs {

class RegionBlocks {
public:
    static constexpr uint32_t kBlock = 64;
    static constexpr double kIdOrderSlack = 1.0;

    explicit RegionBlocks(std::span<const Aabb> region_boxes);

    // The largest absolute coordinate of a region box: prepare the planes with it.
    float coordinate_scale() const { return scale_; }
    size_t region_count() const { return region_count_; }

    // The caller's working memory (one per thread), reused across frames.
    struct Scratch {
        std::vector<uint64_t> bits;
    };

    // Writes to `out` (room for the row's set bits) the regions of `row` whose boxes intersect the
    // prepared planes, as `regions` (every region's box, by id) answers for each; ascending.
    // Returns their count.
    size_t collect(std::span<const uint64_t> row, const FrustumBoxes& regions, const FrustumBoxes::PlaneGroups& planes,
                   Scratch& scratch, uint32_t* out, CullWork& work) const;
    size_t collect(std::span<const uint64_t> row, const FrustumBoxes& regions, const FrustumBoxes::PlaneGroups& planes,
                   Scratch& scratch, uint32_t* out) const
    {
        CullWork ignored;
        return collect(row, regions, planes, scratch, out, ignored);
    }

    // Sets in `near` (words_for(region count) words, overwritten) the regions of `row` whose
    // boxes come within squared distance `limit` of `eye` (regions.squared_distance(r, eye) <=
    // limit, the same answers as testing each) and returns their count.
    size_t keep_near(std::span<const uint64_t> row, const FrustumBoxes& regions, const glm::vec3& eye, float limit,
                     std::span<uint64_t> near, CullWork& work) const;
    size_t keep_near(std::span<const uint64_t> row, const FrustumBoxes& regions, const glm::vec3& eye, float limit,
                     std::span<uint64_t> near) const
    {
        CullWork ignored;
        return keep_near(row, regions, eye, limit, near, ignored);
    }

    size_t memory_bytes() const;
    // Whether the blocks follow the file's numbering (else the Morton order); for reports and tests.
    bool blocks_in_id_order() const { return in_id_order_; }

private:
    template <class Decide, class Take>
    void walk(uint32_t level, uint32_t node, unsigned tests, Decide&& decide, Take&& take) const;
    template <class Decide, class Take>
    void walk_all(unsigned tests, Decide&& decide, Take&& take) const;
    uint64_t members_in_row(uint32_t block, std::span<const uint64_t> row) const;
    bool any_member_in_row(uint32_t block, std::span<const uint64_t> row) const;
    void take_members_in_row(uint32_t block, std::span<const uint64_t> row, std::span<uint64_t> out) const;
    void take_tested_members(uint32_t block, uint64_t tested, std::span<const uint64_t> row, std::span<uint64_t> out) const;
    void make_spans();
    void set_members(uint32_t block, uint64_t members, std::span<uint64_t> out) const;

    // Members are made in this order, and the constructor fills some while making others:
    // odd_ while member_ is made, the level tables while nodes_ is.
    size_t region_count_ = 0;
    std::vector<uint32_t> odd_;          // regions with an empty or non-finite box
    bool in_id_order_ = false;
    std::vector<uint32_t> member_;       // region ids, block by block (blocks of kBlock, the last shorter)
    std::vector<uint32_t> run_start_;    // per block: its first id when its members are consecutive ids, else kNoRun
    static constexpr uint32_t kNoRun = UINT32_MAX;
    // Blocks that are not runs: their members as words of an id row, (word, mask of the members
    // in it) from span_first_[block] to span_first_[block + 1], so a block wholly inside the
    // frustum takes its members with a word operation per word it touches, not a bit per member.
    std::vector<uint32_t> span_first_;
    std::vector<uint32_t> span_word_;
    std::vector<uint64_t> span_mask_;
    std::vector<uint32_t> level_first_;  // per level: its first node in nodes_
    std::vector<uint32_t> level_size_;   // per level: its node count
    float scale_ = 0.0f;
    FrustumBoxes member_boxes_;          // the members' boxes, in member_ order
    FrustumBoxes nodes_;                 // every level's boxes, level 0 (blocks) first
};

} // namespace pvs
