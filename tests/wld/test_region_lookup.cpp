// Point -> region on real trees, checked against independent tests:
//  1. the walk's leaf must lie inside every half-space on its path from the root, with the
//     path found by an independent parent-link search, not by the walk;
//  2. for a sample of points, a brute-force scan over every region's half-spaces must find
//     exactly the walk's region (and none when the walk ends in solid);
//  3. the centroid of every face, nudged off its front side, lies in a region listing the face.
// Plus the tie rules for points exactly on a split plane.
#include "tests/support/test_data.h"
#include "visibility/region_lookup.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <random>

namespace pvs {
namespace {

struct HalfSpace {
    uint32_t node;
    uint8_t side; // 0: strictly in front; 1: on or behind (Quake tie rule)
};

// Root-to-leaf constraints of every region leaf, from parent links.
std::vector<std::vector<HalfSpace>> region_paths(const Zone& zone)
{
    const BspTree& tree = zone.tree;
    std::vector<int64_t> node_parent(tree.nodes.size(), -1), leaf_parent(tree.leaf_region.size(), -1);
    std::vector<uint8_t> node_side(tree.nodes.size()), leaf_side(tree.leaf_region.size());
    std::vector<int32_t> stack{tree.root};
    while (!stack.empty()) {
        const int32_t n = stack.back();
        stack.pop_back();
        if (n < 0)
            continue;
        for (uint8_t side = 0; side < 2; ++side) {
            const int32_t c = tree.nodes[n].children[side];
            if (c >= 0) {
                node_parent[c] = n;
                node_side[c] = side;
                stack.push_back(c);
            } else {
                leaf_parent[~c] = n;
                leaf_side[~c] = side;
            }
        }
    }
    std::vector<std::vector<HalfSpace>> paths(zone.region_count());
    for (size_t leaf = 0; leaf < tree.leaf_region.size(); ++leaf) {
        const int32_t region = tree.leaf_region[leaf];
        if (region < 0 || leaf_parent[leaf] < 0)
            continue;
        auto& path = paths[region];
        path.push_back({uint32_t(leaf_parent[leaf]), leaf_side[leaf]});
        for (int64_t n = leaf_parent[leaf]; node_parent[n] >= 0; n = node_parent[n])
            path.push_back({uint32_t(node_parent[n]), node_side[n]});
    }
    return paths;
}

bool inside(const Zone& zone, const std::vector<HalfSpace>& path, const glm::vec3& p)
{
    for (const HalfSpace& h : path) {
        const BspNode& node = zone.tree.nodes[h.node];
        const float d = glm::dot(node.normal, p) - node.dist;
        if (h.side == 0 ? !(d > 0.0f) : !(d <= 0.0f))
            return false;
    }
    return true;
}

class QuakeLookup : public ::testing::TestWithParam<const char*> {};

TEST_P(QuakeLookup, WalkAgreesWithHalfSpaceTestsFor100000RandomPoints)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const Zone zone = load_zone(path);
    const auto paths = region_paths(zone);
    const Aabb box = zone.bounds();
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y), uz(box.min.z, box.max.z);
    size_t in_regions = 0;
    for (int i = 0; i < 100000; ++i) {
        const glm::vec3 p{ux(rng), uy(rng), uz(rng)};
        const PointLocation at = locate_point(zone.tree, p);
        if (!at.in_region()) {
            ASSERT_EQ(at.region, kLeafSolid);
            continue;
        }
        ++in_regions;
        ASSERT_TRUE(inside(zone, paths[at.region], p)) << "point " << i << " region " << at.region;
        if (i % 50 == 0) { // brute force: no other region may contain the point
            for (uint32_t r = 0; r < zone.region_count(); ++r) {
                if (r != uint32_t(at.region)) {
                    ASSERT_FALSE(inside(zone, paths[r], p)) << "point " << i << " also in region " << r;
                }
            }
        }
    }
    EXPECT_GT(in_regions, 1000u); // the sample really exercised open space
}

TEST_P(QuakeLookup, PointsInSolidAreInNoRegion)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const Zone zone = load_zone(path);
    const auto paths = region_paths(zone);
    const Aabb box = zone.bounds();
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y), uz(box.min.z, box.max.z);
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 p{ux(rng), uy(rng), uz(rng)};
        if (locate_point(zone.tree, p).in_region())
            continue;
        for (uint32_t r = 0; r < zone.region_count(); ++r)
            ASSERT_FALSE(inside(zone, paths[r], p)) << "solid point " << i << " inside region " << r;
    }
}

