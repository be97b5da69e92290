// `pvscope why`'s answers (visibility/eval/pair_explanation.h) against what is known without it:
// the visdemo example's hand-derived pairs (tests/support/visdemo_rows.h), a segment walk through
// the tree written here from scratch, the portals' own regions, and a bit set by hand.
#include "visibility/eval/pair_explanation.h"

#include "tests/support/freedoom.h"
#include "tests/support/test_data.h"
#include "tests/support/visdemo_rows.h"
#include "visibility/bit_row.h"
#include "visibility/reference/mesh_tracer.h"
#include "wld/eq/eq_zone_writer.h"
#include "gen/generate_zone.h"
#include "wld/zone_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <vector>

namespace pvs {
namespace {

// The regions (or kLeafSolid / kLeafOutside) of the leaves the segment p -> q passes through, in
// order: a plain recursive walk, splitting the segment at each node plane it crosses. Pieces of
// zero length are not visited (a segment through a cell's edge does not enter it).
void walk_segment(const BspTree& tree, int32_t child, glm::dvec3 p, glm::dvec3 q, std::vector<int32_t>& out)
{
    if (BspTree::is_leaf(child)) {
        if (p != q)
            out.push_back(tree.leaf_region[size_t(BspTree::leaf_index(child))]);
        return;
    }
    const BspNode& n = tree.nodes[size_t(child)];
    const glm::dvec3 normal(n.normal);
    const double dp = glm::dot(normal, p) - double(n.dist), dq = glm::dot(normal, q) - double(n.dist);
    if (dp == 0.0 && dq == 0.0) {
        walk_segment(tree, n.children[tree.tie_rule == TieRule::OnPlaneGoesBack ? 1 : 0], p, q, out);
    } else if (dp >= 0.0 && dq >= 0.0) {
        walk_segment(tree, n.children[0], p, q, out);
    } else if (dp <= 0.0 && dq <= 0.0) {
        walk_segment(tree, n.children[1], p, q, out);
    } else {
        const glm::dvec3 m = p + (q - p) * (dp / (dp - dq));
        walk_segment(tree, n.children[dp > 0.0 ? 0 : 1], p, m, out);
        walk_segment(tree, n.children[dp > 0.0 ? 1 : 0], m, q, out);
    }
}

// The witness starts in A, ends in B and meets nothing solid on the way (by the walk above).
void expect_witness_open(const Zone& zone, const PairExplanation& e)
{
    ASSERT_TRUE(e.witness);
    std::vector<int32_t> leaves;
    walk_segment(zone.tree, zone.tree.root, e.witness->from, e.witness->to, leaves);
    ASSERT_FALSE(leaves.empty());
    EXPECT_EQ(leaves.front(), int32_t(e.a)) << "the witness starts outside A";
    EXPECT_EQ(leaves.back(), int32_t(e.b)) << "the witness ends outside B";
    for (const int32_t region : leaves)
        EXPECT_GE(region, 0) << "the witness " << e.a << " -> " << e.b << " passes a solid or outside leaf";
    std::vector<uint32_t> crossed; // the walk's regions, consecutive repeats once
    for (const int32_t region : leaves)
        if (region >= 0 && (crossed.empty() || crossed.back() != uint32_t(region)))
            crossed.push_back(uint32_t(region));
    EXPECT_EQ(e.witness_regions, crossed);
    ASSERT_TRUE(e.camera);
    const glm::dvec3 along = glm::normalize(e.witness->to - e.witness->from);
    EXPECT_NEAR(std::atan2(along.y, along.x) * 180.0 / M_PI, e.camera->yaw_degrees, 1e-9);
}

// The chain is a walk through portals from A to B: each step's portal joins the region before it
// and the step's region, and the window the flow saw lies on that portal's plane, no larger.
void expect_chain_is_a_walk(const PairExplanation& e)
{
    ASSERT_TRUE(e.chain);
    ASSERT_FALSE(e.chain->steps.empty());
    uint32_t before = e.a;
    for (const ChainStep& step : e.chain->steps) {
        ASSERT_LT(step.portal, e.portals.portals.size());
        const Portal& portal = e.portals.portals[step.portal];
        const bool joins = (portal.regions[0] == int32_t(before) && portal.regions[1] == int32_t(step.region)) ||
                           (portal.regions[1] == int32_t(before) && portal.regions[0] == int32_t(step.region));
        EXPECT_TRUE(joins) << "portal " << step.portal << " does not join " << before << " and " << step.region;
        EXPECT_LE(step.window_size, step.portal_size * (1 + 1e-9) + 1e-9);
        EXPECT_GT(step.window_size, 0.0);
        EXPECT_EQ(step.separator_planes.size(), step.separators);
        for (const glm::dvec4& plane : step.separator_planes)
            EXPECT_NEAR(glm::length(glm::dvec3(plane)), 1.0, 1e-9);
        before = step.region;
    }
    EXPECT_EQ(before, e.b);
}

ExplainOptions quick_options()
{
    ExplainOptions options;
    options.flow.threads = 2;
    options.witness_budget = 20000;
    return options;
}

TEST(PairExplanation, VisdemoWitnessesAreExactlyTheHandDerivedPairs)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.bsp");
    const Zone& zone = *test::shared_zone("visdemo/example.bsp");
    ASSERT_EQ(zone.region_count(), 11u);
    size_t witnesses = 0, chains = 0;
    for (uint32_t a = 0; a < 11; ++a) {
        const std::vector<uint32_t>& sees = test::kExampleExpected[a];
        for (uint32_t b = 0; b < 11; ++b) {
            const PairExplanation e = explain_pair(zone, nullptr, a, b, quick_options());
            const bool expected = std::find(sees.begin(), sees.end(), b) != sees.end();
            EXPECT_EQ(e.witness.has_value(), expected)
                << a << " -> " << b << (expected ? ": the layout has a sight line, none found" : ": a witness the layout rules out");
            if (e.witness) {
                expect_witness_open(zone, e);
                ++witnesses;
            }
            // The flow is conservative: it holds every pair with a sight line, and has a chain
            // for exactly the pairs it holds (itself excepted: no walk enters A from A).
            if (expected) {
                EXPECT_TRUE(e.flow_holds) << a << " -> " << b;
            }
            if (a != b) {
                EXPECT_EQ(e.chain.has_value(), e.flow_holds) << a << " -> " << b;
                if (e.chain) {
                    expect_chain_is_a_walk(e);
                    ++chains;
                }
            }
            EXPECT_EQ(e.verdict, expected ? PairVerdict::Sees : PairVerdict::Overdraw) << a << " -> " << b;
        }
    }
    EXPECT_GT(chains, 40u);
    EXPECT_GT(witnesses, 80u);
}

// A bit a vis tool could not have set (no sight line, no chain of the flow) is called what it is;
// the same pair without the bit is hidden; a neighbour through one portal sees it with a chain of
// one step.
TEST(PairExplanation, BitSetByHandIsUnexplained)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    const Zone& zone = *test::shared_zone("quake/e1m1.bsp");
    ASSERT_TRUE(zone.baked_pvs);
    const Pvs& file = *zone.baked_pvs;
    // A far pair the file lacks: the first region whose row misses the last one.
    const uint32_t n = uint32_t(zone.region_count());
    uint32_t a = 0, b = n - 1;
    while (a < n && file.visible(a, b))
        ++a;
    ASSERT_LT(a, n);
    const Pvs edited = Pvs::build(n, [&](uint32_t r, std::span<uint64_t> row) {
        file.decode_row(r, row);
        if (r == a)
            bits::set(row, b);
        return true;
    });
    ExplainOptions options = quick_options();
    const PairExplanation forged = explain_pair(zone, &edited, a, b, options);
    EXPECT_TRUE(forged.in_pvs);
    EXPECT_FALSE(forged.witness);
    EXPECT_FALSE(forged.chain);
    EXPECT_EQ(forged.verdict, PairVerdict::Unexplained) << forged.summary;
    options.want_chain = false;
    const PairExplanation plain = explain_pair(zone, &file, a, b, options);
    EXPECT_EQ(plain.verdict, PairVerdict::Hidden) << plain.summary;

