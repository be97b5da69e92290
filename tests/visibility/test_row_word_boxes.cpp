// RowWordBoxes (the culler's stage for sparse rows) gives exactly the per-region answers: on a
// grid of boxes in spatial id order and shuffled, with empty and non-finite boxes among them, for
// random frustums (all six planes and the sides only) and rows sparse and dense; and it counts the
// words it read and the word boxes it decided.
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

Frustum random_frustum(std::mt19937& rng, float far)
{
    std::uniform_real_distribution<float> u(-500.0f, 500.0f), fov(30.0f, 110.0f), aspect(0.6f, 2.0f);
    const glm::vec3 eye{u(rng), u(rng), u(rng)};
    glm::vec3 at{u(rng), u(rng), u(rng)};
    if (glm::length(at - eye) < 1.0f)
        at += glm::vec3(10.0f, 0.0f, 0.0f);
    const glm::mat4 proj = glm::perspective(glm::radians(fov(rng)), aspect(rng), 1.0f, far);
    return Frustum::from_view_projection(proj * glm::lookAt(eye, at, glm::vec3(0, 0, 1)));
}

// A grid of cells, x fastest (neighbouring ids lie together) or shuffled, a few odd boxes.
std::vector<Aabb> grid_boxes(std::mt19937& rng, int n, bool shuffled)
{
    std::vector<Aabb> boxes;
    for (int z = 0; z < n / 2; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                boxes.push_back({glm::vec3(x, y, z) * 40.0f - 400.0f, glm::vec3(x + 1, y + 1, z + 1) * 40.0f - 400.0f});
    if (shuffled)
        std::shuffle(boxes.begin(), boxes.end(), rng);
    boxes[3] = Aabb{};                                        // empty
    boxes[70].max.x = std::numeric_limits<float>::infinity(); // not finite
    boxes[71].min.y = std::numeric_limits<float>::quiet_NaN();
    for (int i = 128; i < 192; ++i)
        boxes[size_t(i)] = Aabb{}; // a word of empty boxes only
    return boxes;
}

std::vector<uint64_t> random_row(std::mt19937& rng, size_t n, double density)
{
    std::vector<uint64_t> row(bits::words_for(n), 0);
    std::bernoulli_distribution pick(density);
    for (size_t i = 0; i < n; ++i)
        if (pick(rng))
            bits::set(row, i);
    return row;
}

void check(bool shuffled)
{
    std::mt19937 rng(shuffled ? 3 : 5);
    const std::vector<Aabb> boxes = grid_boxes(rng, 20, shuffled);
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
