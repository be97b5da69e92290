// Winding clip and split against hand-computed polygons, the epsilon rules of winding.h (ON points
// kept in place, a polygon on the plane kept, axial snapping exact), split areas adding up on
// random polygons and planes, and degenerate inputs (empty, on-plane, NaN) giving the documented
// results.
#include "visibility/geometry/winding.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <limits>
#include <random>

namespace pvs {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

Winding unit_square() { return Winding{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}; }

Plane plane_through(const glm::vec3& normal, const glm::vec3& point)
{
    const glm::vec3 n = glm::normalize(normal);
    return {n, glm::dot(n, point)};
}

// A regular n-gon of radius r around c in the plane with unit normal n, counter-clockwise seen from n.
Winding regular_polygon(const glm::vec3& c, const glm::vec3& n, float r, int count)
{
    const glm::vec3 helper = std::abs(n.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    const glm::vec3 u = glm::normalize(glm::cross(helper, n));
    const glm::vec3 v = glm::cross(n, u);
    Winding w;
    for (int i = 0; i < count; ++i) {
        const float a = glm::two_pi<float>() * float(i) / float(count);
        w.points.push_back(c + r * (std::cos(a) * u + std::sin(a) * v));
    }
    return w;
}

TEST(Winding, UnitSquareClippedAtXQuarterKeepsThreeQuartersWithExactPoints)
{
    const Winding clipped = unit_square().clip({{1, 0, 0}, 0.25f}, kWindingOnEpsilon);
    // Edges 0->1 and 2->3 cross x = 0.25; the axial plane snaps x, y interpolates exactly.
    const std::vector<glm::vec3> expected{{0.25f, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.25f, 1, 0}};
    EXPECT_EQ(clipped.points, expected);
    EXPECT_FLOAT_EQ(clipped.area(), 0.75f);
    EXPECT_EQ(clipped.normal(), glm::vec3(0, 0, 1));

    const Winding other = unit_square().clip({{-1, 0, 0}, -0.25f}, kWindingOnEpsilon); // x <= 0.25
    const std::vector<glm::vec3> expected_other{{0, 0, 0}, {0.25f, 0, 0}, {0.25f, 1, 0}, {0, 1, 0}};
    EXPECT_EQ(other.points, expected_other);
    EXPECT_FLOAT_EQ(other.area(), 0.25f);
}

TEST(Winding, DiagonalClipLeavesTheHandComputedTriangle)
{
    // x + y >= 1 keeps the triangle (1,0) (1,1) (0,1); (1,0) and (0,1) are ON the plane.
    const Winding clipped = unit_square().clip(plane_through({1, 1, 0}, {1, 0, 0}), kWindingOnEpsilon);
    ASSERT_EQ(clipped.size(), 3u);
    EXPECT_EQ(clipped[0], glm::vec3(1, 0, 0));
    EXPECT_EQ(clipped[1], glm::vec3(1, 1, 0));
    EXPECT_EQ(clipped[2], glm::vec3(0, 1, 0));
    EXPECT_NEAR(clipped.area(), 0.5f, 1e-6f);

    // A diagonal through the middle of two edges: x + y >= 1.5 leaves the corner triangle of area 1/8.
    const Winding corner = unit_square().clip(plane_through({1, 1, 0}, {1, 0.5f, 0}), kWindingOnEpsilon);
    ASSERT_EQ(corner.size(), 3u);
    EXPECT_NEAR(corner.area(), 0.125f, 1e-6f);
    EXPECT_NEAR(glm::length(corner[0] - glm::vec3(1, 0.5f, 0)), 0.0f, 1e-6f);
    EXPECT_EQ(corner[1], glm::vec3(1, 1, 0));
    EXPECT_NEAR(glm::length(corner[2] - glm::vec3(0.5f, 1, 0)), 0.0f, 1e-6f);
}

TEST(Winding, SplitPartsAddUpToTheOriginalOnRandomPolygonsAndPlanes)
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int straddling = 0;
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 n = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0, 0, 0.01f));
        const glm::vec3 c = 500.0f * glm::vec3(u(rng), u(rng), u(rng));
        const Winding w = regular_polygon(c, n, 50.0f + 200.0f * std::abs(u(rng)), 3 + int(rng() % 10));
        const Plane plane = plane_through(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0.01f, 0, 0),
                                          c + 100.0f * glm::vec3(u(rng), u(rng), u(rng)));
        const WindingSplit parts = w.split(plane, kWindingOnEpsilon);
        straddling += !parts.front.empty() && !parts.back.empty();
        const double total = double(parts.front.area()) + double(parts.back.area());
        EXPECT_NEAR(total, double(w.area()), 1e-5 * double(w.area())) << "case " << i;
        // Each part is what clip gives for its side.
        EXPECT_EQ(parts.front.points, w.clip(plane, kWindingOnEpsilon).points) << "case " << i;
        EXPECT_EQ(parts.back.points, w.clip(plane.flipped(), kWindingOnEpsilon).points) << "case " << i;
        for (const glm::vec3& p : parts.front.points)
            EXPECT_GE(plane.distance(p), -kWindingOnEpsilon - 1e-3f);
        for (const glm::vec3& p : parts.back.points)
            EXPECT_LE(plane.distance(p), kWindingOnEpsilon + 1e-3f);
        // A part keeps the polygon's plane and orientation.
        if (!parts.front.empty() && parts.front.area() > 1.0f) {
            EXPECT_GT(glm::dot(parts.front.normal(), n), 0.999f);
        }
    }
    EXPECT_GT(straddling, 500);
}