    // A neighbour: the first portal of the set the flow bakes on that joins a to another region.
    options.want_chain = true;
    const PortalSet portals = method_portals(zone, options.flow);
    const Portal* joining = nullptr;
    for (const Portal& p : portals.portals)
        if ((p.regions[0] == int32_t(a) || p.regions[1] == int32_t(a)) && p.regions[0] >= 0 && p.regions[1] >= 0) {
            joining = &p;
            break;
        }
    ASSERT_NE(joining, nullptr);
    const uint32_t neighbour = uint32_t(joining->regions[0] == int32_t(a) ? joining->regions[1] : joining->regions[0]);
    const PairExplanation next = explain_pair(zone, &file, a, neighbour, options);
    EXPECT_EQ(next.verdict, PairVerdict::Sees) << next.summary;
    expect_witness_open(zone, next);
    expect_chain_is_a_walk(next);
    EXPECT_EQ(next.chain->steps.size(), 1u);
}

// Doom's 2-D flow records chains too (widths of column portals), and its witnesses pass the walk.
TEST(PairExplanation, DoomTwoDimensionalChain)
{
    FREEDOOM_OR_SKIP(wad, "freedoom2.wad");
    const auto gwa = test::gl_nodes_file(wad, test::GlBuilder::glbsp_v5);
    if (!gwa)
        GTEST_SKIP() << "SKIPPED: glbsp is not installed";
    ZoneLoadOptions load;
    load.map = "MAP01";
    load.gwa = *gwa;
    const Zone zone = load_zone(wad, load);
    ExplainOptions options = quick_options();
    size_t chains = 0;
    for (uint32_t b = 1; b < 40 && chains < 3; ++b) {
        const PairExplanation e = explain_pair(zone, nullptr, 0, b, options);
        EXPECT_TRUE(e.chain_2d);
        if (!e.chain)
            continue;
        ++chains;
        expect_chain_is_a_walk(e);
        if (e.witness)
            expect_witness_open(zone, e);
    }
    EXPECT_GT(chains, 0u);
}

