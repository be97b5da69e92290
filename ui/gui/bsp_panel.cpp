// The BSP panel: a browser of the zone's tree by navigation rather than nesting (trees are deep:
// a nested ImGui tree would indent off the panel): the culling camera's path from the root, one
// line per node with its depth and the side taken, then the selected node: its plane, depth,
// parent and children (click to move there), and the regions under it (click to go there).
// Selecting a node makes its plane the highlighted one of the split-plane overlay.
#include "ui/gui/panels.h"

#include <algorithm>
#include <string>
#include <vector>

namespace pvs::gui {

namespace {

void update_parents(const InspectorState& state, BspPanel& panel)
{
    if (panel.parents_zone == state.zone_generation())
        return;
    panel.parents_zone = state.zone_generation();
    const BspTree& tree = state.zone().tree;
    panel.parents.assign(tree.nodes.size(), -1);
    panel.depths.assign(tree.nodes.size(), -1);
    if (tree.root < 0 || size_t(tree.root) >= tree.nodes.size())
        return;
    std::vector<int32_t> stack{tree.root};
    panel.depths[size_t(tree.root)] = 0;
    while (!stack.empty()) {
        const int32_t node = stack.back();
        stack.pop_back();
        for (int32_t child : tree.nodes[size_t(node)].children)
            if (!BspTree::is_leaf(child) && size_t(child) < tree.nodes.size() && panel.depths[size_t(child)] < 0) {
                panel.parents[size_t(child)] = node;
                panel.depths[size_t(child)] = panel.depths[size_t(node)] + 1;
                stack.push_back(child);
            }
    }
}

std::string child_label(const BspTree& tree, int32_t child)
{
    if (!BspTree::is_leaf(child))
        return "node " + std::to_string(child);
    const int32_t leaf = BspTree::leaf_index(child);
    const int32_t region = size_t(leaf) < tree.leaf_region.size() ? tree.leaf_region[size_t(leaf)] : kLeafSolid;
    if (region >= 0)
        return "leaf " + std::to_string(leaf) + " (region " + std::to_string(region) + ")";
    return "leaf " + std::to_string(leaf) + (region == kLeafOutside ? " (outside)" : " (solid)");
}

void draw_path(InspectorState& state, float height)
{
    const std::vector<PathStep>& path = state.camera_path();
    ImGui::Text("camera path: %zu nodes, leaf region %d", path.size(), state.last_cull().region);
    if (!ImGui::BeginChild("path", {0.0f, height}, true)) {
        ImGui::EndChild();
        return;
    }
    for (size_t depth = 0; depth < path.size(); ++depth) {
        const PathStep& step = path[depth];
        const std::string label = std::to_string(depth) + ": node " + std::to_string(step.node) +
                                  (step.side == 0 ? "  front" : "  back");
        ImGui::Indent(float(std::min<size_t>(depth, 12)) * 6.0f);
        if (ImGui::Selectable(label.c_str(), state.selected_node == int32_t(step.node)))
            state.selected_node = state.selected_node == int32_t(step.node) ? -1 : int32_t(step.node);
        ImGui::Unindent(float(std::min<size_t>(depth, 12)) * 6.0f);
    }
    ImGui::EndChild();
}

void draw_selected(InspectorState& state, BspPanel& panel)
{
    const BspTree& tree = state.zone().tree;
    const int32_t node = state.selected_node;
    if (node < 0 || size_t(node) >= tree.nodes.size()) {
        ImGui::TextDisabled("select a node on the path to see its plane and regions");
        return;
    }
    const BspNode& n = tree.nodes[size_t(node)];
    ImGui::Text("node %d, depth %d", node, panel.depths[size_t(node)]);
    ImGui::Text("plane (%.3f %.3f %.3f) . p = %.1f", double(n.normal.x), double(n.normal.y), double(n.normal.z),
                double(n.dist));
    if (panel.parents[size_t(node)] >= 0) {
        if (ImGui::SmallButton(("parent: node " + std::to_string(panel.parents[size_t(node)])).c_str()))
            state.selected_node = panel.parents[size_t(node)];
    }
    for (int side = 0; side < 2; ++side) {
        const int32_t child = n.children[side];
        const std::string label = std::string(side == 0 ? "front: " : "back: ") + child_label(tree, child);
        if (!BspTree::is_leaf(child) && size_t(child) < tree.nodes.size()) {
            if (ImGui::SmallButton(label.c_str()))
                state.selected_node = child;
        } else {
            ImGui::TextUnformatted(label.c_str());
        }
    }
    if (panel.regions_zone != state.zone_generation() || panel.regions_node != node) {
        panel.regions_zone = state.zone_generation();
        panel.regions_node = node;
        panel.regions = state.regions_under(node);
    }
    ImGui::Text("%zu regions under it", panel.regions.size());
    if (!ImGui::BeginChild("under", {0.0f, 0.0f}, true)) {
        ImGui::EndChild();
        return;
    }
    ImGuiListClipper clipper;
    clipper.Begin(int(panel.regions.size()));
    while (clipper.Step())
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            const uint32_t r = panel.regions[size_t(i)];
            if (ImGui::Selectable(("region " + std::to_string(r) + "##under").c_str(),
                                  int32_t(r) == state.selection().region)) {
                state.select_region(int32_t(r));
                state.go_to_region(r);
            }
        }
    ImGui::EndChild();
}

} // namespace

void draw_bsp_panel(InspectorState& state, BspPanel& panel)
{
    if (!ImGui::Begin("BSP")) {
        ImGui::End();
        return;
    }
    if (state.has_zone()) {
        update_parents(state, panel);
        ImGui::Checkbox("show split planes", &state.overlays.split_planes);
        ImGui::SameLine();
        ImGui::TextDisabled("%zu nodes", state.zone().tree.nodes.size());
        draw_path(state, std::max(60.0f, ImGui::GetContentRegionAvail().y * 0.4f));
        draw_selected(state, panel);
    }
    ImGui::End();
}

} // namespace pvs::gui
