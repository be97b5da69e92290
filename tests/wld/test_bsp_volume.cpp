// BSP node and leaf volumes on a hand-built tree and on real Quake trees:
//  1. random points: inside every bounding plane of the leaf the walk finds, and inside that
//     leaf's volume bounds (single-leaf and whole-tree computations agree);
//  2. the leaves' cells partition the world box: their volumes, computed here from each cell's
//     faces, add up to the box's (for the direct per-path cells and the top-down ones);
//  3. Quake faces clipped to the leaves of the regions listing them: a face listed once keeps all
//     its area, and a face's pieces over its listing leaves add up to the face (a Quake face may
//     span several leaves below the node of its plane, each listing it);
//  4. node plane polygons: non-empty for every node the root reaches, inside the world box, on
//     their planes.
#include "tests/support/test_data.h"
#include "visibility/geometry/bsp_volume.h"
#include "visibility/region_lookup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <map>
#include <random>
#include <string>

namespace pvs {
namespace {

// The world box the tests cut: the zone's bounds with a margin, so no split plane lies on it.
Aabb world_box(const Zone& zone)
{
    Aabb box = zone.bounds();
    box.min -= glm::vec3(64.0f);
    box.max += glm::vec3(64.0f);
    return box;
}

double box_volume(const Aabb& box)
{
    const glm::dvec3 s(box.size());
    return s.x * s.y * s.z;
}

// Volume of a convex cell from its faces (divergence theorem with apex p0 inside): each face
// contributes area * distance(p0, face plane) / 3, the planes pointing inward.
double cell_volume(const ConvexCell& cell)
{
    if (cell.empty())
        return 0.0;
    glm::dvec3 p0(0.0);
    size_t count = 0;
    for (const Winding& face : cell.faces)
        for (const glm::vec3& p : face.points) {
            p0 += glm::dvec3(p);
            ++count;
        }
    p0 /= double(count);
    double volume = 0.0;
    for (size_t i = 0; i < cell.faces.size(); ++i) {
        const Plane& plane = cell.planes[i];
        const double d = glm::dot(glm::dvec3(plane.normal), p0) - double(plane.dist);
        volume += double(cell.faces[i].area()) * d / 3.0;
    }
    return volume;
}

// Every leaf slot's root-to-leaf half-spaces, found by an independent recursive walk.
void collect_slot_paths(const BspTree& tree, int32_t child, std::vector<Plane>& path,
                        std::vector<std::pair<int32_t, std::vector<Plane>>>& out)
{
    if (BspTree::is_leaf(child)) {
        out.emplace_back(BspTree::leaf_index(child), path);
        return;
    }
    const BspNode& node = tree.nodes[size_t(child)];
    const Plane plane{node.normal, node.dist};
    path.push_back(plane);
    collect_slot_paths(tree, node.children[0], path, out);
    path.back() = plane.flipped();
    collect_slot_paths(tree, node.children[1], path, out);
    path.pop_back();
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// x = 0 at the root; its back side split again by y = 0. Leaves: 0 = x > 0, 1 = x < 0 & y > 0,
// 2 = x < 0 & y < 0.
BspTree cross_tree()
{
    BspTree tree;
    tree.nodes.push_back({{1, 0, 0}, 0.0f, {~0, 1}});
    tree.nodes.push_back({{0, 1, 0}, 0.0f, {~1, ~2}});
    tree.leaf_region = {0, 1, 2};
    tree.root = 0;
    return tree;
}

TEST(BspVolume, HandBuiltTreeGivesTheExpectedPlanesCellsAndPolygons)
{
    const BspTree tree = cross_tree();
    const Aabb world{{-10, -20, -30}, {10, 20, 30}};

    const std::vector<Plane> planes = leaf_bounding_planes(tree, 2);
    ASSERT_EQ(planes.size(), 2u);
    EXPECT_EQ(planes[0].normal, glm::vec3(-1, 0, 0)); // into the leaf: back of x = 0
    EXPECT_EQ(planes[1].normal, glm::vec3(0, -1, 0));
    EXPECT_EQ(leaf_bounding_planes(tree, 0).size(), 1u);

    const Aabb b0 = leaf_volume_bounds(tree, 0, world), b2 = leaf_volume_bounds(tree, 2, world);
    const glm::vec3 e(kCellEpsilon);
    EXPECT_EQ(b0.min, glm::vec3(0, -20, -30) - e);
    EXPECT_EQ(b0.max, glm::vec3(10, 20, 30) + e);
    EXPECT_EQ(b2.min, glm::vec3(-10, -20, -30) - e);
    EXPECT_EQ(b2.max, glm::vec3(0, 0, 30) + e);
    const std::vector<Aabb> all = all_leaf_volume_bounds(tree, world);
    ASSERT_EQ(all.size(), 3u);
    EXPECT_EQ(all[0].min, b0.min);
    EXPECT_EQ(all[2].max, b2.max);

    const std::vector<Winding> polygons = node_plane_polygons(tree, world);
    ASSERT_EQ(polygons.size(), 2u);
    EXPECT_FLOAT_EQ(polygons[0].area(), 40.0f * 60.0f); // x = 0 across the whole box
    EXPECT_FLOAT_EQ(polygons[1].area(), 10.0f * 60.0f); // y = 0 in the x < 0 half
    EXPECT_EQ(polygons[1].normal(), glm::vec3(0, 1, 0));
    EXPECT_EQ(polygons[1].bounds().max.x, 0.0f);

    // A triangle across all three leaves, clipped to leaf 1 (x <= 0, y >= 0).
    const Winding tri{{-5, -5, 0}, {5, -5, 0}, {-5, 5, 0}};
    const Winding part = clip_to_leaf(tri, tree, 1, kWindingOnEpsilon);
    EXPECT_FLOAT_EQ(part.area(), 12.5f);

    double total = 0.0;
    for_each_leaf_cell(tree, world, [&](int32_t, const ConvexCell& cell) { total += cell_volume(cell); });
    EXPECT_NEAR(total, box_volume(world), 1e-6 * box_volume(world));

    // A leaf the tree does not reach has no volume; a one-leaf tree's leaf is the world.
    BspTree unreached = tree;
    unreached.leaf_region.push_back(3);
    EXPECT_TRUE(leaf_volume_bounds(unreached, 3, world).empty());
    EXPECT_TRUE(clip_to_leaf(tri, unreached, 3, kWindingOnEpsilon).empty());
    EXPECT_TRUE(leaf_volume_bounds(unreached, 99, world).empty());
    BspTree single;
    single.leaf_region = {0};
    single.root = ~0;
    EXPECT_TRUE(leaf_bounding_planes(single, 0).empty());
    EXPECT_EQ(clip_to_leaf(tri, single, 0, kWindingOnEpsilon).points, tri.points);
    EXPECT_EQ(leaf_volume_bounds(single, 0, world).min, world.min - e);
    EXPECT_TRUE(all_leaf_volume_bounds(single, world)[0].contains(world.max));
}

TEST(BspVolume, SharedLeafGetsTheCommonPlanesAndTheUnionOfItsCells)
{
    BspTree tree = cross_tree();
    tree.nodes[1].children[1] = ~0; // leaf 0 now also holds x < 0 & y < 0
    const Aabb world{{-10, -20, -30}, {10, 20, 30}};
    EXPECT_TRUE(leaf_bounding_planes(tree, 0).empty()); // paths diverge at the root
    const Aabb b = leaf_volume_bounds(tree, 0, world);
    EXPECT_EQ(b.min, world.min - glm::vec3(kCellEpsilon));
    EXPECT_EQ(b.max, world.max + glm::vec3(kCellEpsilon));
    EXPECT_EQ(all_leaf_volume_bounds(tree, world)[0].min, b.min);
    int visits = 0;
    for_each_leaf_cell(tree, world, [&](int32_t leaf, const ConvexCell&) { visits += leaf == 0; });
    EXPECT_EQ(visits, 2);
}

TEST(BspVolume, RandomPointsLieInTheirLeafsPlanesAndBounds)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    const Zone* zone = test::shared_zone("quake/e1m1.bsp");
    ASSERT_NE(zone, nullptr);
    const BspTree& tree = zone->tree;
    const Aabb world = world_box(*zone);

    auto start = std::chrono::steady_clock::now();
    const std::vector<Aabb> all_bounds = all_leaf_volume_bounds(tree, world);
    const double all_seconds = seconds_since(start);

    std::map<int32_t, std::vector<Plane>> planes_of;
    std::map<int32_t, Aabb> bounds_of;
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> ux(world.min.x, world.max.x), uy(world.min.y, world.max.y),
        uz(world.min.z, world.max.z);
    int outside_planes = 0, outside_bounds = 0, outside_all_bounds = 0;
    start = std::chrono::steady_clock::now();
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 p(ux(rng), uy(rng), uz(rng));
        const int32_t leaf = locate_point(tree, p).leaf;
        auto planes = planes_of.find(leaf);
        if (planes == planes_of.end()) {
            planes = planes_of.emplace(leaf, leaf_bounding_planes(tree, leaf)).first;
            bounds_of.emplace(leaf, leaf_volume_bounds(tree, leaf, world));
        }
        // Closed half-spaces: the walk's tie rule puts d == 0 on one side, and both contain it.
        for (const Plane& plane : planes->second)
            if (!(plane.distance(p) >= 0.0f)) {
                ++outside_planes;
                break;
            }
        outside_bounds += !bounds_of.at(leaf).contains(p);
        outside_all_bounds += !all_bounds[size_t(leaf)].contains(p);
    }
    const double per_leaf_seconds = seconds_since(start);
    EXPECT_EQ(outside_planes, 0);
    EXPECT_EQ(outside_bounds, 0);
    EXPECT_EQ(outside_all_bounds, 0);

