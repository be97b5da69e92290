// Frustum planes extracted from a view-projection matrix, checked against the independent
// clip-space test (-w <= x, y, z <= w after projecting the point) on random points, and the
// box test's promise: never false for a box with a corner inside.
#include "visibility/math/frustum.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <random>

namespace pvs {
namespace {

bool clip_inside(const glm::mat4& vp, const glm::vec3& p)
{
    const glm::vec4 c = vp * glm::vec4(p, 1.0f);
    return c.w > 0 && std::abs(c.x) <= c.w && std::abs(c.y) <= c.w && std::abs(c.z) <= c.w;
}

glm::mat4 test_view_projection()
{
    const glm::mat4 proj = glm::perspective(glm::radians(70.0f), 4.0f / 3.0f, 1.0f, 500.0f);
    const glm::mat4 view = glm::lookAt(glm::vec3(10, 20, 30), glm::vec3(100, -40, 0), glm::vec3(0, 0, 1));
    return proj * view;
}

TEST(Frustum, PlanesAgreeWithTheClipSpaceTestOnRandomPoints)
{
    const glm::mat4 vp = test_view_projection();
    const Frustum f = Frustum::from_view_projection(vp);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-600.0f, 600.0f);
    int inside = 0, disagreements = 0;
    for (int i = 0; i < 100000; ++i) {
        const glm::vec3 p{u(rng), u(rng), u(rng)};
        const bool expected = clip_inside(vp, p);
        inside += expected;
        // Points within a hair of a plane may round either way.
        float margin = 1e9f;
        for (const Plane& plane : f.planes)
            margin = std::min(margin, std::abs(plane.distance(p)));
        if (margin > 1e-2f && f.contains(p) != expected)
            ++disagreements;
    }
    EXPECT_GT(inside, 1000);
    EXPECT_EQ(disagreements, 0);
}

TEST(Frustum, PlanesAreUnitLengthAndPointInward)
{
    const glm::mat4 vp = test_view_projection();
    const Frustum f = Frustum::from_view_projection(vp);
    const glm::vec3 ahead = glm::vec3(10, 20, 30) + 50.0f * glm::normalize(glm::vec3(90, -60, -30));
    for (const Plane& plane : f.planes) {
        EXPECT_NEAR(glm::length(plane.normal), 1.0f, 1e-5f);
        EXPECT_GT(plane.distance(ahead), 0.0f);
    }
}

TEST(Frustum, BoxWithACornerInsideIsNeverCulled)
{
    const glm::mat4 vp = test_view_projection();
    const Frustum f = Frustum::from_view_projection(vp);
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> u(-600.0f, 600.0f), s(0.5f, 80.0f);
    int culled = 0;
    for (int i = 0; i < 20000; ++i) {
        Aabb box;
        const glm::vec3 c{u(rng), u(rng), u(rng)};
        box.grow(c);
        box.grow(c + glm::vec3(s(rng), s(rng), s(rng)));
        bool corner_inside = false;
        for (int k = 0; k < 8; ++k)
            corner_inside |= clip_inside(vp, {k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y,
                                              k & 4 ? box.max.z : box.min.z});
        if (corner_inside) {
            ASSERT_TRUE(f.intersects(box)) << i;
        }
        culled += !f.intersects(box);
    }
    EXPECT_GT(culled, 1000); // and it does cull
}

TEST(Frustum, BoxBehindTheCameraIsCulled)
{
    const Frustum f = Frustum::from_view_projection(
        glm::perspective(glm::radians(90.0f), 1.0f, 1.0f, 100.0f) *
        glm::lookAt(glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(0, 0, 1)));
    Aabb behind;
    behind.grow({-20, -1, -1});
    behind.grow({-10, 1, 1});
    EXPECT_FALSE(f.intersects(behind));
    Aabb ahead;
    ahead.grow({10, -1, -1});
    ahead.grow({20, 1, 1});
    EXPECT_TRUE(f.intersects(ahead));
}

} // namespace
} // namespace pvs

namespace pvs {
namespace {

TEST(Frustum, SidePlanesAloneAreConservativeAndStillRejectWhatIsBehind)
{
    const glm::mat4 vp = glm::perspective(glm::radians(70.0f), 4.0f / 3.0f, 1.0f, 500.0f) *
                         glm::lookAt(glm::vec3(10, 20, 30), glm::vec3(100, -40, 0), glm::vec3(0, 0, 1));
    const Frustum f = Frustum::from_view_projection(vp);
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> u(-400.0f, 400.0f), s(0.5f, 40.0f);
    int disagreements = 0;
    for (int i = 0; i < 20000; ++i) {
        Aabb box;
        const glm::vec3 c{u(rng), u(rng), u(rng)};
        box.grow(c);
        box.grow(c + glm::vec3(s(rng), s(rng), s(rng)));
        // The side test may only add boxes: ones in the slab before the near plane or beyond the far one.
        if (f.intersects(box)) {
            ASSERT_TRUE(f.intersects_sides(box)) << i;
        }
        disagreements += f.intersects(box) != f.intersects_sides(box);
    }
    EXPECT_LT(disagreements, 400); // few boxes lie there
    Aabb behind;
    behind.grow(glm::vec3(10, 20, 30) - 50.0f * glm::normalize(glm::vec3(90, -60, -30)));
    behind.grow(behind.min + glm::vec3(2.0f));
    EXPECT_FALSE(f.intersects_sides(behind));
}

} // namespace
} // namespace pvs
