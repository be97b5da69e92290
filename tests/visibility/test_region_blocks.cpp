// RegionBlocks (the culler's block stage) gives exactly the per-region answers: on clustered and
// scattered boxes in any id order, with empty and non-finite boxes among them, for random
// frustums (all six planes and the sides only), far-plane spheres and rows, including boxes
// placed to touch a block's boundary, in Morton blocks and in blocks that follow the file's own
// spatial numbering; and the intersect mask equals intersects() box by box.
#include "tests/support/culling_inputs.h"
#include "visibility/bit_row.h"
#include "visibility/math/frustum_boxes.h"
#include "visibility/region_blocks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <random>

namespace pvs {
namespace {

using test::random_frustum;
using test::random_row;

// The shared grid, ids shuffled (as outdoor zones).
std::vector<Aabb> grid_boxes(std::mt19937& rng, int n) { return test::grid_boxes(rng, n, true); }

// collect() against each region's own test, for random frustums and rows; returns the regions kept.
size_t check_collect(const std::vector<Aabb>& boxes, const RegionBlocks& blocks, std::mt19937& rng)
{
    const FrustumBoxes regions(boxes);
    RegionBlocks::Scratch scratch;
    std::vector<uint32_t> got(boxes.size());
    size_t decided = 0;
    for (int f = 0; f < 60; ++f) {
        const Frustum frustum = random_frustum(rng, f % 2 ? 300.0f : 5000.0f);
        const auto row = random_row(rng, boxes.size(), f % 3 == 0 ? 1.0 : 0.6);
        for (auto which : {FrustumBoxes::Planes::All, FrustumBoxes::Planes::SidesOnly}) {
            const auto planes = FrustumBoxes::prepare(frustum, which, blocks.coordinate_scale());
            std::vector<uint32_t> expected;
            for (uint32_t r = 0; r < boxes.size(); ++r)
                if (bits::test(row, r) && regions.intersects(r, planes))
                    expected.push_back(r);
            got.resize(boxes.size());
            got.resize(blocks.collect(row, regions, planes, scratch, got.data()));
            EXPECT_EQ(got, expected) << "frustum " << f;
            if (got != expected)
                return 0;
            decided += expected.size();
        }
    }
    return decided;
}

// keep_near() against each region's own distance test, for random spheres and rows.
void check_keep_near(const std::vector<Aabb>& boxes, const RegionBlocks& blocks, std::mt19937& rng)
{
    const FrustumBoxes regions(boxes);
    std::uniform_real_distribution<float> u(-500.0f, 500.0f), radius(10.0f, 600.0f);
    std::vector<uint64_t> near(bits::words_for(boxes.size()));
    for (int t = 0; t < 80; ++t) {
        const glm::vec3 eye{u(rng), u(rng), u(rng)};
        float limit = radius(rng);
        limit *= limit;
        if (t % 4 == 0) // exactly the distance of some box: the boundary case
            limit = regions.squared_distance(uint32_t(t * 7 % boxes.size()), eye);
        const auto row = random_row(rng, boxes.size(), 0.7);
        const size_t kept = blocks.keep_near(row, regions, eye, limit, near);
        size_t expected = 0;
        for (uint32_t r = 0; r < boxes.size(); ++r) {
            const bool in = bits::test(row, r) && regions.squared_distance(r, eye) <= limit;
            expected += in;
            ASSERT_EQ(bits::test(near, r), in) << "region " << r << ", sphere " << t;
        }
        EXPECT_EQ(kept, expected);
    }
}

TEST(RegionBlocks, CollectGivesEveryRegionsOwnAnswer)
{
    std::mt19937 rng(21);
    const std::vector<Aabb> boxes = grid_boxes(rng, 20);
    const RegionBlocks blocks(boxes);
    EXPECT_FALSE(blocks.blocks_in_id_order()) << "shuffled ids: the Morton order is more compact";
    EXPECT_GT(check_collect(boxes, blocks, rng), 1000u);
}

// A file whose ids are already spatial (as a tree numbers its leaves): cells numbered 4 x 4 x 4
// cube by cube, so runs of 64 ids are compact and the blocks take the file's order, reading
// their row bits as runs. Two odd boxes among them shift every later run off the 64-bit word
// boundaries and make two blocks that are not runs (tested bit by bit).
std::vector<Aabb> cube_numbered_boxes()
{
    std::vector<Aabb> boxes;
    for (int cz = 0; cz < 2; ++cz)
        for (int cy = 0; cy < 5; ++cy)
            for (int cx = 0; cx < 5; ++cx)
                for (int z = 0; z < 4; ++z)
                    for (int y = 0; y < 4; ++y)
                        for (int x = 0; x < 4; ++x) {
                            const glm::vec3 cell(cx * 4 + x, cy * 4 + y, cz * 4 + z);
                            boxes.push_back({cell * 40.0f - 400.0f, (cell + 1.0f) * 40.0f - 400.0f});
                        }
    boxes.insert(boxes.begin() + 5, Aabb{});
    boxes.insert(boxes.begin() + 700, Aabb{glm::vec3(0.0f), glm::vec3(std::numeric_limits<float>::quiet_NaN())});
    return boxes;
}

TEST(RegionBlocks, BlocksInTheFilesOwnOrderGiveEveryRegionsOwnAnswer)
{
    std::mt19937 rng(23);
    const std::vector<Aabb> boxes = cube_numbered_boxes();
    const RegionBlocks blocks(boxes);
    EXPECT_TRUE(blocks.blocks_in_id_order()) << "ids numbered cube by cube are as compact as the Morton order";
    EXPECT_GT(check_collect(boxes, blocks, rng), 1000u);
    check_keep_near(boxes, blocks, rng);
}

TEST(RegionBlocks, KeepNearGivesEveryRegionsOwnAnswer)
{
    std::mt19937 rng(5);
    const std::vector<Aabb> boxes = grid_boxes(rng, 20);
    check_keep_near(boxes, RegionBlocks(boxes), rng);
}

TEST(RegionBlocks, IntersectMaskEqualsEachBoxsAnswer)
{
    std::mt19937 rng(9);
    const std::vector<Aabb> boxes = grid_boxes(rng, 12);
    const FrustumBoxes packed(boxes);
    for (int f = 0; f < 30; ++f) {
        const auto planes = FrustumBoxes::prepare(random_frustum(rng, 800.0f), FrustumBoxes::Planes::All);
        for (uint32_t first = 0; first + 64 <= boxes.size(); first += 37)
            for (uint32_t count : {1u, 3u, 4u, 17u, 64u}) {
                const uint64_t mask = packed.intersect_mask(first, count, planes);
                for (uint32_t i = 0; i < 64; ++i)
                    ASSERT_EQ((mask >> i) & 1, i < count ? uint64_t(packed.intersects(first + i, planes)) : 0u);
            }
    }
}

// The clip-flag shortcut: a box holding boxes [first, first + count) is classified, and the boxes
// are then tested against only the planes crossing it (and only the fours `wanted` names). Every
// answer must still be the box's own, on boxes that touch the planes' margins too (the grid's
// boxes share faces, and the frustums are random), with all six planes and the sides only. The
// grid is in row order here (not shuffled), so a run of ids is a compact strip.
TEST(RegionBlocks, CrossingPlanesOnlyGiveEachBoxsAnswer)
{
    std::mt19937 rng(17);
    std::vector<Aabb> boxes;
    for (int z = 0; z < 8; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
                boxes.push_back({glm::vec3(x, y, z) * 40.0f - 400.0f, glm::vec3(x + 1, y + 1, z + 1) * 40.0f - 400.0f});
    const FrustumBoxes packed(boxes);
    const float scale = 400.0f;
    size_t shortcuts = 0, checked = 0;
    for (int f = 0; f < 60; ++f) {
        const Frustum frustum = random_frustum(rng, f % 2 ? 300.0f : 800.0f);
        for (auto which : {FrustumBoxes::Planes::All, FrustumBoxes::Planes::SidesOnly}) {
            const auto planes = FrustumBoxes::prepare(frustum, which, scale);
            for (uint32_t first = 0; first + 16 <= boxes.size(); first += 8) {
                const uint32_t count = first % 16 ? 8 : 16;
                Aabb hull;
                for (uint32_t i = first; i < first + count; ++i)
                    hull.grow(boxes[i]);
                const FrustumBoxes holder(std::vector<Aabb>{hull});
                unsigned crossing = FrustumBoxes::all_planes(planes);
                if (holder.classify(0, planes, crossing) == FrustumBoxes::Side::Outside)
                    continue;
                shortcuts += crossing != FrustumBoxes::all_planes(planes);
                const uint64_t wanted = (uint64_t(rng()) << 32) | rng();
                const uint64_t mask = packed.intersect_mask(first, count, planes, crossing, wanted);
                for (uint32_t i = 0; i < count; ++i) {
                    if ((wanted >> (i & ~3u)) & 15u) // its four is tested
                        ASSERT_EQ((mask >> i) & 1, uint64_t(packed.intersects(first + i, planes)))
                            << "box " << first + i << ", frustum " << f;
                    else
                        ASSERT_EQ((mask >> i) & 1, 0u);
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(shortcuts, 500u) << "few strips had a plane wholly in front: the shortcut went untested";
    EXPECT_GT(checked, 10000u);
}

} // namespace
} // namespace pvs