    // The direct per-leaf cells and the top-down ones agree.
    float worst = 0.0f;
    for (const auto& [leaf, box] : bounds_of) {
        worst = std::max(worst, glm::length(box.min - all_bounds[size_t(leaf)].min));
        worst = std::max(worst, glm::length(box.max - all_bounds[size_t(leaf)].max));
    }
    EXPECT_LT(worst, 0.05f);
    std::printf("[ e1m1 ] %zu distinct leaves hit; all_leaf_volume_bounds %.3f s; per-leaf planes+bounds %.3f s; "
                "largest per-leaf vs top-down bounds difference %.5f\n",
                planes_of.size(), all_seconds, per_leaf_seconds, double(worst));
}

std::string test_name(const ::testing::TestParamInfo<const char*>& param) { return test::param_name(param.param); }

class QuakeVolume : public ::testing::TestWithParam<const char*> {};

TEST_P(QuakeVolume, LeafCellsPartitionTheWorldBox)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const Zone* zone = test::shared_zone(GetParam());
    ASSERT_NE(zone, nullptr);
    const BspTree& tree = zone->tree;
    const Aabb world = world_box(*zone);
    const double expected = box_volume(world);

    // Direct: each slot's path collected here, its cell from convex_cell.
    auto start = std::chrono::steady_clock::now();
    std::vector<Plane> path_planes;
    std::vector<std::pair<int32_t, std::vector<Plane>>> slots;
    collect_slot_paths(tree, tree.root, path_planes, slots);
    double direct = 0.0;
    size_t empty_cells = 0;
    for (const auto& [leaf, planes] : slots) {
        const ConvexCell cell = convex_cell(planes, world);
        empty_cells += cell.empty();
        direct += cell_volume(cell);
    }
    const double direct_seconds = seconds_since(start);

