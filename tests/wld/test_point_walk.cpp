// The portal walk from a point (visibility/reference/point_walk.h) against the tree itself: the
// portal planes face the regions the portal builder says they do, every region the walk reaches
// is one a line from the eye through the walk's window reaches in the tree (tree_trace.h, an
// independent computation: it knows nothing of portals), and the walk finds every region that
// dense lines from the same eye find.
#include "visibility/reference/point_walk.h"

#include "tests/support/test_data.h"
#include "visibility/portal/portalize.h"
#include "visibility/reference/sample_sequence.h"
#include "visibility/reference/line_witness.h"
#include "visibility/reference/tree_trace.h"
#include "gen/generate_zone.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <set>
#include <vector>

namespace pvs {
namespace {

PortalSet zone_portals(const Zone& zone)
{
    PortalOptions options;
    options.sky = SkyPortals::None;
    return build_zone_portals(zone, options);
}

glm::dvec3 portal_centre(const PortalSet& set, uint32_t portal)
{
    glm::dvec3 sum(0.0);
    const Portal& p = set.portals[portal];
    for (uint32_t k = 0; k < p.point_count; ++k)
        sum += glm::dvec3(set.points[p.first_point + k]);
    return sum / double(p.point_count);
}

// Each portal's plane, stepped a little off its centre, is in regions[0] on the normal's side and
// in regions[1] on the other, as the tree finds the points.
void expect_planes_face_their_regions(const Zone& zone)
{
    const PortalSet set = zone_portals(zone);
    const uint32_t regions = uint32_t(zone.region_count());
    const PortalSampler links(set, regions);
    const PortalWalker walker(set, links, regions);
    const TreeTracer tracer(zone.tree, zone.regions, SkyPortals::None);
    size_t checked = 0, agree = 0;
    for (uint32_t r = 0; r < regions; ++r)
        for (const PortalSampler::Link& link : links.links(r)) {
            const glm::dvec4 plane = walker.plane(link.portal);
            const glm::dvec3 c = portal_centre(set, link.portal), n(plane);
            const int32_t front = tracer.region_at(c + 0.01 * n), back = tracer.region_at(c - 0.01 * n);
            ++checked;
            agree += front == set.portals[link.portal].regions[0] && back == set.portals[link.portal].regions[1];
        }
    ASSERT_GT(checked, 0u);
    // A centre can sit on a third region's corner in a few portals; the orientation rule is global.
    EXPECT_GE(double(agree), 0.98 * double(checked)) << agree << " of " << checked;
}

// A 10 x 10 portal in the plane x = 0 between regions 0 and 1.
PortalSet square_portal()
{
    PortalSet set;
    set.points = {{0, 0, 0}, {0, 10, 0}, {0, 10, 10}, {0, 0, 10}};
    set.portals.push_back({{0, 1}, 0, 4});
    return set;
}

TEST(PointWalk, BoundaryEyesLieInsetOnThePortal)
{
    const PortalSet set = square_portal();
    const PortalSampler links(set, 2);
    const PortalWalker walker(set, links, 2);
    for (int k = 0; k < 64; ++k) {
        const double u = (k + 0.5) / 64.0;
        const glm::dvec3 p = walker.boundary_point(0, u, 0.3);
        EXPECT_NEAR(p.x, 0.0, 1e-12) << "in the portal's plane";
        const double to_edge = std::min({p.y, 10.0 - p.y, p.z, 10.0 - p.z});
        // Moved 0.3 toward the centre: at least 0.3 / sqrt(2) from every edge (a corner moves
        // along the diagonal), at most 0.3 from the edge it started on.
        EXPECT_GE(to_edge, 0.3 / std::sqrt(2.0) - 1e-12) << "u " << u;
        EXPECT_LE(to_edge, 0.3 + 1e-12) << "u " << u;
    }
    // The perimeter is walked in order: u = 1/8 is halfway along the first edge.
    const glm::dvec3 first = walker.boundary_point(0, 0.125, 0.0);
    EXPECT_NEAR(first.y, 5.0, 1e-12);
    EXPECT_NEAR(first.z, 0.0, 1e-12);
    // A portal thinner than twice the inset: the eye stops halfway to the centre.
    const glm::dvec3 tiny = walker.boundary_point(0, 0.125, 100.0);
    EXPECT_NEAR(tiny.y, 5.0, 1e-12);
    EXPECT_NEAR(tiny.z, 2.5, 1e-12);
}

TEST(PointWalk, StratifiedUnitsFillEveryIntervalOfEachDoubling)
{
    for (uint32_t shift : {0u, 0x9e3779b9u}) {
        for (uint32_t k = 0; k <= 10; ++k) {
            const uint32_t n = 1u << k;
            std::vector<int> hits(n);
            for (uint32_t i = 0; i < n; ++i) {
                const double u = sampling::stratified_unit(i, shift);
                ASSERT_GE(u, 0.0);
                ASSERT_LT(u, 1.0);
                ++hits[size_t(u * n)];
            }
            EXPECT_EQ(std::count(hits.begin(), hits.end(), 1), int(n)) << "2^" << k << " points, shift " << shift;
        }
    }
}

TEST(PointWalk, PortalPlanesFaceTheirFrontRegionOnAGeneratedZone)
{
    expect_planes_face_their_regions(gen::generate_zone({40, 3}));
}

TEST(PointWalk, PortalPlanesFaceTheirFrontRegionOnE1m1)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    expect_planes_face_their_regions(*test::shared_zone("quake/e1m1.bsp"));
}

struct WalkCheck {
    size_t sights = 0, sights_reached = 0;    // walk sights, and of them those the tree line reaches
    size_t ray_regions = 0, ray_in_walk = 0;  // regions dense rays from the eye reach, and of them walked
};

// From `eyes` eyes on portals of the zone (seeded, spread over every region): each walk's sights
// against lines traced in the tree, and dense rays from each eye against the walk.
WalkCheck check_walks(const Zone& zone, uint32_t eyes, uint32_t rays_per_eye)
{
    const PortalSet set = zone_portals(zone);
    const uint32_t regions = uint32_t(zone.region_count());
    const PortalSampler links(set, regions);
    const PortalWalker walker(set, links, regions);
    const TreeTracer tracer(zone.tree, zone.regions, SkyPortals::None);
    const Aabb world = zone_portal_world(zone);
    const double reach = 2.0 * glm::length(glm::dvec3(world.max) - glm::dvec3(world.min));
    PortalWalker::Scratch scratch;
    TreeTracer::Scratch trace;
    Stretch stretch;
    WalkCheck out;
    std::vector<char> walked(regions);
    for (uint32_t e = 0; e < eyes; ++e) {
        const uint32_t from = uint32_t(sampling::sample_key(7, 1, e, 0) % regions);
        const auto out_of = links.links(from);
        if (out_of.empty())
            continue;
        const uint64_t key = sampling::sample_key(7, 2, e, 0);
        const PortalSampler::Link link = out_of[size_t(sampling::hash_unit(key, 0) * double(out_of.size()))];
        const glm::dvec3 eye = links.point(link.portal, sampling::hash_unit(key, 1), sampling::hash_unit(key, 2),
                                           sampling::hash_unit(key, 3));
        walker.walk(eye, link.portal, from, scratch);
        std::fill(walked.begin(), walked.end(), 0);
        walked[from] = walked[link.other] = 1;
        for (const PortalWalker::Sight& sight : scratch.sights) {
            walked[sight.region] = 1;
            const glm::dvec3 d = glm::normalize(sight.aim - eye);
            ++out.sights;
            if (open_stretch(tracer, eye + 0.5 * (sight.aim - eye), d, reach, trace, stretch))
                out.sights_reached +=
                    std::find(stretch.regions.begin(), stretch.regions.end(), sight.region) != stretch.regions.end();
        }
        // Rays into the half-space beyond the eye's portal, through the tree alone.
        const glm::dvec4 plane = walker.plane(link.portal);
        const glm::dvec3 beyond = set.portals[link.portal].regions[0] == int32_t(from) ? -glm::dvec3(plane)
                                                                                         : glm::dvec3(plane);
        for (uint32_t k = 0; k < rays_per_eye; ++k) {
            glm::dvec3 d = sampling::stratified_direction(k, key);
            if (glm::dot(d, beyond) < 0.0)
                d = -d;
            if (!open_stretch(tracer, eye + 1e-3 * d, d, reach, trace, stretch))
                continue;
            for (size_t i = 0; i < stretch.regions.size(); ++i)
                if (stretch.t_mid[i] > 0.0) {
                    ++out.ray_regions;
                    out.ray_in_walk += walked[stretch.regions[i]];
                }
        }
    }
    return out;
}

void expect_walks_agree_with_the_tree(const Zone& zone, const char* name)
{
    const WalkCheck check = check_walks(zone, 300, 2000);
    std::printf("[ %s ] %zu of %zu sights reached by their tree line; %zu of %zu regions on dense rays walked\n", name,
                check.sights_reached, check.sights, check.ray_in_walk, check.ray_regions);
    ASSERT_GT(check.sights, 1000u);
    ASSERT_GT(check.ray_regions, 10000u);
    // The walk is exact but for windows at a wall's edge, where a line through the window's middle
    // can still clip the wall's corner; it finds nearly all that rays find (the rest: gaps the
    // portal builder leaves no portal for, and windows under kMinWindowArea).
    EXPECT_GE(double(check.sights_reached), 0.995 * double(check.sights));
    EXPECT_GE(double(check.ray_in_walk), 0.995 * double(check.ray_regions));
}

// Found on e1m1: a ramp (the plane 0.229 y + 0.973 z = 273.47, by region 225) cut into several
// portals. The planes fitted to their float points disagree by about 1e-3 a hundred units away, so
// an eye on one of them was "in front" of another coplanar one both ways round, and the walk went
// round regions 225, 226 and 230 until its depth limit. Eyes on every portal of the ramp must walk
// without reaching a limit.
TEST(PointWalk, EyesOnACoplanarRampDoNotWalkInCircles)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    const Zone& zone = *test::shared_zone("quake/e1m1.bsp");
    const PortalSet set = zone_portals(zone);
    const uint32_t regions = uint32_t(zone.region_count());
    const PortalSampler links(set, regions);
    const PortalWalker walker(set, links, regions);
    const glm::dvec3 ramp_normal = glm::normalize(glm::dvec3(0.0, 0.229039, 0.973417));
    PortalWalker::Scratch scratch;
    size_t ramp_portals = 0, walks = 0, truncated = 0;
    for (uint32_t r = 0; r < regions; ++r)
        for (const PortalSampler::Link& link : links.links(r)) {
            const glm::dvec4 plane = walker.plane(link.portal);
            if (std::abs(std::abs(glm::dot(glm::dvec3(plane), ramp_normal)) - 1.0) > 1e-5 ||
                std::abs(std::abs(plane.w) - 273.473) > 0.01)
                continue;
            ++ramp_portals;
            for (uint32_t k = 0; k < 64; ++k) {
                const uint64_t key = sampling::sample_key(11, r, link.portal, k);
                walker.walk(links.point(link.portal, sampling::hash_unit(key, 0), sampling::hash_unit(key, 1),
                                        sampling::hash_unit(key, 2)),
                            link.portal, r, scratch);
                ++walks;
                truncated += scratch.truncated;
            }
        }
    ASSERT_GE(ramp_portals, 6u) << "the ramp's portals, both ways round";
    EXPECT_EQ(truncated, 0u) << "of " << walks << " walks from the ramp";
}

TEST(PointWalk, SightsAreWhatTheTreeSeesOnAGeneratedZone)
{
    expect_walks_agree_with_the_tree(gen::generate_zone({60, 5}), "gen 60");
}

TEST(PointWalk, SightsAreWhatTheTreeSeesOnE1m1)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    expect_walks_agree_with_the_tree(*test::shared_zone("quake/e1m1.bsp"), "e1m1");
}

} // namespace
} // namespace pvs