TEST(Winding, PolygonOnThePlaneIsKeptByClipWhicheverWayThePlaneFaces)
{
    const Winding square = unit_square();
    EXPECT_EQ(square.clip({{0, 0, 1}, 0.0f}, kWindingOnEpsilon).points, square.points);
    EXPECT_EQ(square.clip({{0, 0, -1}, 0.0f}, kWindingOnEpsilon).points, square.points);
    // Within epsilon counts as on, on either side.
    EXPECT_EQ(square.clip({{0, 0, 1}, 0.05f}, kWindingOnEpsilon).points, square.points);
    EXPECT_EQ(square.clip({{0, 0, 1}, -0.05f}, kWindingOnEpsilon).points, square.points);
    // Beyond it the polygon is behind (gone) or in front (whole).
    EXPECT_TRUE(square.clip({{0, 0, 1}, 0.2f}, kWindingOnEpsilon).empty());
    EXPECT_EQ(square.clip({{0, 0, 1}, -0.2f}, kWindingOnEpsilon).points, square.points);
    // With epsilon 0 only exact zeros are on.
    EXPECT_TRUE(square.clip({{0, 0, 1}, 0.05f}, 0.0f).empty());
}

TEST(Winding, SplitSendsAnOnPlanePolygonToTheSideItFaces)
{
    const Winding square = unit_square(); // normal +z
    const WindingSplit same = square.split({{0, 0, 1}, 0.0f}, kWindingOnEpsilon);
    EXPECT_EQ(same.front.points, square.points);
    EXPECT_TRUE(same.back.empty());
    const WindingSplit opposite = square.split({{0, 0, -1}, 0.0f}, kWindingOnEpsilon);
    EXPECT_TRUE(opposite.front.empty());
    EXPECT_EQ(opposite.back.points, square.points);
}

TEST(Winding, OnPointsAreKeptWhereTheyAreNotMovedOntoThePlane)
{
    // x >= 0.25 with a vertex at x = 0.2 (0.05 behind, within epsilon): it is ON, kept unmoved,
    // and the crossing is only on the edge from the strictly-back vertex.
    const Winding w{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.2f, 1, 0}};
    const Winding clipped = w.clip({{1, 0, 0}, 0.25f}, kWindingOnEpsilon);
    const std::vector<glm::vec3> expected{{0.25f, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.2f, 1, 0}};
    EXPECT_EQ(clipped.points, expected);
    // Touching the plane from behind (ON and BACK only): gone. From in front: unchanged.
    const Winding behind{{0.25f, 0, 0}, {0, 0, 0}, {0, 1, 0}};
    EXPECT_TRUE(behind.clip({{1, 0, 0}, 0.25f}, kWindingOnEpsilon).empty());
    const Winding ahead{{0.25f, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    EXPECT_EQ(ahead.clip({{1, 0, 0}, 0.25f}, kWindingOnEpsilon).points, ahead.points);
}

TEST(Winding, AxialPlanesSnapTheNewCoordinateExactly)
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-4000.0f, 4000.0f);
    for (int i = 0; i < 500; ++i) {
        const glm::vec3 c(u(rng), u(rng), u(rng));
        const Winding w = regular_polygon(c, glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f)), 300.0f, 7);
        const int axis = i % 3;
        const float at = c[axis] + 0.001f * u(rng) + 0.123f;
        glm::vec3 n(0.0f);
        n[axis] = (i & 1) ? 1.0f : -1.0f;
        const Plane plane{n, (i & 1) ? at : -at};
        const WindingSplit parts = w.split(plane, kWindingOnEpsilon);
        ASSERT_FALSE(parts.front.empty());
        ASSERT_FALSE(parts.back.empty());
        int new_points = 0;
        for (const Winding* part : {&parts.front, &parts.back})
            for (const glm::vec3& p : part->points)
                if (std::find(w.points.begin(), w.points.end(), p) == w.points.end()) {
                    EXPECT_EQ(p[axis], at); // exactly, not within round-off
                    ++new_points;
                }
        EXPECT_GE(new_points, 2); // one copy of each new point in each part
    }
    // The base winding of an axial plane lies on it exactly too.
    const Winding base = base_winding_for_plane({{0, -1, 0}, -123.456f}, 1000.0f, {10, 20, 30});
    ASSERT_EQ(base.size(), 4u);
    for (const glm::vec3& p : base.points)
        EXPECT_EQ(p.y, 123.456f);
}

