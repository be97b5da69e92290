// Base vis's float tables (visibility/portal/base_vis.h):
//  1. quick_verdict answers only where the floats make it certain, never against the exact
//     test portal_might_see, on every pair of a generated zone (coplanar and edge-sharing
//     portals by the thousand) and of a real map, and it decides nearly all of them (else the
//     tables would be slower than the doubles they stand in for);
//  2. base vis in batches of 64 sources (base_vis_batch.h), in any order and with a short last
//     batch, gives the rows of a plain flood through portal_might_see,
//     written here on the graph alone (no tables, no float, one source at a time), on the same
//     zones.
#include "visibility/portal/base_vis.h"
#include "visibility/portal/base_vis_batch.h"
#include "visibility/portal/source_lanes.h"

#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/portal/portalize.h"
#include "gen/generate_zone.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <span>
#include <cstdio>
#include <string>
#include <vector>

namespace pvs {
namespace {

using portal_vis::Graph;
using portal_vis::Verdict;

struct Portals {
    PortalSet set;
    uint32_t regions = 0;
};

Portals generated_portals(int rooms, uint64_t seed)
{
    const Zone zone = gen::generate_zone({rooms, seed, 32.0f, false});
    return {build_zone_portals(zone), uint32_t(zone.region_count())};
}

// A Quake map's portals as the accuracy tests build them (no portals at sky leaves).
Portals map_portals(const Zone& zone)
{
    PortalOptions options;
    options.sky = SkyPortals::None;
    return {build_zone_portals(zone, options), uint32_t(zone.region_count())};
}

// Sanitizer builds ask fewer source portals (every `stride`-th); optimised builds ask all.
#if defined(__SANITIZE_ADDRESS__)
constexpr uint32_t kStride = 7;
#else
constexpr uint32_t kStride = 1;
#endif

struct VerdictCounts {
    size_t pairs = 0, decided = 0, might_see = 0, cannot_see = 0, contradicted = 0;
};

// Every (p, t) pair with p != t: the float verdict against the exact test.
VerdictCounts check_every_pair(const Graph& g, const portal_vis::BaseVisTables& tables)
{
    VerdictCounts counts;
    for (uint32_t pi = 0; pi < g.portals.size(); pi += kStride) {
        const portal_vis::SourcePortal source(g, tables, pi);
        for (uint32_t leaf = 0; leaf < g.leaf_count; ++leaf) {
            const portal_vis::FloodSlot* header = &tables.slots[tables.leaf_slot[leaf]];
            const bool in_front = source.leaf_in_front(tables, *header);
            for (uint32_t j = 0; j < header->leaf; ++j) {
                const size_t k = header->slot + j;
                const uint32_t ti = g.leaf_portals[k];
                if (ti == pi)
                    continue;
                const Verdict verdict = portal_vis::quick_verdict(tables, source, header[1 + j], k, in_front);
                const bool exact = portal_vis::portal_might_see(g, g.portals[pi], g.portals[ti]);
                ++counts.pairs;
                if (verdict == Verdict::kUndecided)
                    continue;
                ++counts.decided;
                (verdict == Verdict::kMightSee ? counts.might_see : counts.cannot_see) += 1;
                if ((verdict == Verdict::kMightSee) != exact && counts.contradicted++ < 5)
                    ADD_FAILURE() << "portal " << pi << " against " << ti << ": float says "
                                  << (verdict == Verdict::kMightSee ? "might see" : "cannot see") << ", exact "
                                  << exact;
            }
        }
    }
    return counts;
}

void expect_verdicts_agree(const Portals& portals, const std::string& name, double min_decided)
{
    const Graph g = portal_vis::build_graph(portals.set, portals.regions);
    const portal_vis::BaseVisTables tables = portal_vis::base_vis_tables(g);
    ASSERT_GT(tables.slack, 0.0);
    ASSERT_LT(tables.slack, portal_vis::kOnEpsilon / 2) << "points on a plane could not be decided in floats";
    const VerdictCounts c = check_every_pair(g, tables);
    EXPECT_EQ(c.contradicted, 0u);
    EXPECT_GT(c.might_see, 0u);
    EXPECT_GT(c.cannot_see, 0u);
    const double decided = double(c.decided) / double(c.pairs);
    EXPECT_GE(decided, min_decided);
    std::printf("[ %-7s ] %zu directed portals, %zu pairs asked: %.2f %% decided in floats (%zu might see, "
                "%zu cannot), slack %.4f\n",
                name.c_str(), g.portals.size(), c.pairs, 100.0 * decided, c.might_see, c.cannot_see, tables.slack);
}

// SourceLanes (source_lanes.h) against quick_verdict, one lane at a time: every lane the
// vectors decide is decided the same way by the scalar code, and every lane they leave is one
// the scalar code's spheres leave to verdict_near_planes (it answers what verdict_near_planes
// answers). All 64 lanes, in batches of the zone's portals in index order, against every slot.
void expect_lanes_as_scalar(const Portals& portals, const char* name)
{
    const Graph g = portal_vis::build_graph(portals.set, portals.regions);
    const portal_vis::BaseVisTables tables = portal_vis::base_vis_tables(g);
    portal_vis::SourceLanes lanes;
    size_t asked = 0, decided = 0, differing = 0;
    for (uint32_t first = 0; first < g.portals.size(); first += 64 * kStride) {
        std::vector<portal_vis::SourcePortal> sources;
        for (uint32_t lane = 0; lane < 64 && first + lane < g.portals.size(); ++lane) {
            sources.emplace_back(g, tables, first + lane);
            lanes.set(lane, sources.back());
        }
        const uint64_t all = sources.size() == 64 ? ~uint64_t{0} : (uint64_t{1} << sources.size()) - 1;
        for (uint32_t leaf = 0; leaf < g.leaf_count; ++leaf) {
            const portal_vis::FloodSlot* header = &tables.slots[tables.leaf_slot[leaf]];
            const uint64_t front = lanes.lanes_in_front(tables, header->sphere, all);
            for (uint32_t j = 0; j < header->leaf; ++j) {
                const size_t k = header->slot + j;
                const portal_vis::SphereVerdicts v = lanes.sphere_verdicts(tables, header[1 + j], all, front);
                for (uint32_t lane = 0; lane < sources.size(); ++lane) {
                    const uint64_t bit = uint64_t{1} << lane;
                    const bool in_front = sources[lane].leaf_in_front(tables, *header);
                    const Verdict scalar = portal_vis::quick_verdict(tables, sources[lane], header[1 + j], k, in_front);
                    const Verdict near =
                        portal_vis::verdict_near_planes(tables, sources[lane], header[1 + j], k, in_front);
                    const Verdict vector = (v.might_see & bit) != 0    ? Verdict::kMightSee
                                           : (v.cannot_see & bit) != 0 ? Verdict::kCannotSee
                                                                       : near;
                    ++asked;
                    decided += ((v.might_see | v.cannot_see) & bit) != 0;
                    if (((front & bit) != 0) != in_front || vector != scalar) {
                        if (differing++ < 5)
                            ADD_FAILURE() << name << ": source " << first + lane << ", slot " << k
                                          << ": lanes and scalar differ";
                    }
                }
                EXPECT_EQ((v.might_see | v.cannot_see) & ~all, 0u);
                EXPECT_EQ(v.might_see & v.cannot_see, 0u);
            }
        }
    }
    EXPECT_EQ(differing, 0u) << name;
    EXPECT_GT(decided, asked / 2) << name << ": the spheres should decide most pairs";
    std::printf("[ %-7s ] %zu lane tests, %.1f %% decided by the spheres\n", name, asked,
                100.0 * double(decided) / double(std::max<size_t>(asked, 1)));
}

// A flood from p's destination through every portal portal_might_see passes: the definition of
// mightsee (base_vis.h), on the graph's own arrays.
std::vector<uint64_t> plain_flood(const Graph& g, uint32_t pi)
{
    std::vector<uint64_t> row(g.words, 0);
    const portal_vis::DirectedPortal& p = g.portals[pi];
    bits::set(row, p.leaf);
    std::vector<uint32_t> todo{p.leaf};
    while (!todo.empty()) {
        const uint32_t leaf = todo.back();
        todo.pop_back();
        for (uint32_t k = g.leaf_first[leaf]; k < g.leaf_first[leaf + 1]; ++k) {
            const uint32_t ti = g.leaf_portals[k];
            const uint32_t dest = g.portals[ti].leaf;
            if (ti != pi && !bits::test(row, dest) && portal_vis::portal_might_see(g, p, g.portals[ti])) {
                bits::set(row, dest);
                todo.push_back(dest);
            }
        }
    }
    return row;
}

// The batches of `order`, kBatchLanes at a time (the last one short unless the count divides),
// against the plain flood of each source.
void expect_batch_rows_of_plain_flood(const Graph& g, const portal_vis::BaseVisTables& tables,
                                      const std::vector<uint32_t>& order, const char* name)
{
    ASSERT_EQ(order.size(), g.portals.size());
    portal_vis::BaseVisBatch batch(g);
    size_t differing = 0, asked = 0;
    for (size_t first = 0; first < order.size(); first += portal_vis::kBatchLanes) {
        const size_t lanes = std::min<size_t>(portal_vis::kBatchLanes, order.size() - first);
        const std::span<const uint32_t> sources(&order[first], lanes);
        batch.run(g, tables, sources);
        if ((first / portal_vis::kBatchLanes) % kStride != 0)
            continue;
        for (uint32_t lane = 0; lane < lanes; ++lane) {
            const std::vector<uint64_t> expected = plain_flood(g, sources[lane]);
            const std::span<const uint64_t> row = batch.row(lane);
            ++asked;
            EXPECT_EQ(batch.count(lane), bits::count(expected));
            if (!std::equal(row.begin(), row.end(), expected.begin(), expected.end()) && differing++ < 5)
                ADD_FAILURE() << name << ": portal " << sources[lane] << " (lane " << lane << "): "
                              << bits::count(row) << " bits, the plain flood " << bits::count(expected);
        }
    }
    EXPECT_EQ(differing, 0u) << name;
    EXPECT_GT(asked, 0u);
}

// In the order base vis uses, and in index order backwards (other company in every batch, and a
// short last batch at the other end).
void expect_batches_of_plain_flood(const Portals& portals)
{
    const Graph g = portal_vis::build_graph(portals.set, portals.regions);
    const portal_vis::BaseVisTables tables = portal_vis::base_vis_tables(g);
    const std::vector<uint32_t> order = portal_vis::base_vis_batch_order(g);
    std::vector<uint32_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (uint32_t i = 0; i < sorted.size(); ++i)
        ASSERT_EQ(sorted[i], i) << "every directed portal once";
    expect_batch_rows_of_plain_flood(g, tables, order, "batch order");
    std::vector<uint32_t> backwards(g.portals.size());
    for (uint32_t i = 0; i < backwards.size(); ++i)
        backwards[i] = uint32_t(backwards.size()) - 1 - i;
    ASSERT_NE(backwards.size() % portal_vis::kBatchLanes, 0u) << "pick a zone whose last batch is short";
    expect_batch_rows_of_plain_flood(g, tables, backwards, "index order, backwards");
}

// ---------------------------------------------------------------------------------------------
// 1. The verdicts

TEST(BaseVisTables, FloatVerdictsNeverContradictTheExactTestOnAGeneratedZone)
{
    expect_verdicts_agree(generated_portals(120, 7), "gen 120", 0.95);
}

TEST(BaseVisTables, FloatVerdictsNeverContradictTheExactTestOnARealMap)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    const Zone* zone = test::shared_zone("quake/e1m1.bsp");
    ASSERT_NE(zone, nullptr);
    expect_verdicts_agree(map_portals(*zone), "e1m1", 0.9);
}

// A zone whose coordinates pass 1e30 (PRT files are floats: up to 3.4e38) would overflow float
// distances: the slack is infinite there, nothing is decided in floats, and the exact test
// alone gives the rows.
TEST(BaseVisTables, CoordinatesBeyondFloatDistancesLeaveEverythingToTheExactTest)
{
    Portals portals = generated_portals(20, 3);
    for (glm::vec3& v : portals.set.points)
        v *= 1e34f; // a few hundred units become a few 1e36
    const Graph g = portal_vis::build_graph(portals.set, portals.regions);
    ASSERT_EQ(g.skipped, 0u);
    const portal_vis::BaseVisTables tables = portal_vis::base_vis_tables(g);
    EXPECT_TRUE(std::isinf(tables.slack));
    const VerdictCounts c = check_every_pair(g, tables);
    EXPECT_GT(c.pairs, 0u);
    EXPECT_EQ(c.decided, 0u);
    expect_batches_of_plain_flood(portals);
}

// ---------------------------------------------------------------------------------------------
// 2. The rows

TEST(BaseVisBatch, RowsAreThoseOfAPlainFloodOnAGeneratedZone)
{
    expect_batches_of_plain_flood(generated_portals(150, 11));
}

TEST(SourceLanes, VerdictsAreTheScalarOnesOnAGeneratedZone)
{
    expect_lanes_as_scalar(generated_portals(120, 7), "gen 120");
}

TEST(SourceLanes, VerdictsAreTheScalarOnesOnARealMap)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    const Zone* zone = test::shared_zone("quake/e1m1.bsp");
    ASSERT_NE(zone, nullptr);
    expect_lanes_as_scalar(map_portals(*zone), "e1m1");
}

