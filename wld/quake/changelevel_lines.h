// Quake-family trigger_changelevel entities as zone lines (Quake BSP 29 / BSP2, Quake 2 IBSP 38):
// each names its brush model ("model" "*N") and the next map ("map"); its volume is the model's
// box moved by its "origin", grown by one unit per side (compilers store model bounds shrunk by
// one), and marks every region it touches with kRegionZoneLine, found as the engines link an
// entity: a box walk down the tree, taking both sides where the box straddles a plane.
// Adds the count "trigger_changelevel" and a note for each trigger without a valid model.
#pragma once

#include "visibility/zone.h"
#include "wld/quake/entities.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>

namespace pvs::quake {

struct ModelBox {
    glm::vec3 mins, maxs;
};

// `model_box(n)`: brush model n's bounds as the file stores them, or nothing when the file has
// no model n (n >= 1; model 0 is the world).
void add_changelevel_zone_lines(std::span<const Entity> entities,
                                const std::function<std::optional<ModelBox>(int32_t)>& model_box, Zone& zone);

// Leaves (indices) whose volume `box` touches, appended to `out`.
void leaves_touching_box(const BspTree& tree, const Aabb& box, std::vector<int32_t>& out);

} // namespace pvs::quake
