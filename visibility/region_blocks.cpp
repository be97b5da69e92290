#include "visibility/region_blocks.h"

#include "visibility/bit_row.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace pvs {
namespace {

bool regular_box(const Aabb& b)
{
    return !b.empty() && std::isfinite(b.min.x) && std::isfinite(b.min.y) && std::isfinite(b.min.z) &&
           std::isfinite(b.max.x) && std::isfinite(b.max.y) && std::isfinite(b.max.z);
}

// 10 bits of each coordinate, interleaved.
uint32_t morton(uint32_t x, uint32_t y, uint32_t z)
{
    auto spread = [](uint32_t v) {
        v &= 0x3ff;
        v = (v | (v << 16)) & 0x030000ff;
        v = (v | (v << 8)) & 0x0300f00f;
        v = (v | (v << 4)) & 0x030c30c3;
        v = (v | (v << 2)) & 0x09249249;
        return v;
    };
    return spread(x) | (spread(y) << 1) | (spread(z) << 2);
}

double block_surface(std::span<const Aabb> boxes, const std::vector<uint32_t>& order)
{
    double total = 0.0;
    for (size_t i = 0; i < order.size(); i += RegionBlocks::kBlock) {
        Aabb block;
        for (size_t k = i; k < std::min(order.size(), i + RegionBlocks::kBlock); ++k)
            block.grow(boxes[order[k]]);
        const glm::vec3 s = block.size();
        total += 2.0 * (double(s.x) * s.y + double(s.y) * s.z + double(s.z) * s.x);
    }
    return total;
}

// The regular regions in id order when that order's blocks are compact enough (see the header),
// else in Morton order of their centres; the others in `odd`.
std::vector<uint32_t> spatial_order(std::span<const Aabb> boxes, std::vector<uint32_t>& odd, bool& in_id_order)
{
    Aabb all;
    std::vector<uint32_t> regular;
    for (uint32_t r = 0; r < boxes.size(); ++r) {
        if (regular_box(boxes[r])) {
            regular.push_back(r);
            all.grow(boxes[r]);
        } else {
            odd.push_back(r);
        }
    }
    std::vector<std::pair<uint32_t, uint32_t>> keyed;
    keyed.reserve(regular.size());
    const glm::vec3 size = glm::max(all.size(), glm::vec3(1e-6f));
    for (uint32_t r : regular) {
        const glm::vec3 t = (boxes[r].center() - all.min) / size * 1023.0f;
        keyed.push_back({morton(uint32_t(std::clamp(t.x, 0.0f, 1023.0f)), uint32_t(std::clamp(t.y, 0.0f, 1023.0f)),
                                uint32_t(std::clamp(t.z, 0.0f, 1023.0f))),
                         r});
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<uint32_t> morton_order(keyed.size());
    for (size_t i = 0; i < keyed.size(); ++i)
        morton_order[i] = keyed[i].second;
    in_id_order = block_surface(boxes, regular) <= RegionBlocks::kIdOrderSlack * block_surface(boxes, morton_order);
    return in_id_order ? regular : morton_order;
}

// Per block: its first id when its members are consecutive ids.
std::vector<uint32_t> run_starts(const std::vector<uint32_t>& member, uint32_t no_run)
{
    std::vector<uint32_t> out;
    for (size_t first = 0; first < member.size(); first += RegionBlocks::kBlock) {
        const size_t count = std::min<size_t>(RegionBlocks::kBlock, member.size() - first);
        bool run = true;
        for (size_t i = 1; i < count && run; ++i)
            run = member[first + i] == member[first] + i;
        out.push_back(run ? member[first] : no_run);
    }
    return out;
}

std::vector<Aabb> member_boxes(std::span<const Aabb> boxes, const std::vector<uint32_t>& member)
{
    std::vector<Aabb> out(member.size());
    for (size_t i = 0; i < member.size(); ++i)
        out[i] = boxes[member[i]];
    return out;
}

// Level 0: one box per block of members; each level above joins neighbours two by two.
std::vector<Aabb> level_boxes(const std::vector<Aabb>& members, std::vector<uint32_t>& first, std::vector<uint32_t>& size)
{
    const size_t blocks = (members.size() + RegionBlocks::kBlock - 1) / RegionBlocks::kBlock;
    std::vector<Aabb> all(blocks);
    for (size_t i = 0; i < members.size(); ++i)
        all[i / RegionBlocks::kBlock].grow(members[i]);
    first.push_back(0);
    size.push_back(uint32_t(blocks));
    while (size.back() > 1) {
        const uint32_t below = first.back(), count = size.back();
        first.push_back(uint32_t(all.size()));
        size.push_back((count + 1) / 2);
        for (uint32_t i = 0; i < count; i += 2) {
            Aabb box = all[below + i];
            if (i + 1 < count)
                box.grow(all[below + i + 1]);
            all.push_back(box);
        }
    }
    return all;
}

float largest_coordinate(std::span<const Aabb> boxes)
{
    float scale = 0.0f;
    for (const Aabb& b : boxes)
        if (regular_box(b))
            for (int k = 0; k < 3; ++k)
                scale = std::max({scale, std::abs(b.min[k]), std::abs(b.max[k])});
    return scale;
}

} // namespace

RegionBlocks::RegionBlocks(std::span<const Aabb> region_boxes)
    : region_count_(region_boxes.size()), member_(spatial_order(region_boxes, odd_, in_id_order_)),
      run_start_(run_starts(member_, kNoRun)), scale_(largest_coordinate(region_boxes)), member_boxes_(member_boxes(region_boxes, member_)),
      nodes_(level_boxes(member_boxes(region_boxes, member_), level_first_, level_size_))
{
    make_spans();
}

void RegionBlocks::make_spans()
{
    span_first_.push_back(0);
    std::vector<uint32_t> ids;
    for (uint32_t block = 0; block < run_start_.size(); ++block) {
        if (run_start_[block] == kNoRun) {
            const uint32_t first = block * kBlock;
            ids.assign(member_.begin() + first, member_.begin() + std::min<size_t>(member_.size(), first + kBlock));
            std::sort(ids.begin(), ids.end());
            for (uint32_t id : ids) {
                if (span_word_.size() == span_first_.back() || span_word_.back() != id / 64) {
                    span_word_.push_back(id / 64);
                    span_mask_.push_back(0);
                }
                span_mask_.back() |= uint64_t{1} << (id % 64);
            }
        }
        span_first_.push_back(uint32_t(span_word_.size()));
    }
}

size_t RegionBlocks::memory_bytes() const
{
    return (member_.capacity() + run_start_.capacity() + odd_.capacity() + level_first_.capacity() + level_size_.capacity() +
            span_first_.capacity() + span_word_.capacity()) * sizeof(uint32_t) +
           span_mask_.capacity() * sizeof(uint64_t) + member_boxes_.memory_bytes() + nodes_.memory_bytes();
}

// Visits the tree from `node` at `level`: decide(box, tests) says Outside / Inside / Partial for a
// node's box, given `tests` (what the node's parent left to decide: for the frustum, the planes
// crossing it) and narrowing them for the children; take(block, side, tests) handles a whole
// block (Inside or Partial at level 0).
template <class Decide, class Take>
void RegionBlocks::walk(uint32_t level, uint32_t node, unsigned tests, Decide&& decide, Take&& take) const
{
    const FrustumBoxes::Side side = decide(level_first_[level] + node, tests);
    if (side == FrustumBoxes::Side::Outside)
        return;
    if (side == FrustumBoxes::Side::Partial && level > 0) {
        for (uint32_t child = node * 2; child <= node * 2 + 1 && child < level_size_[level - 1]; ++child)
            walk(level - 1, child, tests, decide, take);
        return;
    }
    const uint32_t first = node << level;
    const uint32_t last = std::min(level_size_[0], (node + 1) << level);
    for (uint32_t block = first; block < last; ++block)
        take(block, side, tests);
}

// walk() from every node of the top level.
template <class Decide, class Take>
void RegionBlocks::walk_all(unsigned tests, Decide&& decide, Take&& take) const
{
    if (level_size_.empty() || level_size_[0] == 0)
        return;
    const uint32_t top = uint32_t(level_size_.size() - 1);
    for (uint32_t node = 0; node < level_size_[top]; ++node)
        walk(top, node, tests, decide, take);
}

// Bit i set when the row holds the block's member i.
uint64_t RegionBlocks::members_in_row(uint32_t block, std::span<const uint64_t> row) const
{
    const uint32_t first = block * kBlock;
    const uint32_t count = std::min<uint32_t>(kBlock, uint32_t(member_.size()) - first);
    if (const uint32_t start = run_start_[block]; start != kNoRun) {
        const uint32_t word = start / 64, shift = start % 64;
        uint64_t bits = row[word] >> shift;
        if (shift != 0 && shift + count > 64)
            bits |= row[word + 1] << (64 - shift);
        return count == 64 ? bits : bits & ((uint64_t{1} << count) - 1);
    }
    uint64_t in_row = 0;
    for (uint32_t i = 0; i < count; ++i)
        in_row |= uint64_t(bits::test(row, member_[first + i])) << i;
    return in_row;
}

// Sets in `out` the region of each of the block's members that `members` holds.
void RegionBlocks::set_members(uint32_t block, uint64_t members, std::span<uint64_t> out) const
{
    if (const uint32_t start = run_start_[block]; start != kNoRun) {
        const uint32_t word = start / 64, shift = start % 64;
        out[word] |= members << shift;
        if (shift != 0 && (members >> (64 - shift)) != 0)
            out[word + 1] |= members >> (64 - shift);
        return;
    }
    for (; members != 0; members &= members - 1)
        bits::set(out, member_[block * kBlock + uint32_t(std::countr_zero(members))]);
}

// Whether the row holds any member of the block.
bool RegionBlocks::any_member_in_row(uint32_t block, std::span<const uint64_t> row) const
{
    if (run_start_[block] != kNoRun)
        return members_in_row(block, row) != 0;
    for (uint32_t s = span_first_[block]; s < span_first_[block + 1]; ++s)
        if ((row[span_word_[s]] & span_mask_[s]) != 0)
            return true;
    return false;
}

// Sets in `out` every member of the block that the row holds.
void RegionBlocks::take_members_in_row(uint32_t block, std::span<const uint64_t> row, std::span<uint64_t> out) const
{
    if (run_start_[block] != kNoRun) {
        set_members(block, members_in_row(block, row), out);
        return;
    }
    for (uint32_t s = span_first_[block]; s < span_first_[block + 1]; ++s)
        out[span_word_[s]] |= row[span_word_[s]] & span_mask_[s];
}

// Sets in `out` the members of `tested` (bit i: member i) that the row holds.
void RegionBlocks::take_tested_members(uint32_t block, uint64_t tested, std::span<const uint64_t> row,
                                       std::span<uint64_t> out) const
{
    for (; tested != 0; tested &= tested - 1) {
        const uint32_t region = member_[block * kBlock + uint32_t(std::countr_zero(tested))];
        if (bits::test(row, region))
            bits::set(out, region);
    }
}

size_t RegionBlocks::collect(std::span<const uint64_t> row, const FrustumBoxes& regions,
                             const FrustumBoxes::PlaneGroups& planes, Scratch& scratch, uint32_t* out,
                             CullWork& work) const
{
    std::vector<uint64_t>& taken = scratch.bits;
    taken.assign(row.size(), 0);
    work.row_words += uint32_t(row.size());
    // Only the planes that cross a node are tested for its children (as Quake's clip flags).
    const auto decide = [&](uint32_t box, unsigned& crossing) {
        ++work.blocks;
        return nodes_.classify(box, planes, crossing);
    };
    // A run block reads its row bits in two words and tests only the fours the row holds; another
    // block tests every member (a gather of 64 row bits costs more than the tests it saves on the
    // dense rows this stage runs for) and looks up the row only for those the frustum keeps.
    const auto take = [&](uint32_t block, FrustumBoxes::Side side, unsigned crossing) {
        if (side != FrustumBoxes::Side::Partial) {
            take_members_in_row(block, row, taken); // Inside: every member the row holds
            return;
        }
        const uint32_t first = block * kBlock;
        const uint32_t count = std::min<uint32_t>(kBlock, uint32_t(member_.size()) - first);
        if (run_start_[block] != kNoRun) {
            const uint64_t in_row = members_in_row(block, row);
            if (in_row != 0)
                set_members(block, in_row & member_boxes_.intersect_mask(first, count, planes, crossing, in_row), taken);
            uint64_t fours = in_row | in_row >> 1;
            fours |= fours >> 2;
            work.boxes += 4 * bits::popcount(fours & 0x1111111111111111u); // a group with a member tests all four
        } else if (any_member_in_row(block, row)) {
            take_tested_members(block, member_boxes_.intersect_mask(first, count, planes, crossing, ~uint64_t{0}), row, taken);
            work.boxes += count;
        }
    };
    walk_all(FrustumBoxes::all_planes(planes), decide, take);
    for (uint32_t r : odd_)
        if (bits::test(row, r)) {
            ++work.boxes;
            if (regions.intersects(r, planes))
                bits::set(taken, r);
        }
    size_t kept = 0;
    bits::for_each_set(std::span<const uint64_t>(taken), [&](size_t r) { out[kept++] = uint32_t(r); });
    return kept;
}

size_t RegionBlocks::keep_near(std::span<const uint64_t> row, const FrustumBoxes& regions, const glm::vec3& eye,
                               float limit, std::span<uint64_t> near, CullWork& work) const
{
    std::fill(near.begin(), near.end(), 0);
    work.row_words += uint32_t(row.size());
    // Float distances of a box inside a node differ from the node's by far less than this.
    constexpr float kMargin = 1e-4f;
    const auto decide = [&](uint32_t box, unsigned) {
        ++work.blocks;
        if (nodes_.squared_distance(box, eye) > limit * (1.0f + kMargin))
            return FrustumBoxes::Side::Outside;
        return nodes_.squared_reach(box, eye) < limit * (1.0f - kMargin) ? FrustumBoxes::Side::Inside
                                                                          : FrustumBoxes::Side::Partial;
    };
    // As collect(): a block that is not a run tests its members before looking up the row.
    const auto take = [&](uint32_t block, FrustumBoxes::Side side, unsigned) {
        if (side != FrustumBoxes::Side::Partial) {
            take_members_in_row(block, row, near);
            return;
        }
        const bool run = run_start_[block] != kNoRun;
        const uint32_t first = block * kBlock;
        const uint32_t count = std::min<uint32_t>(kBlock, uint32_t(member_.size()) - first);
        if (!run && !any_member_in_row(block, row))
            return;
        const uint64_t kept = member_boxes_.near_mask(first, count, eye, limit);
        work.boxes += count;
        if (run)
            set_members(block, kept & members_in_row(block, row), near);
        else
            take_tested_members(block, kept, row, near);
    };
    walk_all(0, decide, take);
    for (uint32_t r : odd_)
        if (bits::test(row, r)) {
            ++work.boxes;
            if (regions.squared_distance(r, eye) <= limit)
                bits::set(near, r);
        }
    size_t kept = 0;
    for (uint64_t w : near)
        kept += bits::popcount(w);
    return kept;
}

} // namespace pvs
