// Crafted zones that each sit on one way a visibility method can fail:
// `pvscope gen --case NAME`, `pvscope stability --cases`, the inspector's Stability panel.
//
// Each case is a handful of named boxes of open space (rooms, doorways, cracks, steps) in solid
// rock, on an uneven grid (grid_axes.h) so that a wall 0.1 units thick or a crack 0.01 wide is
// exact, and built into a zone as the procedural zones are (grid_zone.h). Every box becomes
// exactly one region (checked when the case is made), so the region names are the box names.
//
// The truth is known by construction, in two halves:
//  - visible: the case's sight lines are drawn through the layout by hand (through the middle of
//    each doorway or crack, along each corridor); every pair of regions one line passes through
//    sees each other. Each line is traced through the case's own tree in double when the case is
//    made (tree_trace.h) and must be open end to end;
//  - not visible: every other pair, because the layout puts solid rock on every segment between
//    them or lets them meet only along an edge (a set of measure zero, which no one sees). Each
//    case's comment in stability_cases.cpp says why. The tests check this half independently:
//    the sampled reference (a lower bound) must find no pair outside the truth.
// So a conservative method must hold every bit of `truth` (missing bits = failures) and a lower
// bound may hold none outside it (excess bits of a lower bound = a broken instrument).
//
// Library code: throws std::invalid_argument for an unknown name; a case whose layout breaks the
// rules above is a bug and throws std::logic_error naming the case.
#pragma once

#include "visibility/camera.h"
#include "visibility/pvs.h"
#include "visibility/zone.h"

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pvs::gen {

struct StabilityCase {
    std::string name;
    std::string failure;                    // the failure mode it sits on, one line for a user
    Zone zone;                              // source.path "case:NAME"; no PVS
    std::vector<std::string> region_names;  // region -> the box it is
    std::vector<std::pair<glm::vec3, glm::vec3>> sight_lines; // the truth's visible half
    Pvs truth;                              // symmetric, every region sees itself
    Camera camera;                          // where to look: at the failure, from the first room
};

// The names, in the order tables list them.
std::span<const std::string_view> stability_case_names();
StabilityCase make_stability_case(std::string_view name);

} // namespace pvs::gen
