// The BSP panel: the zone's tree as a nested tree, the culling camera's path from the root opened
// (again each time the path changes; the user may close it) and coloured, the camera's leaf
// scrolled into view; then the selected node: its plane, depth, parent and children (click to
// move there), and the regions under it (click to go there). Clicking a node's label selects it
// and makes its plane the highlighted one of the split-plane overlay; clicking a leaf selects
// its region. Trees are deep (30-60 levels): the indent per level is a few pixels, so the path
// stays on the panel, and only open nodes are visited (ImGui draws nothing inside closed ones).
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

constexpr ImU32 kPathColor = IM_COL32(255, 224, 64, 255);
constexpr int kMaxTreeDepth = 1024; // a hostile tree with a cycle still ends

// Opens the camera's path when it changed since the tree last opened it.
bool update_open_path(const InspectorState& state, BspPanel& panel)
{
    const std::vector<PathStep>& path = state.camera_path();
    const size_t node_count = state.zone().tree.nodes.size();
    bool same = panel.open_path.size() == path.size() && panel.on_path.size() == node_count;
    for (size_t i = 0; same && i < path.size(); ++i)
        same = panel.open_path[i] == path[i].node;
    if (same)
        return false;
    panel.open_path.clear();
    panel.on_path.assign(node_count, 0);
    for (const PathStep& step : path) {
        panel.open_path.push_back(step.node);
        if (step.node < node_count)
            panel.on_path[step.node] = 1;
    }
    return true;
}

void draw_leaf(InspectorState& state, const BspTree& tree, int32_t child, const char* side, bool camera_leaf,
               bool scroll_here)
{
    const int32_t leaf = BspTree::leaf_index(child);
    const int32_t region = size_t(leaf) < tree.leaf_region.size() ? tree.leaf_region[size_t(leaf)] : kLeafSolid;
    const std::string label = std::string(side) + child_label(tree, child) + "##leaf" + std::to_string(leaf);
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
    if (region >= 0 && region == state.selection().region)
        flags |= ImGuiTreeNodeFlags_Selected;
    if (camera_leaf)
        ImGui::PushStyleColor(ImGuiCol_Text, kPathColor);
    ImGui::TreeNodeEx(label.c_str(), flags);
    if (camera_leaf)
        ImGui::PopStyleColor();
    if (ImGui::IsItemClicked() && region >= 0)
        state.select_region(region);
    if (scroll_here) { // the camera's leaf in view, with some of the path to its left
        ImGui::SetScrollHereY(0.5f);
        ImGui::SetScrollHereX(0.25f);
    }
}

void draw_subtree(InspectorState& state, BspPanel& panel, int32_t node, const char* side, int depth, bool open_path)
{
    const BspTree& tree = state.zone().tree;
    if (size_t(node) >= tree.nodes.size() || depth > kMaxTreeDepth)
        return;
    const bool on_path = panel.on_path[size_t(node)] != 0;
    if (open_path && on_path)
        ImGui::SetNextItemOpen(true, ImGuiCond_Always);
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_OpenOnDoubleClick;
    if (state.selected_node == node)
        flags |= ImGuiTreeNodeFlags_Selected;
    const std::string label = std::string(side) + "node " + std::to_string(node) + "##n" + std::to_string(node);
    if (on_path)
        ImGui::PushStyleColor(ImGuiCol_Text, kPathColor);
    const bool open = ImGui::TreeNodeEx(label.c_str(), flags);
    if (on_path)
        ImGui::PopStyleColor();
    panel.drawn_nodes.push_back(node);
    if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen())
        state.selected_node = state.selected_node == node ? -1 : node;
    if (!open)
        return;
    const std::vector<PathStep>& path = state.camera_path();
    const bool last_on_path = on_path && !path.empty() && int32_t(path.back().node) == node;
    for (int s = 0; s < 2; ++s) {
        const int32_t child = tree.nodes[size_t(node)].children[s];
        const char* child_side = s == 0 ? "front: " : "back: ";
        if (BspTree::is_leaf(child))
            draw_leaf(state, tree, child, child_side, last_on_path && path.back().side == s, open_path && last_on_path);
        else
            draw_subtree(state, panel, child, child_side, depth + 1, open_path);
    }
    ImGui::TreePop();
}

void draw_tree(InspectorState& state, BspPanel& panel, float height)
{
    const std::vector<PathStep>& path = state.camera_path();
    ImGui::Text("camera path: %zu nodes, leaf region %d", path.size(), state.last_cull().region);
    const bool open_path = update_open_path(state, panel);
    panel.drawn_nodes.clear();
    if (!ImGui::BeginChild("tree", {0.0f, height}, true, ImGuiWindowFlags_HorizontalScrollbar)) {
        ImGui::EndChild();
        return;
    }
    ImGui::PushStyleVar(ImGuiStyleVar_IndentSpacing, 5.0f);
    const BspTree& tree = state.zone().tree;
    if (tree.root >= 0 && size_t(tree.root) < tree.nodes.size())
        draw_subtree(state, panel, tree.root, "root: ", 0, open_path);
    else
        ImGui::TextDisabled("the zone has no tree");
    ImGui::PopStyleVar();
    ImGui::EndChild();
}

void draw_selected(InspectorState& state, BspPanel& panel)
{
    const BspTree& tree = state.zone().tree;
    const int32_t node = state.selected_node;
    if (node < 0 || size_t(node) >= tree.nodes.size()) {
        ImGui::TextDisabled("click a node in the tree to see its plane and regions");
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
        draw_tree(state, panel, std::max(80.0f, ImGui::GetContentRegionAvail().y * 0.5f));
        draw_selected(state, panel);
    }
    ImGui::End();
}

} // namespace pvs::gui