TEST(Winding, BaseWindingLiesOnThePlaneFacesItsFrontAndIsCentredOnTheProjection)
{
    const Plane plane = plane_through({1, 2, 3}, {100, -50, 20});
    const glm::vec3 center(400, 300, -200);
    const Winding w = base_winding_for_plane(plane, 5000.0f, center);
    ASSERT_EQ(w.size(), 4u);
    for (const glm::vec3& p : w.points)
        EXPECT_NEAR(plane.distance(p), 0.0f, 2e-3f);
    EXPECT_GT(glm::dot(w.normal(), plane.normal), 0.99999f);
    EXPECT_NEAR(w.area(), 4.0f * 5000.0f * 5000.0f, 4.0f * 5000.0f * 5000.0f * 1e-5f);
    const glm::vec3 projected = center - plane.normal * plane.distance(center);
    EXPECT_LT(glm::length(w.centroid() - projected), 1e-2f);
    // A non-unit normal describes the same plane.
    const Winding scaled = base_winding_for_plane({plane.normal * 3.0f, plane.dist * 3.0f}, 10.0f);
    ASSERT_EQ(scaled.size(), 4u);
    for (const glm::vec3& p : scaled.points)
        EXPECT_NEAR(plane.distance(p), 0.0f, 1e-3f);
}

TEST(Winding, AreaCentroidNormalPlaneAndBounds)
{
    const Winding triangle{{0, 0, 5}, {3, 0, 5}, {0, 3, 5}};
    EXPECT_FLOAT_EQ(triangle.area(), 4.5f);
    EXPECT_EQ(triangle.centroid(), glm::vec3(1, 1, 5));
    EXPECT_EQ(triangle.normal(), glm::vec3(0, 0, 1));
    const Plane p = triangle.plane();
    EXPECT_EQ(p.normal, glm::vec3(0, 0, 1));
    EXPECT_FLOAT_EQ(p.dist, 5.0f);
    EXPECT_EQ(triangle.reversed().normal(), glm::vec3(0, 0, -1));
    const Aabb box = triangle.bounds();
    EXPECT_EQ(box.min, glm::vec3(0, 0, 5));
    EXPECT_EQ(box.max, glm::vec3(3, 3, 5));
    // The centroid is area-weighted, not the mean of the points.
    const Winding lopsided{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1.999f, 2, 0}, {1.998f, 2, 0}, {0, 2, 0}};
    EXPECT_NEAR(lopsided.centroid().x, 1.0f, 1e-5f);
    EXPECT_NEAR(lopsided.centroid().y, 1.0f, 1e-5f);
}

