// RowWordBoxes (the culler's stage for sparse rows) gives exactly the per-region answers: on a
// grid of boxes in spatial id order and shuffled, with empty and non-finite boxes among them, for
// random frustums (all six planes and the sides only) and rows sparse and dense; and it counts the
// words it read and the word boxes it decided.
#include "tests/support/culling_inputs.h"
#include "visibility/bit_row.h"
#include "visibility/math/frustum_boxes.h"
#include "visibility/row_word_boxes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <random>

namespace pvs {
namespace {

// The shared grid with a word of empty boxes only (ids 128..191).
std::vector<Aabb> grid_boxes_with_empty_word(std::mt19937& rng, int n, bool shuffled)
{
    std::vector<Aabb> boxes = test::grid_boxes(rng, n, shuffled);
    for (int i = 128; i < 192; ++i)
        boxes[size_t(i)] = Aabb{};
    return boxes;
}

using test::random_frustum;
using test::random_row;

void check(bool shuffled)
{
    std::mt19937 rng(shuffled ? 3 : 5);
    const std::vector<Aabb> boxes = grid_boxes_with_empty_word(rng, 20, shuffled);
    const FrustumBoxes regions(boxes);
    const RowWordBoxes words(boxes);
    std::vector<uint32_t> got(boxes.size());
    size_t decided = 0, word_boxes = 0;
    for (int f = 0; f < 80; ++f) {
        const Frustum frustum = random_frustum(rng, f % 2 ? 300.0f : 5000.0f);
        const auto row = random_row(rng, boxes.size(), f % 4 == 0 ? 1.0 : f % 4 == 1 ? 0.02 : 0.3);
        for (auto which : {FrustumBoxes::Planes::All, FrustumBoxes::Planes::SidesOnly}) {
            const auto planes = FrustumBoxes::prepare(frustum, which, words.coordinate_scale());
            std::vector<uint32_t> expected;
            for (uint32_t r = 0; r < boxes.size(); ++r)
                if (bits::test(row, r) && regions.intersects(r, planes))
                    expected.push_back(r);
            CullWork work;
            got.resize(boxes.size());
            got.resize(words.collect(row, regions, planes, got.data(), work));
            ASSERT_EQ(got, expected) << "frustum " << f << (shuffled ? ", shuffled ids" : "");
            EXPECT_EQ(work.row_words, row.size());
            decided += expected.size();
            word_boxes += work.blocks;
        }
    }
    EXPECT_GT(decided, 2000u);
    EXPECT_GT(word_boxes, 500u);
}

TEST(RowWordBoxes, SpatialIdsGiveThePerRegionAnswers) { check(false); }
TEST(RowWordBoxes, ShuffledIdsGiveThePerRegionAnswers) { check(true); }

} // namespace
} // namespace pvs