TEST_P(QuakeLookup, FaceCentroidsNudgedForwardLieInARegionListingTheFace)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const Zone zone = load_zone(path);
    std::vector<std::vector<uint32_t>> face_regions(zone.mesh.faces.size());
    for (uint32_t r = 0; r < zone.region_count(); ++r)
        for (uint32_t f : zone.faces_of_region(r))
            face_regions[f].push_back(r);
    size_t checked = 0, failed = 0;
    for (uint32_t f = 0; f < zone.mesh.faces.size(); ++f) {
        const Face& face = zone.mesh.faces[f];
        if (face_regions[f].empty())
            continue; // faces no leaf lists (none in id's maps; allowed by the format)
        glm::vec3 sum{0.0f};
        const uint32_t* tri = &zone.mesh.indices[3 * size_t(face.first_triangle)];
        for (uint32_t k = 0; k < 3 * face.triangle_count; ++k)
            sum += zone.mesh.positions[tri[k]];
        const glm::vec3 centroid = sum / float(3 * face.triangle_count);
        // The face's front from the area-weighted sum of its triangles' normals: a fan over
        // a polygon with T-junction vertices has zero-area triangles, so one triangle won't do.
        glm::vec3 area_normal{0.0f};
        for (uint32_t t = 0; t < face.triangle_count; ++t) {
            const glm::vec3 a = zone.mesh.positions[tri[3 * t]], b = zone.mesh.positions[tri[3 * t + 1]],
                            c = zone.mesh.positions[tri[3 * t + 2]];
            area_normal += glm::cross(b - a, c - a);
        }
        const glm::vec3 normal = glm::normalize(area_normal);
        const PointLocation at = locate_point(zone.tree, centroid + normal * 0.05f);
        ++checked;
        const auto& listing = face_regions[f];
        if (!at.in_region() || std::find(listing.begin(), listing.end(), uint32_t(at.region)) == listing.end()) {
            ++failed;
            ADD_FAILURE() << "face " << f << " centroid (" << centroid.x << "," << centroid.y << "," << centroid.z
                          << ") nudged forward is in region " << at.region;
            if (failed > 5)
                return;
        }
    }
    EXPECT_GE(checked, zone.mesh.faces.size() / 2);
}

INSTANTIATE_TEST_SUITE_P(SharedData, QuakeLookup,
                         ::testing::Values("quake/e1m1.bsp", "quake/e2m1.bsp", "quake/end.bsp", "visdemo/example.bsp"),
                         [](const ::testing::TestParamInfo<const char*>& param) { return test::param_name(param.param); });

// A one-node tree: the plane x = 0, front leaf 1 -> region 0, back leaf 2 -> region 1.
BspTree one_plane_tree(TieRule rule)
{
    BspTree tree;
    tree.nodes.push_back({{1.0f, 0.0f, 0.0f}, 0.0f, {~1, ~2}});
    tree.leaf_region = {kLeafSolid, 0, 1};
    tree.root = 0;
    tree.tie_rule = rule;
    return tree;
}

TEST(RegionLookupTies, QuakeSendsPointsOnThePlaneToTheBack)
{
    const BspTree tree = one_plane_tree(TieRule::OnPlaneGoesBack);
    EXPECT_EQ(locate_point(tree, {0.0f, 5.0f, 5.0f}).region, 1);
    EXPECT_EQ(locate_point(tree, {1e-6f, 0.0f, 0.0f}).region, 0);
    EXPECT_EQ(locate_point(tree, {-1e-6f, 0.0f, 0.0f}).region, 1);
}

TEST(RegionLookupTies, EverQuestSendsPointsOnThePlaneToTheFront)
{
    const BspTree tree = one_plane_tree(TieRule::OnPlaneGoesFront);
    EXPECT_EQ(locate_point(tree, {0.0f, 5.0f, 5.0f}).region, 0);
    EXPECT_EQ(locate_point(tree, {-1e-6f, 0.0f, 0.0f}).region, 1);
}

TEST(RegionLookupTies, NanEndsInALeafAndTraceRecordsThePath)
{
    const BspTree tree = one_plane_tree(TieRule::OnPlaneGoesBack);
    std::vector<PathStep> path;
    const PointLocation at = trace_point(tree, {std::nanf(""), 0.0f, 0.0f}, path);
    EXPECT_EQ(at.region, 1);
    ASSERT_EQ(path.size(), 1u);
    EXPECT_EQ(path[0].node, 0u);
    EXPECT_EQ(path[0].side, 1u);
}

TEST(RegionLookupTies, OneLeafTreeNeedsNoNode)
{
    BspTree tree;
    tree.leaf_region = {0};
    tree.root = ~0;
    EXPECT_EQ(locate_point(tree, {1, 2, 3}).region, 0);
}

} // namespace
} // namespace pvs