TEST(Winding, RemoveDegeneratePointsDropsDuplicatesAndColinearPoints)
{
    Winding w{{0, 0, 0}, {0.5f, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1.00001f, 0}, {0, 1, 0}, {0, 0.5f, 0.001f}};
    const float area = w.area();
    EXPECT_EQ(w.remove_degenerate_points(0.01f), 4u);
    const std::vector<glm::vec3> expected{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    EXPECT_EQ(w.points, expected);
    EXPECT_NEAR(w.area(), area, 1e-3f);
    // All points on one line: no polygon left.
    Winding line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
    EXPECT_EQ(line.remove_degenerate_points(0.01f), 4u);
    EXPECT_TRUE(line.points.empty());
    // A clean polygon is untouched.
    Winding square = unit_square();
    EXPECT_EQ(square.remove_degenerate_points(0.01f), 0u);
    EXPECT_EQ(square.points, unit_square().points);
}

TEST(Winding, ClipIntoReusesTheOutputStorage)
{
    const Winding w = regular_polygon({0, 0, 0}, {0, 0, 1}, 10.0f, 12);
    Winding out, scratch;
    out.points.reserve(32);
    const glm::vec3* storage = out.points.data();
    for (int i = 0; i < 50; ++i) {
        // Epsilon 0: a vertex a hair behind the line would otherwise be kept and add a sliver.
        w.clip_into(plane_through({std::cos(float(i)), std::sin(float(i)), 0}, {0, 0, 0}), 0.0f, out);
        ASSERT_EQ(out.points.data(), storage);
        EXPECT_NEAR(out.area(), 0.5f * w.area(), 1e-3f);
    }
    Winding a = w;
    scratch.points.reserve(32);
    EXPECT_TRUE(a.clip_in_place({{1, 0, 0}, 0.0f}, kWindingOnEpsilon, scratch));
    EXPECT_TRUE(a.clip_in_place({{0, 1, 0}, 0.0f}, kWindingOnEpsilon, scratch));
    EXPECT_NEAR(a.area(), 0.25f * w.area(), 1e-3f);
    EXPECT_FALSE(a.clip_in_place({{-1, 0, 0}, 20.0f}, kWindingOnEpsilon, scratch));
    EXPECT_TRUE(a.empty());
}

TEST(Winding, DegenerateInputsGiveTheDocumentedResults)
{
    // Empty and two-point windings are no polygon: empty results, zero measures.
    for (const Winding& w : {Winding{}, Winding{{0, 0, 0}, {1, 0, 0}}}) {
        EXPECT_TRUE(w.empty());
        EXPECT_TRUE(w.clip({{1, 0, 0}, 0.0f}, kWindingOnEpsilon).points.empty());
        const WindingSplit parts = w.split({{1, 0, 0}, 0.0f}, kWindingOnEpsilon);
        EXPECT_TRUE(parts.front.points.empty());
        EXPECT_TRUE(parts.back.points.empty());
        EXPECT_EQ(w.area(), 0.0f);
        EXPECT_EQ(w.normal(), glm::vec3(0.0f));
    }
    EXPECT_EQ(Winding{}.centroid(), glm::vec3(0.0f));
    EXPECT_TRUE(Winding{}.bounds().empty());

    // A NaN plane carries no side: clip keeps the input, split puts it in front.
    const Winding square = unit_square();
    for (const Plane& bad : {Plane{{kNaN, 0, 0}, 0.0f}, Plane{{1, 0, 0}, kNaN},
                             Plane{{std::numeric_limits<float>::infinity(), 0, 0}, 0.0f}}) {
        EXPECT_EQ(square.clip(bad, kWindingOnEpsilon).points, square.points);
        const WindingSplit parts = square.split(bad, kWindingOnEpsilon);
        EXPECT_EQ(parts.front.points, square.points);
        EXPECT_TRUE(parts.back.empty());
        Winding in_place = square, scratch;
        EXPECT_TRUE(in_place.clip_in_place(bad, kWindingOnEpsilon, scratch));
        EXPECT_EQ(in_place.points, square.points);
        EXPECT_TRUE(base_winding_for_plane(bad, 100.0f).empty());
    }
    // Zero normal or bad size: no base winding.
    EXPECT_TRUE(base_winding_for_plane({{0, 0, 0}, 1.0f}, 100.0f).empty());
    EXPECT_TRUE(base_winding_for_plane({{0, 0, 1}, 1.0f}, 0.0f).empty());
    EXPECT_TRUE(base_winding_for_plane({{0, 0, 1}, 1.0f}, kNaN).empty());

    // A NaN or negative epsilon counts as 0.
    const Plane lifted{{0, 0, 1}, 0.05f};
    EXPECT_TRUE(square.clip(lifted, kNaN).empty());
    EXPECT_TRUE(square.clip(lifted, -1.0f).empty());

    // NaN points classify ON: kept, no crash; measures are NaN or zero, never a trap.
    const Winding nan_points{{kNaN, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    EXPECT_EQ(nan_points.clip({{1, 0, 0}, 0.5f}, kWindingOnEpsilon).size(), 4u);
    (void)nan_points.area();
    (void)nan_points.centroid();
    EXPECT_EQ(nan_points.normal(), glm::vec3(0.0f));
    Winding copy = nan_points;
    (void)copy.remove_degenerate_points(0.01f);

    // A degenerate (zero-area) winding: no normal, mean of points as centroid, plane normal 0.
    const Winding flat{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    EXPECT_EQ(flat.area(), 0.0f);
    EXPECT_EQ(flat.normal(), glm::vec3(0.0f));
    EXPECT_EQ(flat.centroid(), glm::vec3(1, 1, 1));
    EXPECT_EQ(flat.plane().normal, glm::vec3(0.0f));
}

} // namespace
} // namespace pvs