// A bit taken out of the hand-derived PVS pops: the witness is the camera that shows it, and the
// flow (which holds the pair) is not cut along it.
TEST(PairExplanation, RemovedBitWouldPop)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.bsp");
    const Zone& zone = *test::shared_zone("visdemo/example.bsp");
    const Pvs hand = Pvs::build(11, [&](uint32_t r, std::span<uint64_t> row) {
        for (const uint32_t c : test::kExampleExpected[r])
            if (!(r == 0 && c == 10))
                bits::set(row, c);
        return true;
    });
    const PairExplanation e = explain_pair(zone, &hand, 0, 10, quick_options());
    EXPECT_EQ(e.verdict, PairVerdict::WouldPop) << e.summary;
    EXPECT_FALSE(e.in_pvs);
    expect_witness_open(zone, e);
    EXPECT_TRUE(e.flow_holds);
    EXPECT_FALSE(e.flow_cut);
    EXPECT_GE(e.witness_regions.size(), 5u) << "0 sees 10 only through the corridor, 2, 4, 5, 6, 7";
    const PairExplanation kept = explain_pair(zone, &hand, 10, 0, quick_options());
    EXPECT_EQ(kept.verdict, PairVerdict::Sees) << kept.summary;
}

// An EverQuest zone (a generated one, written as .s3d and read back): a region and its first
// neighbour through the flow's portals see each other through one portal, and the witness is
// open by the test's own walk.
TEST(PairExplanation, EverQuestZoneNeighbours)
{
    gen::GenParams params = gen::demo_zone_params();
    params.rooms = 12;
    const Zone generated = gen::generate_zone(params);
    const std::vector<uint8_t> bytes = eq::write_eq_zone(generated, "whyzone");
    const std::string path = (std::filesystem::temp_directory_path() / "pvscope-why-test.s3d").string();
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    const Zone zone = load_zone(path, {});
    std::remove(path.c_str());
    ASSERT_GT(zone.region_count(), 2u);
    ExplainOptions options = quick_options();
    const PortalSet portals = method_portals(zone, options.flow);
    ASSERT_FALSE(portals.portals.empty());
    const Portal& first = portals.portals.front();
    ASSERT_GE(first.regions[0], 0);
    ASSERT_GE(first.regions[1], 0);
    const PairExplanation e = explain_pair(zone, zone.baked_pvs ? &*zone.baked_pvs : nullptr,
                                           uint32_t(first.regions[0]), uint32_t(first.regions[1]), options);
    EXPECT_EQ(e.verdict, PairVerdict::Sees) << e.summary;
    expect_witness_open(zone, e);
    expect_chain_is_a_walk(e);
}

