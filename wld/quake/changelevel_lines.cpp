#include "wld/quake/changelevel_lines.h"

#include <charconv>
#include <glm/geometric.hpp>
#include <string>
#include <string_view>

namespace pvs::quake {

namespace {

glm::vec3 parse_origin(std::string_view text)
{
    glm::vec3 v{0.0f};
    const char* p = text.data();
    const char* end = p + text.size();
    for (int k = 0; k < 3 && p < end; ++k) {
        while (p < end && *p == ' ')
            ++p;
        auto [next, ec] = std::from_chars(p, end, v[k]);
        if (ec != std::errc())
            return glm::vec3{0.0f};
        p = next;
    }
    return v;
}

} // namespace

void leaves_touching_box(const BspTree& tree, const Aabb& box, std::vector<int32_t>& out)
{
    std::vector<int32_t> stack{tree.root};
    while (!stack.empty()) {
        const int32_t child = stack.back();
        stack.pop_back();
        if (BspTree::is_leaf(child)) {
            out.push_back(BspTree::leaf_index(child));
            continue;
        }
        const BspNode& node = tree.nodes[child];
        const glm::vec3 center = box.center(), half = box.size() * 0.5f;
        const float d = glm::dot(node.normal, center) - node.dist;
        const float r = glm::dot(glm::abs(node.normal), half);
        if (d + r > 0.0f)
            stack.push_back(node.children[0]);
        if (d - r <= 0.0f)
            stack.push_back(node.children[1]);
    }
}

void add_changelevel_zone_lines(std::span<const Entity> entities,
                                const std::function<std::optional<ModelBox>(int32_t)>& model_box, Zone& zone)
{
    uint64_t changelevels = 0;
    std::vector<int32_t> leaves;
    for (const Entity& e : entities) {
        if (e.get("classname") != "trigger_changelevel")
            continue;
        ++changelevels;
        const auto model = e.get("model");
        int32_t index = -1;
        if (model && model->size() > 1 && (*model)[0] == '*')
            std::from_chars(model->data() + 1, model->data() + model->size(), index);
        const std::optional<ModelBox> box = index >= 1 ? model_box(index) : std::nullopt;
        if (!box) {
            zone.source.notes.push_back("trigger_changelevel at entity offset " + std::to_string(e.offset) +
                                        " has no valid brush model; ignored");
            continue;
        }
        const glm::vec3 origin = parse_origin(e.get("origin").value_or(""));
        ZoneLine line;
        line.target = std::string(e.get("map").value_or(""));
        line.bounds.grow(origin + box->mins - 1.0f);
        line.bounds.grow(origin + box->maxs + 1.0f);
        const auto line_index = static_cast<int32_t>(zone.zone_lines.size());
        zone.zone_lines.push_back(line);
        leaves.clear();
        leaves_touching_box(zone.tree, line.bounds, leaves);
        for (int32_t leaf : leaves) {
            const int32_t region = zone.tree.leaf_region[size_t(leaf)];
            if (region < 0)
                continue;
            zone.regions[size_t(region)].flags |= kRegionZoneLine;
            zone.regions[size_t(region)].zone_line = line_index;
        }
    }
    zone.source.counts.emplace_back("trigger_changelevel", changelevels);
}

} // namespace pvs::quake