    // Top-down.
    start = std::chrono::steady_clock::now();
    double top_down = 0.0;
    size_t visits = 0;
    for_each_leaf_cell(tree, world, [&](int32_t, const ConvexCell& cell) {
        top_down += cell_volume(cell);
        ++visits;
    });
    const double top_down_seconds = seconds_since(start);

    EXPECT_EQ(visits, slots.size());
    EXPECT_NEAR(direct, expected, 1e-3 * expected);
    EXPECT_NEAR(top_down, expected, 1e-3 * expected);
    std::printf("[ %s ] %zu leaf slots (%zu empty cells); box %.6g; direct sum %.6g (rel. error %.2e, %.2f s); "
                "top-down sum %.6g (rel. error %.2e, %.2f s)\n",
                test::param_name(GetParam()).c_str(), slots.size(), empty_cells, expected, direct,
                (direct - expected) / expected, direct_seconds, top_down, (top_down - expected) / expected,
                top_down_seconds);
}

INSTANTIATE_TEST_SUITE_P(RealMaps, QuakeVolume,
                         ::testing::Values("quake/e1m1.bsp", "quake/dm2.bsp", "visdemo/example.bsp"), test_name);

// How much of each Quake face the leaves listing it keep, faces clipped triangle by triangle.
struct FaceCoverage {
    std::vector<double> pair_kept;    // per (face, listing region): fraction of the face's area kept
    std::vector<double> single_kept;  // the same for faces listed by exactly one region
    std::vector<double> face_covered; // per listed face: sum of its fractions over its listing regions
    std::map<int, int> faces_by_listing_count;
    size_t mismatches = 0; // clip_to_leaf differing from clip_to_planes(leaf_bounding_planes)
    double seconds = 0.0;
};