// The nearest triangle the ray from `eye` through `to` meets (Moller-Trumbore over every triangle
// of the mesh, no acceleration: independent of Embree), as its face, or -1.
int64_t nearest_face(const Zone& zone, const glm::dvec3& eye, const glm::dvec3& to)
{
    const glm::dvec3 dir = glm::normalize(to - eye);
    double best = 1e30;
    int64_t best_face = -1;
    for (uint32_t f = 0; f < zone.mesh.faces.size(); ++f) {
        const Face& face = zone.mesh.faces[f];
        for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t) {
            const glm::dvec3 a(zone.mesh.positions[zone.mesh.indices[size_t(t) * 3]]);
            const glm::dvec3 b(zone.mesh.positions[zone.mesh.indices[size_t(t) * 3 + 1]]);
            const glm::dvec3 c(zone.mesh.positions[zone.mesh.indices[size_t(t) * 3 + 2]]);
            const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(dir, e2);
            const double det = glm::dot(e1, p);
            if (std::abs(det) < 1e-12)
                continue;
            const glm::dvec3 s = eye - a;
            const double u = glm::dot(s, p) / det;
            const glm::dvec3 q = glm::cross(s, e1);
            const double v = glm::dot(dir, q) / det, dist = glm::dot(e2, q) / det;
            if (u < 0 || v < 0 || u + v > 1 || dist <= 1e-6 || dist >= best)
                continue;
            best = dist;
            best_face = f;
        }
    }
    return best_face;
}

// An OBJ level with its .hepvs grid: cells see objects. For pairs HateEngine's baker set, the
// witness search finds lines whose eye lies in the cell and whose first hit (by a brute-force
// ray test written here) is a face of the object.
TEST(PairExplanation, GridZoneCellToObject)
{
    SHARED_DATA_OR_SKIP(path, "hateengine/E1M1.obj");
    const Zone zone = load_zone(path, {});
    ASSERT_TRUE(zone.view_grid && zone.baked_pvs);
    const Pvs& file = *zone.baked_pvs;
    ExplainOptions options = quick_options();
    size_t asked = 0, found = 0;
    std::vector<uint64_t> row(file.words_per_row());
    const MeshTracer tracer(zone); // only to choose cells a camera can stand in
    for (uint32_t cell = 0; cell < file.row_count() && asked < 8; cell += 7) {
        if (!tracer.in_open_space(zone.view_grid->cell_bounds(cell).center()))
            continue;
        file.decode_row(cell, row);
        // The row's object with the most faces (a wall of the room, not a far speck).
        int64_t object = -1;
        for (uint32_t o = 0; o < file.region_count(); ++o)
            if (bits::test(row, o) && (object < 0 || zone.faces_of_region(o).size() > zone.faces_of_region(uint32_t(object)).size()))
                object = o;
        if (object < 0)
            continue;
        ++asked;
        const PairExplanation e = explain_pair(zone, &file, cell, uint32_t(object), options);
        EXPECT_TRUE(e.grid);
        EXPECT_FALSE(e.chain);
        EXPECT_TRUE(e.in_pvs);
        if (!e.witness) {
            EXPECT_EQ(e.verdict, PairVerdict::Overdraw);
            continue;
        }
        ++found;
        EXPECT_EQ(e.verdict, PairVerdict::Sees);
        const Aabb box = zone.view_grid->cell_bounds(cell);
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(e.witness->from[k], double(box.min[k]) - 1e-3);
            EXPECT_LE(e.witness->from[k], double(box.max[k]) + 1e-3);
        }
        const int64_t face = nearest_face(zone, e.witness->from, e.witness->to);
        ASSERT_GE(face, 0);
        const auto faces = zone.faces_of_region(uint32_t(object));
        EXPECT_NE(std::find(faces.begin(), faces.end(), uint32_t(face)), faces.end())
            << "cell " << cell << " -> object " << object << ": the ray's first face is another object's";
    }
    std::printf("[ E1M1.obj ] %zu cell -> object pairs of the .hepvs asked, %zu with a sight line\n", asked, found);
    EXPECT_GE(asked, 6u);
    EXPECT_GE(found * 2, asked) << "HateEngine's pairs are seen from the cell: most have a line";
}

TEST(PairExplanation, RegionOutOfRangeNamesTheCount)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.bsp");
    const Zone& zone = *test::shared_zone("visdemo/example.bsp");
    try {
        explain_pair(zone, nullptr, 0, 11, quick_options());
        FAIL() << "no error for region 11 of 11";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("region 11 is out of range"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("has 11 regions"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace pvs
