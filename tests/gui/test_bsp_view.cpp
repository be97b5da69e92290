// The BSP views the inspector draws from: the culling camera's path (checked against a walk of
// the tree written here from the node planes), each path node's split-plane polygon lying on its
// plane and inside its ancestors' half-spaces (its cell), and the regions under a node.
#include "ui/gui/inspector_state.h"

#include <gtest/gtest.h>

#include <set>

namespace pvs {
namespace {

// Root-to-leaf walk by the planes: distance > 0 front, < 0 back, == 0 by the tree's tie rule.
std::vector<PathStep> walk(const BspTree& tree, const glm::vec3& p)
{
    std::vector<PathStep> path;
    int32_t child = tree.root;
    while (!BspTree::is_leaf(child)) {
        const BspNode& n = tree.nodes[size_t(child)];
        const float d = glm::dot(n.normal, p) - n.dist;
        const bool front = d > 0.0f || (d == 0.0f && tree.tie_rule == TieRule::OnPlaneGoesFront);
        path.push_back({uint32_t(child), uint8_t(front ? 0 : 1)});
        child = n.children[front ? 0 : 1];
    }
    return path;
}

struct DemoBsp : ::testing::Test {
    void SetUp() override
    {
        state.set_viewport_size(96, 64);
        state.open_demo();
    }
    gui::InspectorState state;
};

TEST_F(DemoBsp, CameraPathIsTheWalkDownTheTree)
{
    const Zone& zone = state.zone();
    for (uint32_t r : {0u, uint32_t(zone.region_count() / 2), uint32_t(zone.region_count() - 1)}) {
        state.go_to_region(r);
        state.frame();
        const std::vector<PathStep> expected = walk(zone.tree, state.cull_camera().position);
        const std::vector<PathStep>& path = state.camera_path();
        ASSERT_EQ(path.size(), expected.size());
        for (size_t i = 0; i < path.size(); ++i) {
            EXPECT_EQ(path[i].node, expected[i].node);
            EXPECT_EQ(path[i].side, expected[i].side);
        }
        ASSERT_FALSE(path.empty());
        const BspNode& last = zone.tree.nodes[path.back().node];
        const int32_t leaf = BspTree::leaf_index(last.children[path.back().side]);
        EXPECT_EQ(zone.tree.leaf_region[size_t(leaf)], int32_t(r));
    }
}

TEST_F(DemoBsp, PathPlanePolygonsLieOnTheirPlaneInsideTheirCell)
{
    state.go_to_region(uint32_t(state.zone().region_count() / 3));
    state.frame();
    const BspTree& tree = state.zone().tree;
    const std::vector<Winding>& polygons = state.node_polygons();
    ASSERT_EQ(polygons.size(), tree.nodes.size());
    const std::vector<PathStep>& path = state.camera_path();
    for (size_t depth = 0; depth < path.size(); ++depth) {
        const BspNode& node = tree.nodes[path[depth].node];
        const Winding& w = polygons[path[depth].node];
        ASSERT_FALSE(w.empty()) << "node " << path[depth].node;
        for (const glm::vec3& p : w.points) {
            EXPECT_NEAR(glm::dot(node.normal, p) - node.dist, 0.0f, 0.05f);
            // Inside every ancestor's half-space on the side the path took.
            for (size_t up = 0; up < depth; ++up) {
                const BspNode& a = tree.nodes[path[up].node];
                const float d = glm::dot(a.normal, p) - a.dist;
                if (path[up].side == 0)
                    EXPECT_GE(d, -0.05f);
                else
                    EXPECT_LE(d, 0.05f);
            }
        }
    }
}

TEST_F(DemoBsp, RegionsUnderANode)
{
    const BspTree& tree = state.zone().tree;
    std::set<uint32_t> all;
    for (int32_t region : tree.leaf_region)
        if (region >= 0)
            all.insert(uint32_t(region));
    const std::vector<uint32_t> under_root = state.regions_under(tree.root);
    EXPECT_EQ(std::set<uint32_t>(under_root.begin(), under_root.end()), all);
    EXPECT_TRUE(std::is_sorted(under_root.begin(), under_root.end()));
    // The camera's deepest node has the camera's region under it; its two children split it.
    state.frame();
    const PathStep deepest = state.camera_path().back();
    const std::vector<uint32_t> under = state.regions_under(int32_t(deepest.node));
    EXPECT_TRUE(std::binary_search(under.begin(), under.end(), uint32_t(state.last_cull().region)));
    size_t children = 0;
    for (int32_t child : tree.nodes[deepest.node].children)
        children += state.regions_under(child).size();
    EXPECT_GE(children, under.size());
    EXPECT_TRUE(state.regions_under(-1000000).empty()); // leaf 999999: out of range
    EXPECT_TRUE(state.regions_under(int32_t(tree.nodes.size()) + 5).empty());
}

TEST_F(DemoBsp, SelectedNodeIsTheHighlightedPlane)
{
    state.overlays = {};
    state.overlays.zone_lines = false;
    state.frame();
    const ui::Image plain = state.image();
    state.overlays.split_planes = true;
    state.selected_node = int32_t(state.camera_path().front().node);
    state.frame();
    size_t highlighted = 0;
    for (size_t i = 0; i < plain.rgba.size(); i += 4)
        highlighted += state.image().rgba[i] != plain.rgba[i] ? 1 : 0;
    EXPECT_GT(highlighted, 0u);
}

} // namespace
} // namespace pvs