FaceCoverage face_coverage(const Zone& zone, float epsilon)
{
    FaceCoverage out;
    const Mesh& mesh = zone.mesh;
    std::vector<double> covered(mesh.faces.size(), 0.0), first(mesh.faces.size(), 0.0);
    std::vector<int> listings(mesh.faces.size(), 0);
    const auto start = std::chrono::steady_clock::now();
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        const int32_t leaf = int32_t(r) + 1; // Quake: region r is leaf r + 1
        const std::vector<Plane> planes = leaf_bounding_planes(zone.tree, leaf);
        for (const uint32_t f : zone.faces_of_region(r)) {
            const Face& face = mesh.faces[f];
            double total = 0.0, inside = 0.0;
            for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t) {
                const Winding tri{mesh.positions[mesh.indices[3 * t]], mesh.positions[mesh.indices[3 * t + 1]],
                                  mesh.positions[mesh.indices[3 * t + 2]]};
                total += tri.area();
                // clip_to_leaf finds the leaf's path on every call: used on a sample, the same
                // planes found once per region otherwise.
                const Winding part = clip_to_planes(tri, planes, epsilon);
                if (f % 16 == 0 && clip_to_leaf(tri, zone.tree, leaf, epsilon).points != part.points)
                    ++out.mismatches;
                inside += part.area();
            }
            if (total > 0.0) {
                out.pair_kept.push_back(inside / total);
                covered[f] += inside / total;
                first[f] = inside / total;
                ++listings[f];
            }
        }
    }
    out.seconds = seconds_since(start);
    for (size_t f = 0; f < covered.size(); ++f) {
        if (listings[f] == 0)
            continue;
        out.face_covered.push_back(covered[f]);
        ++out.faces_by_listing_count[listings[f]];
        if (listings[f] == 1)
            out.single_kept.push_back(first[f]);
    }
    for (auto* v : {&out.pair_kept, &out.single_kept, &out.face_covered})
        std::sort(v->begin(), v->end());
    return out;
}

// Fraction of the sorted values that are >= x.
double share_at_least(const std::vector<double>& sorted, double x)
{
    return double(sorted.end() - std::lower_bound(sorted.begin(), sorted.end(), x)) / double(sorted.size());
}

// A face lies on its leaves' boundary (on a plane of their paths, within the file's vertex
// noise), so the front-side epsilon must keep points ON: kWindingOnEpsilon. A Quake face is
// stored at the node of its plane, split only by that node's ancestors, so it may span several
// leaves below that node: each listing leaf keeps its own piece. So the checks are: a face listed
// once keeps its area; a face's pieces over all its listing leaves add up to the face; no
// leaf lists a face it does not touch.
class QuakeFaceVolume : public ::testing::TestWithParam<const char*> {};

