#include "visibility/bsp_tree_edit.h"

#include <stdexcept>

namespace pvs {

namespace {

bool is_solid(const BspTree& tree, int32_t child)
{
    return BspTree::is_leaf(child) && tree.leaf_region[size_t(BspTree::leaf_index(child))] == kLeafSolid;
}

// Follows height nodes from `child` to the first child that is not one.
int32_t past_height_nodes(const BspTree& tree, int32_t child)
{
    for (size_t steps = 0; !BspTree::is_leaf(child) && uint32_t(child) >= tree.first_height_node; ++steps) {
        if (steps > tree.nodes.size())
            throw std::invalid_argument("height nodes form a cycle");
        const BspNode& node = tree.nodes[size_t(child)];
        if (is_solid(tree, node.children[1]))
            child = node.children[0];
        else if (is_solid(tree, node.children[0]))
            child = node.children[1];
        else
            throw std::invalid_argument("height node " + std::to_string(child) + " has no solid child");
    }
    return child;
}

} // namespace

BspTree without_height_nodes(const BspTree& tree)
{
    BspTree out = tree;
    if (!tree.has_height_nodes())
        return out;
    out.nodes.resize(tree.first_height_node);
    for (BspNode& node : out.nodes)
        for (int32_t& child : node.children)
            child = past_height_nodes(tree, child);
    out.root = past_height_nodes(tree, tree.root);
    out.first_height_node = UINT32_MAX;
    return out;
}

} // namespace pvs
