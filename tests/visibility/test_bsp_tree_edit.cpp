// without_height_nodes: the column view of an extruded tree (bsp_tree_edit.h), on a hand-built
// tree of two regions split by x = 0, each with a floor and a ceiling as its loaders write them.
#include "visibility/bsp_tree_edit.h"
#include "visibility/region_lookup.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace {

using namespace pvs;

// Node 0: x = 0 (front x > 0: region 0's floor, back: region 1's floor). Nodes 1-4: floor and
// ceiling of region 0 (z 0..10) and region 1 (z 5..8), each with a solid back (leaf 0).
BspTree extruded_tree()
{
    BspTree t;
    t.leaf_region = {kLeafSolid, 0, 1};
    t.nodes = {
        {glm::vec3(1, 0, 0), 0.0f, {1, 3}},
        {glm::vec3(0, 0, 1), 0.0f, {2, ~0}},   // region 0 floor: above z = 0
        {glm::vec3(0, 0, -1), -10.0f, {~1, ~0}}, // region 0 ceiling: below z = 10
        {glm::vec3(0, 0, 1), 5.0f, {4, ~0}},
        {glm::vec3(0, 0, -1), -8.0f, {~2, ~0}},
    };
    t.root = 0;
    t.first_height_node = 1;
    return t;
}

TEST(BspTreeEdit, ColumnsReachTheRegionsAtAnyHeight)
{
    const BspTree tree = extruded_tree();
    ASSERT_TRUE(tree.has_height_nodes());
    EXPECT_EQ(locate_point(tree, glm::vec3(1, 0, 20)).region, kLeafSolid); // above region 0's ceiling
    EXPECT_EQ(locate_point(tree, glm::vec3(-1, 0, 6)).region, 1);
    const BspTree columns = without_height_nodes(tree);
    EXPECT_FALSE(columns.has_height_nodes());
    EXPECT_EQ(columns.nodes.size(), 1u);
    for (float z : {-100.0f, 0.5f, 9.0f, 100.0f}) {
        EXPECT_EQ(locate_point(columns, glm::vec3(1, 0, z)).region, 0) << z;
        EXPECT_EQ(locate_point(columns, glm::vec3(-1, 0, z)).region, 1) << z;
    }
}

TEST(BspTreeEdit, TreesWithoutHeightNodesAreUnchangedAndBadOnesRefused)
{
    BspTree plain = extruded_tree();
    plain.first_height_node = UINT32_MAX;
    EXPECT_EQ(without_height_nodes(plain).nodes.size(), plain.nodes.size());
    BspTree bad = extruded_tree();
    bad.nodes[1].children[1] = ~1; // a height node with no solid child
    EXPECT_THROW(without_height_nodes(bad), std::invalid_argument);
}

} // namespace
