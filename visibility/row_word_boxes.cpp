#include "visibility/row_word_boxes.h"

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

std::vector<Aabb> word_boxes(std::span<const Aabb> regions, std::vector<uint64_t>& odd, std::vector<uint8_t>& has_box,
                             float& scale)
{
    const size_t words = bits::words_for(regions.size());
    std::vector<Aabb> boxes(words);
    odd.assign(words, 0);
    has_box.assign(words, 0);
    for (size_t r = 0; r < regions.size(); ++r) {
        if (!regular_box(regions[r])) {
            odd[r / 64] |= uint64_t{1} << (r % 64);
            continue;
        }
        boxes[r / 64].grow(regions[r]);
        has_box[r / 64] = 1;
        scale = std::max({scale, std::abs(regions[r].min.x), std::abs(regions[r].min.y), std::abs(regions[r].min.z),
                          std::abs(regions[r].max.x), std::abs(regions[r].max.y), std::abs(regions[r].max.z)});
    }
    return boxes;
}

// The groups of four bits (0-3, 4-7, ...) with a bit set.
uint32_t groups_of_four(uint64_t bits)
{
    bits |= bits >> 1;
    bits |= bits >> 2;
    return bits::popcount(bits & 0x1111111111111111u);
}

} // namespace

RowWordBoxes::RowWordBoxes(std::span<const Aabb> region_boxes)
    : region_count_(uint32_t(region_boxes.size())), word_boxes_(word_boxes(region_boxes, odd_, has_box_, scale_))
{
}

size_t RowWordBoxes::collect(std::span<const uint64_t> row, const FrustumBoxes& regions,
                             const FrustumBoxes::PlaneGroups& planes, uint32_t* out, CullWork& work) const
{
    size_t kept = 0;
    const uint32_t words = uint32_t(std::min(row.size(), odd_.size()));
    work.row_words += words;
    for (uint32_t w = 0; w < words; ++w) {
        const uint64_t candidates = row[w];
        if (candidates == 0)
            continue;
        const uint64_t odd = candidates & odd_[w];
        uint64_t regular = candidates & ~odd_[w], keep = 0;
        if (regular != 0 && has_box_[w]) {
            ++work.blocks;
            unsigned crossing = FrustumBoxes::all_planes(planes);
            switch (word_boxes_.classify(w, planes, crossing)) {
            case FrustumBoxes::Side::Outside:
                break;
            case FrustumBoxes::Side::Inside:
                keep = regular;
                break;
            case FrustumBoxes::Side::Partial: {
                const uint32_t first = w * 64, count = std::min<uint32_t>(64, region_count_ - first);
                keep = regular & regions.intersect_mask(first, count, planes, crossing, regular);
                work.boxes += 4 * groups_of_four(regular); // a group with a candidate tests all four
                break;
            }
            }
        }
        for (uint64_t m = odd; m != 0; m &= m - 1) {
            const uint32_t r = w * 64 + uint32_t(std::countr_zero(m));
            ++work.boxes;
            if (regions.intersects(r, planes))
                keep |= uint64_t{1} << (r % 64);
        }
        for (; keep != 0; keep &= keep - 1)
            out[kept++] = w * 64 + uint32_t(std::countr_zero(keep));
    }
    return kept;
}

} // namespace pvs