TEST_P(QuakeFaceVolume, FacesClippedToTheirRegionsLeafKeepTheirArea)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const Zone* zone = test::shared_zone(GetParam());
    ASSERT_NE(zone, nullptr);
    const FaceCoverage c = face_coverage(*zone, kWindingOnEpsilon);
    ASSERT_FALSE(c.pair_kept.empty());
    ASSERT_FALSE(c.single_kept.empty());
    EXPECT_EQ(c.mismatches, 0u);
    // Faces listed by one region: whole. All faces: their pieces add up to the face (not more:
    // the listing leaves do not overlap on it). Pairs: the leaf touches the face.
    EXPECT_GE(share_at_least(c.single_kept, 0.99), 0.99);
    size_t covered = 0;
    for (double x : c.face_covered)
        covered += x >= 0.99 && x <= 1.01;
    EXPECT_GE(double(covered), 0.99 * double(c.face_covered.size()));
    EXPECT_GE(share_at_least(c.pair_kept, 1e-6), 0.99);

    const auto& kept = c.pair_kept;
    std::printf("[ %s ] %zu (face, region) pairs in %.2f s; area kept per pair: >= 99%%: %.2f%%, >= 90%%: %.2f%%, "
                ">= 50%%: %.2f%%, > 0: %.2f%%; min %.4f, 1st percentile %.4f, median %.4f\n",
                test::param_name(GetParam()).c_str(), kept.size(), c.seconds, 100.0 * share_at_least(kept, 0.99),
                100.0 * share_at_least(kept, 0.90), 100.0 * share_at_least(kept, 0.5),
                100.0 * share_at_least(kept, 1e-9), kept.front(), kept[kept.size() / 100], kept[kept.size() / 2]);
    std::printf("[ %s ] faces listed once: %zu, >= 99%% kept: %.2f%%, min %.4f; per face, its pieces summed over its "
                "listing regions: min %.4f, max %.4f; faces by listing count:",
                test::param_name(GetParam()).c_str(), c.single_kept.size(), 100.0 * share_at_least(c.single_kept, 0.99),
                c.single_kept.front(), c.face_covered.front(), c.face_covered.back());
    for (const auto& [n, count] : c.faces_by_listing_count)
        std::printf(" %d:%d", n, count);
    std::printf("\n");
}

INSTANTIATE_TEST_SUITE_P(RealMaps, QuakeFaceVolume,
                         ::testing::Values("quake/e1m1.bsp", "quake/e2m1.bsp", "quake/dm2.bsp"), test_name);

class NodePlaneVolume : public ::testing::TestWithParam<const char*> {};

TEST_P(NodePlaneVolume, NodePlanePolygonsAreNonEmptyAndInsideTheWorldBox)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const Zone* zone = test::shared_zone(GetParam());
    ASSERT_NE(zone, nullptr);
    const BspTree& tree = zone->tree;
    const Aabb world = world_box(*zone);
    const std::vector<Winding> polygons = node_plane_polygons(tree, world);
    ASSERT_EQ(polygons.size(), tree.nodes.size());
    ASSERT_FALSE(polygons.empty());

    // The nodes the root reaches (Quake files also hold brush entities' trees, not reached).
    std::vector<uint8_t> reached(tree.nodes.size(), 0);
    std::vector<int32_t> stack{tree.root};
    while (!stack.empty()) {
        const int32_t child = stack.back();
        stack.pop_back();
        if (BspTree::is_leaf(child))
            continue;
        reached[size_t(child)] = 1;
        stack.push_back(tree.nodes[size_t(child)].children[0]);
        stack.push_back(tree.nodes[size_t(child)].children[1]);
    }

    Aabb slack = world;
    slack.min -= glm::vec3(kCellEpsilon + 1e-3f);
    slack.max += glm::vec3(kCellEpsilon + 1e-3f);
    size_t reached_count = 0, empty = 0, unreached_not_empty = 0, wrong_facing = 0, outside = 0, off_plane = 0;
    double total_area = 0.0;
    for (size_t n = 0; n < polygons.size(); ++n) {
        const Winding& w = polygons[n];
        if (!reached[n]) {
            unreached_not_empty += !w.points.empty();
            continue;
        }
        ++reached_count;
        if (w.empty() || !(w.area() > 0.0f)) {
            ++empty;
            continue;
        }
        const Plane plane{tree.nodes[n].normal, tree.nodes[n].dist};
        wrong_facing += !(glm::dot(w.normal(), plane.normal) > 0.999f);
        for (const glm::vec3& p : w.points) {
            outside += !slack.contains(p);
            off_plane += !(std::abs(plane.distance(p)) <= 0.01f);
        }
        total_area += w.area();
    }
    EXPECT_GT(reached_count, 0u);
    EXPECT_EQ(empty, 0u);
    EXPECT_EQ(unreached_not_empty, 0u);
    EXPECT_EQ(wrong_facing, 0u);
    EXPECT_EQ(outside, 0u);
    EXPECT_EQ(off_plane, 0u);
    std::printf("[ %s ] %zu nodes reached from the root (of %zu), all with a polygon; total polygon area %.6g\n",
                test::param_name(GetParam()).c_str(), reached_count, polygons.size(), total_area);
}

INSTANTIATE_TEST_SUITE_P(RealMaps, NodePlaneVolume,
                         ::testing::Values("visdemo/example.bsp", "quake/e1m1.bsp"), test_name);

} // namespace
} // namespace pvs
