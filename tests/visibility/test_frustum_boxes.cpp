// FrustumBoxes (the culler's branch-free box test) gives exactly Frustum::intersects's answers
// (and intersects_sides's), which test_frustum.cpp checks against clip space: on random boxes
// and view directions, on boxes that touch a plane exactly (placed with the plane's own
// arithmetic), and on degenerate (flat and point) boxes.
#include "visibility/math/frustum_boxes.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <random>

namespace pvs {
namespace {

Frustum random_frustum(std::mt19937& rng)
{
    std::uniform_real_distribution<float> u(-200.0f, 200.0f), fov(30.0f, 120.0f), aspect(0.5f, 2.5f);
    const glm::vec3 eye{u(rng), u(rng), u(rng)};
    glm::vec3 at{u(rng), u(rng), u(rng)};
    if (glm::length(at - eye) < 1.0f)
        at += glm::vec3(10.0f, 0.0f, 0.0f);
    const glm::mat4 proj = glm::perspective(glm::radians(fov(rng)), aspect(rng), 1.0f, 300.0f);
    const glm::mat4 view = glm::lookAt(eye, at, glm::vec3(0, 0, 1));
    return Frustum::from_view_projection(proj * view);
}

std::vector<Aabb> random_boxes(std::mt19937& rng, size_t count)
{
    std::uniform_real_distribution<float> u(-400.0f, 400.0f), extent(0.0f, 60.0f);
    std::vector<Aabb> boxes(count);
    for (Aabb& b : boxes) {
        const glm::vec3 c{u(rng), u(rng), u(rng)};
        const glm::vec3 e{extent(rng), extent(rng), extent(rng)};
        b = {c - e, c + e};
        if (&b - boxes.data() < 50)
            b.max = b.min; // point boxes
    }
    return boxes;
}

TEST(FrustumBoxes, SameAnswersAsFrustumIntersectsOnRandomBoxes)
{
    std::mt19937 rng(11);
    const std::vector<Aabb> boxes = random_boxes(rng, 4000);
    const FrustumBoxes packed(boxes);
    int inside_all = 0, inside_sides = 0;
    for (int f = 0; f < 50; ++f) {
        const Frustum frustum = random_frustum(rng);
        const auto all = FrustumBoxes::prepare(frustum, FrustumBoxes::Planes::All);
        const auto sides = FrustumBoxes::prepare(frustum, FrustumBoxes::Planes::SidesOnly);
        for (uint32_t i = 0; i < boxes.size(); ++i) {
            ASSERT_EQ(packed.intersects(i, all), frustum.intersects(boxes[i])) << "frustum " << f << " box " << i;
            ASSERT_EQ(packed.intersects(i, sides), frustum.intersects_sides(boxes[i])) << "frustum " << f << " box " << i;
            inside_all += frustum.intersects(boxes[i]);
            inside_sides += frustum.intersects_sides(boxes[i]);
        }
    }
    // Both answers occur, and leaving out the near and far planes keeps more boxes.
    EXPECT_GT(inside_all, 1000);
    EXPECT_LT(inside_all, 50 * 4000 - 1000);
    EXPECT_GT(inside_sides, inside_all);
}

TEST(FrustumBoxes, CollectAllGivesTheBoxesThatIntersectInOrder)
{
    std::mt19937 rng(13);
    for (size_t count : {0u, 1u, 3u, 4u, 7u, 1001u}) { // whole groups of four and tails
        const std::vector<Aabb> boxes = random_boxes(rng, count);
        const FrustumBoxes packed(boxes);
        for (int f = 0; f < 20; ++f) {
            const Frustum frustum = random_frustum(rng);
            for (auto which : {FrustumBoxes::Planes::All, FrustumBoxes::Planes::SidesOnly}) {
                const auto planes = FrustumBoxes::prepare(frustum, which);
                std::vector<uint32_t> expected, got(count + 1, 0xFFFFFFFFu);
                for (uint32_t i = 0; i < count; ++i)
                    if (which == FrustumBoxes::Planes::All ? frustum.intersects(boxes[i]) : frustum.intersects_sides(boxes[i]))
                        expected.push_back(i);
                got.resize(packed.collect_all(planes, got.data()));
                EXPECT_EQ(got, expected) << count << " boxes, frustum " << f;
            }
        }
    }
}

TEST(FrustumBoxes, BoxesTouchingAPlaneAreKeptLikeTheScalarTest)
{
    // A box whose positive vertex lies on the left plane (distance 0 or within an ulp): the
    // scalar test keeps it exactly when distance >= 0; the packed test must agree bit for bit.
    std::mt19937 rng(12);
    int touching = 0;
    for (int f = 0; f < 200; ++f) {
        const Frustum frustum = random_frustum(rng);
        const Plane& left = frustum.planes[0];
        std::vector<Aabb> boxes;
        for (int k = 0; k < 20; ++k) {
            // A point inside the frustum's far region moved onto the left plane.
            glm::vec3 p = glm::vec3(float(k) * 3.0f, 5.0f, -2.0f);
            p -= left.normal * left.distance(p);
            const glm::vec3 e{1.0f + float(k), 2.0f, 0.5f};
            // Put the box entirely behind the plane except for its positive vertex.
            const glm::vec3 sign{left.normal.x >= 0 ? 1.0f : -1.0f, left.normal.y >= 0 ? 1.0f : -1.0f,
                                 left.normal.z >= 0 ? 1.0f : -1.0f};
            const glm::vec3 far_corner = p - 2.0f * e * sign;
            boxes.push_back({glm::min(p, far_corner), glm::max(p, far_corner)});
        }
        const FrustumBoxes packed(boxes);
        const auto all = FrustumBoxes::prepare(frustum, FrustumBoxes::Planes::All);
        for (uint32_t i = 0; i < boxes.size(); ++i) {
            ASSERT_EQ(packed.intersects(i, all), frustum.intersects(boxes[i]));
            touching += std::abs(left.distance(glm::vec3(left.normal.x >= 0 ? boxes[i].max.x : boxes[i].min.x,
                                                          left.normal.y >= 0 ? boxes[i].max.y : boxes[i].min.y,
                                                          left.normal.z >= 0 ? boxes[i].max.z : boxes[i].min.z))) < 1e-3f;
        }
    }
    EXPECT_GT(touching, 2000); // the cases really were on the plane
}

// The far-plane sphere's test on many boxes at once: the same answer as squared_distance() <=
// limit box by box, with limits set to a box's own squared distance (the boundary case), points
// inside boxes, and an eye that is not a number (never near, as the scalar form has it).
TEST(FrustumBoxes, NearMaskEqualsEachBoxsSquaredDistanceTest)
{
    std::mt19937 rng(19);
    const std::vector<Aabb> boxes = random_boxes(rng, 640);
    const FrustumBoxes packed(boxes);
    std::uniform_real_distribution<float> u(-400.0f, 400.0f), radius(0.0f, 500.0f);
    int near = 0, far = 0;
    for (int t = 0; t < 200; ++t) {
        glm::vec3 eye{u(rng), u(rng), u(rng)};
        if (t == 0)
            eye.x = std::numeric_limits<float>::quiet_NaN();
        const uint32_t first = uint32_t(rng() % (boxes.size() - 64));
        float limit = radius(rng) * radius(rng);
        if (t % 3 == 1)
            limit = packed.squared_distance(first + uint32_t(rng() % 64), eye); // exactly on one box
        for (uint32_t count : {64u, 13u, 4u, 1u}) {
            const uint64_t mask = packed.near_mask(first, count, eye, limit);
            for (uint32_t i = 0; i < 64; ++i) {
                const bool expected = i < count && packed.squared_distance(first + i, eye) <= limit;
                ASSERT_EQ(((mask >> i) & 1u) != 0, expected) << "sphere " << t << ", box " << first + i;
                if (count == 64) {
                    (expected ? near : far) += 1;
                }
            }
        }
        if (t == 0) {
            EXPECT_EQ(packed.near_mask(first, 64, eye, limit), 0u) << "a NaN eye is near nothing";
        }
    }
    EXPECT_GT(near, 1000);
    EXPECT_GT(far, 1000);
}

} // namespace
} // namespace pvs