// Real zones rarely put a sphere within ON_EPSILON of a plane, so the thresholds themselves
// are asked here: each lane's sphere and each tested sphere placed at, just before and just
// past every boundary of quick_verdict's sphere tests (a source's distance to the tested
// portal's plane, the tested sphere's to the source's plane, the leaf's to the source's), on
// unit planes along x, facing each other, each portal's points on its sphere's point nearest
// the other's plane (so that where the points decide, the coplanar rule can turn them down).
TEST(SourceLanes, VerdictsAreTheScalarOnesAtEveryThreshold)
{
    const Portals portals = generated_portals(20, 3);
    const Graph g = portal_vis::build_graph(portals.set, portals.regions);
    portal_vis::BaseVisTables tables = portal_vis::base_vis_tables(g);
    const float slack = tables.slack_f, beyond = tables.beyond_f;
    const uint32_t t_points = tables.point_first[1] - tables.point_first[0]; // entry 0's, t's below
    const float jitters[] = {-0.5f * slack, -1e-6f, 0.0f, 1e-6f, 0.5f * slack, -0.3f * beyond, 0.3f * beyond};
    // Offsets of a sphere's centre from a plane, given its radius r: each boundary +- jitter.
    auto offsets = [&](float r) {
        std::vector<float> out;
        for (float boundary : {r + slack, -r - beyond, -r - slack, r + beyond, 0.0f})
            for (float j : jitters)
                out.push_back(boundary + j);
        return out;
    };
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> radius(0.0f, 40.0f);
    portal_vis::SourceLanes lanes;
    std::vector<portal_vis::SourcePortal> sources;
    std::vector<portal_vis::Float3> points(64);
    for (uint32_t lane = 0; lane < 64; ++lane) {
        portal_vis::SourcePortal p(g, tables, lane % uint32_t(g.portals.size()));
        // Facing t (whose plane is x = 100, normal +x).
        p.plane = {-1.0f, 0.0f, 0.0f, -100.0f};
        const float r = radius(rng);
        const std::vector<float> o = offsets(r);
        p.sphere = {100.0f + o[rng() % o.size()], 3.0f, -7.0f, r};
        points[lane] = {p.sphere.x + r, 3.0f, -7.0f};
        p.points = &points[lane];
        p.point_count = 1;
        sources.push_back(p);
        lanes.set(lane, p);
    }
    size_t asked = 0, differing = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const float leaf_r = radius(rng);
        const std::vector<float> leaf_o = offsets(leaf_r);
        portal_vis::FloodSlot header;
        header.sphere = {100.0f + leaf_o[rng() % leaf_o.size()], 0.0f, 0.0f, leaf_r};
        portal_vis::FloodSlot t;
        const float t_r = radius(rng);
        const std::vector<float> t_o = offsets(t_r);
        t.plane = {1.0f, 0.0f, 0.0f, 100.0f};
        t.sphere = {100.0f + t_o[rng() % t_o.size()], -2.0f, 5.0f, t_r};
        for (uint32_t j = 0; j < t_points; ++j) // all on its sphere's point nearest p's plane
            tables.points[tables.point_first[0] + j] = {t.sphere.x + t_r, -2.0f, 5.0f};
        const uint64_t all = ~uint64_t{0};
        const uint64_t front = lanes.lanes_in_front(tables, header.sphere, all);
        const portal_vis::SphereVerdicts v = lanes.sphere_verdicts(tables, t, all, front);
        for (uint32_t lane = 0; lane < 64; ++lane) {
            const uint64_t bit = uint64_t{1} << lane;
            const bool in_front = sources[lane].leaf_in_front(tables, header);
            const Verdict scalar = portal_vis::quick_verdict(tables, sources[lane], t, 0, in_front);
            const Verdict vector = (v.might_see & bit) != 0    ? Verdict::kMightSee
                                   : (v.cannot_see & bit) != 0 ? Verdict::kCannotSee
                                                               : portal_vis::verdict_near_planes(
                                                                     tables, sources[lane], t, 0, in_front);
            ++asked;
            if ((((front & bit) != 0) != in_front || vector != scalar) && differing++ < 5)
                ADD_FAILURE() << "trial " << trial << " lane " << lane << ": lanes and scalar differ";
        }
    }
    EXPECT_EQ(differing, 0u);
    EXPECT_EQ(asked, 2000u * 64u);
}

