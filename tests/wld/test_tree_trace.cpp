// Sight lines through the tree (visibility/reference/tree_trace.h), checked against an
// independent computation: the float point walk (locate_point, region_lookup.h) at many points
// along each segment. On e1m1 and on a generated zone, for random segments between points in
// regions:
//  - the regions the trace visits, in order, are the regions the point walk finds along the
//    segment, with runs shorter than the sampling step allowed to be missed by the sampling;
//  - the midpoint of every visited interval is in the visited region;
//  - where a trace is blocked, a point just before the stop is open and a point just after is in
//    a leaf that is solid/outside or a medium the previous region does not see through.
// And on a hand-made tree: the content rule (media.h) with every sky mode, the tie rule for a
// segment lying in a plane, corrupt node indices treated as solid, and no tree at all.
#include "visibility/reference/tree_trace.h"

#include "tests/support/test_data.h"
#include "visibility/region_lookup.h"
#include "gen/generate_zone.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <random>
#include <vector>

namespace pvs {
namespace {

struct Visited {
    int32_t region;
    double t0, t1;
};

std::vector<Visited> trace_all(const TreeTracer& tracer, const glm::dvec3& a, const glm::dvec3& b, TraceEnd* end)
{
    std::vector<Visited> out;
    TreeTracer::Scratch scratch;
    const glm::dvec3 d = b - a;
    *end = tracer.trace(a, d, 1.0, scratch, [&](int32_t r, double t0, double t1) { out.push_back({r, t0, t1}); });
    return out;
}

// A random point inside a random region (by its bounds, accepted when the walk agrees).
glm::vec3 random_open_point(const Zone& zone, std::mt19937_64& rng)
{
    std::uniform_int_distribution<uint32_t> pick(0, uint32_t(zone.region_count() - 1));
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (;;) {
        const uint32_t r = pick(rng);
        const Aabb& b = zone.regions[r].bounds;
        const glm::vec3 p = b.min + glm::vec3(unit(rng), unit(rng), unit(rng)) * (b.max - b.min);
        if (locate_point(zone.tree, p).region == int32_t(r) && !(zone.regions[r].flags & kRegionSky))
            return p;
    }
}

void check_against_point_walk(const Zone& zone, int segments, uint64_t seed)
{
    const TreeTracer tracer(zone.tree, zone.regions, SkyPortals::SkyToSky);
    ASSERT_TRUE(tracer.has_tree());
    std::mt19937_64 rng(seed);
    int blocked = 0, compared_runs = 0;
    for (int s = 0; s < segments; ++s) {
        const glm::dvec3 a(random_open_point(zone, rng)), b(random_open_point(zone, rng));
        TraceEnd end;
        const std::vector<Visited> visited = trace_all(tracer, a, b, &end);
        ASSERT_FALSE(visited.empty()) << "segment " << s << " starts in a region";
        EXPECT_EQ(visited.front().region, locate_point(zone.tree, glm::vec3(a)).region);
        for (const Visited& v : visited) {
            const glm::dvec3 mid = a + (v.t0 + v.t1) * 0.5 * (b - a);
            // The float walk may disagree only on a hair-thin interval (a float rounding of the
            // midpoint onto the other side).
            if ((v.t1 - v.t0) * glm::length(b - a) > 0.01) {
                EXPECT_EQ(locate_point(zone.tree, glm::vec3(mid)).region, v.region) << "segment " << s;
            }
        }
        // The sampled sequence of regions, in steps of about 0.25 units, up to where the trace stopped.
        const double length = glm::length(b - a);
        const int steps = std::max(2, int(length / 0.25));
        std::vector<int32_t> sampled;
        for (int i = 0; i <= steps; ++i) {
            const double t = end.t * double(i) / double(steps);
            const int32_t r = locate_point(zone.tree, glm::vec3(a + t * (b - a))).region;
            if (r >= 0 && (sampled.empty() || sampled.back() != r))
                sampled.push_back(r);
        }
        // Every sampled region appears in the trace, in the same order (the trace may hold more:
        // runs shorter than a step).
        size_t k = 0;
        for (const int32_t r : sampled) {
            while (k < visited.size() && visited[k].region != r)
                ++k;
            EXPECT_LT(k, visited.size()) << "segment " << s << ": region " << r << " found by the point walk is "
                                         << "missing from the trace (or out of order)";
        }
        ++compared_runs;
        if (end.blocked) {
            ++blocked;
            const glm::dvec3 dir = b - a;
            const double eps = 0.02 / length;
            const PointLocation before = locate_point(zone.tree, glm::vec3(a + (end.t - eps) * dir));
            const PointLocation after = locate_point(zone.tree, glm::vec3(a + (end.t + eps) * dir));
            EXPECT_GE(before.region, 0) << "segment " << s;
            const bool opaque = after.region < 0 || !tracer.passes(end.last_region, after.region);
            EXPECT_TRUE(opaque) << "segment " << s << " stopped at t=" << end.t << " before region " << after.region;
        } else {
            EXPECT_EQ(end.t, 1.0);
        }
    }
    EXPECT_GT(blocked, segments / 10); // most random segments between rooms hit a wall
    EXPECT_EQ(compared_runs, segments);
}

TEST(TreeTrace, E1m1SegmentsAgreeWithThePointWalk)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    check_against_point_walk(*test::shared_zone("quake/e1m1.bsp"), 400, 7);
}

TEST(TreeTrace, GeneratedZoneSegmentsAgreeWithThePointWalk)
{
    const Zone zone = gen::generate_zone({30, 5});
    check_against_point_walk(zone, 400, 9);
}

// x is split at 0 (front: x > 0) and at -10: x > 0 region 0, -10 < x < 0 the leaf `middle`,
// x < -10 region 1.
struct Slab {
    Zone zone;
    explicit Slab(int32_t middle, uint32_t flags0, uint32_t flags1, uint32_t flags_middle = 0)
    {
        zone.regions.resize(3);
        zone.regions[0].flags = flags0;
        zone.regions[1].flags = flags1;
        zone.regions[2].flags = flags_middle;
        zone.tree.nodes = {{{1, 0, 0}, 0.0f, {~0, 1}}, {{1, 0, 0}, -10.0f, {~1, ~2}}};
        zone.tree.leaf_region = {0, middle, 1};
        zone.tree.root = 0;
    }
};

std::vector<int32_t> regions_of(const Zone& zone, SkyPortals sky, TraceEnd* end)
{
    const TreeTracer tracer(zone.tree, zone.regions, sky);
    std::vector<int32_t> out;
    TreeTracer::Scratch scratch;
    *end = tracer.trace({5, 0, 0}, {-1, 0, 0}, 30.0, scratch, [&](int32_t r, double, double) { out.push_back(r); });
    return out;
}

TEST(TreeTrace, SolidAndOutsideLeavesBlock)
{
    TraceEnd end;
    EXPECT_EQ(regions_of(Slab(kLeafSolid, 0, 0).zone, SkyPortals::SkyToSky, &end), std::vector<int32_t>{0});
    EXPECT_TRUE(end.blocked);
    EXPECT_DOUBLE_EQ(end.t, 5.0);
    EXPECT_EQ(end.last_region, 0);
    EXPECT_EQ(end.refused_region, -1) << "a wall, not the content rule";
    EXPECT_EQ(regions_of(Slab(kLeafOutside, 0, 0).zone, SkyPortals::SkyToSky, &end), std::vector<int32_t>{0});
    EXPECT_TRUE(end.blocked);
    EXPECT_EQ(regions_of(Slab(7, 0, 0).zone, SkyPortals::SkyToSky, &end), std::vector<int32_t>{0})
        << "a leaf naming a region out of range is solid";
    EXPECT_EQ(regions_of(Slab(2, 0, 0).zone, SkyPortals::SkyToSky, &end), (std::vector<int32_t>{0, 2, 1}));
    EXPECT_FALSE(end.blocked);
    EXPECT_DOUBLE_EQ(end.t, 30.0);
    EXPECT_EQ(end.last_region, 1);
}

TEST(TreeTrace, MediaFollowTheContentRule)
{
    TraceEnd end;
    // Air sees through water and lava.
    EXPECT_EQ(regions_of(Slab(2, 0, kRegionLava, kRegionWater).zone, SkyPortals::SkyToSky, &end).size(), 3u);
    // Sky: opaque from outside by default, translucent with All, opaque to everything with None.
    EXPECT_EQ(regions_of(Slab(2, 0, 0, kRegionSky).zone, SkyPortals::SkyToSky, &end), std::vector<int32_t>{0});
    EXPECT_TRUE(end.blocked);
    EXPECT_EQ(end.refused_region, 2) << "the sky leaf's region, refused by the content rule";
    EXPECT_EQ(regions_of(Slab(2, 0, 0, kRegionSky).zone, SkyPortals::All, &end).size(), 3u);
    EXPECT_EQ(regions_of(Slab(2, kRegionSky, kRegionSky, kRegionSky).zone, SkyPortals::SkyToSky, &end).size(), 3u);
    EXPECT_EQ(regions_of(Slab(2, kRegionSky, kRegionSky, kRegionSky).zone, SkyPortals::None, &end),
              std::vector<int32_t>{0});
}

TEST(TreeTrace, SegmentInASplitPlaneFollowsTheTieRule)
{
    Slab slab(2, 0, 0);
    TreeTracer::Scratch scratch;
    for (const TieRule rule : {TieRule::OnPlaneGoesBack, TieRule::OnPlaneGoesFront}) {
        slab.zone.tree.tie_rule = rule;
        const TreeTracer tracer(slab.zone.tree, slab.zone.regions, SkyPortals::SkyToSky);
        std::vector<int32_t> seen;
        tracer.trace({0, -5, 0}, {0, 1, 0}, 10.0, scratch, [&](int32_t r, double, double) { seen.push_back(r); });
        EXPECT_EQ(seen, std::vector<int32_t>{rule == TieRule::OnPlaneGoesFront ? 0 : 2});
        EXPECT_EQ(tracer.region_at({0, 0, 0}), rule == TieRule::OnPlaneGoesFront ? 0 : 2);
    }
}

TEST(TreeTrace, CorruptTreesAndNoTreeBlock)
{
    Slab slab(2, 0, 0);
    slab.zone.tree.nodes[0].children[1] = 99; // a node index out of range
    TraceEnd end;
    EXPECT_EQ(regions_of(slab.zone, SkyPortals::SkyToSky, &end), std::vector<int32_t>{0});
    EXPECT_TRUE(end.blocked);

    Zone empty;
    empty.regions.resize(1);
    const TreeTracer none(empty.tree, empty.regions, SkyPortals::SkyToSky);
    EXPECT_FALSE(none.has_tree());
    TreeTracer::Scratch scratch;
    int visits = 0;
    end = none.trace({0, 0, 0}, {1, 0, 0}, 1.0, scratch, [&](int32_t, double, double) { ++visits; });
    EXPECT_TRUE(end.blocked);
    EXPECT_EQ(visits, 0);
    EXPECT_EQ(none.region_at({0, 0, 0}), kLeafSolid);
}

} // namespace
} // namespace pvs