// Fewer leaves than lanes, and a first batch with a source into every leaf: every leaf is
// queued at once when the batch starts (the queue must not take itself for empty).
TEST(BaseVisBatch, RowsAreThoseOfAPlainFloodWhenTheSourcesStartInEveryLeaf)
{
    const Portals portals = generated_portals(5, 5);
    const Graph g = portal_vis::build_graph(portals.set, portals.regions);
    const portal_vis::BaseVisTables tables = portal_vis::base_vis_tables(g);
    ASSERT_LE(g.leaf_count, portal_vis::kBatchLanes);
    std::vector<uint32_t> first, rest;
    std::vector<bool> led_into(g.leaf_count, false);
    for (uint32_t i = 0; i < g.portals.size(); ++i) {
        const uint32_t leaf = g.portals[i].leaf;
        (led_into[leaf] ? rest : first).push_back(i);
        led_into[leaf] = true;
    }
    ASSERT_EQ(first.size(), size_t{g.leaf_count}) << "a portal into every leaf";
    first.insert(first.end(), rest.begin(), rest.end());
    expect_batch_rows_of_plain_flood(g, tables, first, "a source into every leaf first");
}

TEST(BaseVisBatch, RowsAreThoseOfAPlainFloodOnARealMap)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    const Zone* zone = test::shared_zone("quake/e1m1.bsp");
    ASSERT_NE(zone, nullptr);
    expect_batches_of_plain_flood(map_portals(*zone));
}

} // namespace
} // namespace pvs
