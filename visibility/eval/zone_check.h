// A zone's health report (`pvscope check`): the invariants every stage after loading relies on,
// checked on the zone model, so a fault of any loader or file shows up the same way.
//
// Checks, each a CheckItem with a severity and a count of what failed (0: passed):
//   tree            (error)   the root and every child in range, no node reached twice from the
//                             root (a cycle or a shared subtree), planes finite with a unit
//                             normal (1e-3), leaf regions valid ids or solid / outside (nodes the
//                             root does not reach, a Quake map's other models, are only counted);
//   tree_regions    (warning) regions that no leaf reached from the root names: no camera can
//                             be in them;
//   portal_crossings (error)  the crossing invariant (portal_crossings.h) over the portals built
//                             from the tree (portalize.h) and, when the zone has its own (a .prt),
//                             over those too: blocked crossings, with their positions;
//   leaks           (warning) open leaves whose cell reaches the world box (portalize.h: a Quake
//                             map that leaks, a tree that does not close its open space);
//   outside         (note)    open leaves sharing a face with an outside leaf (normal in
//                             EverQuest trees, whose region-less leaves are the outside);
//   faces           (note)    regions that list no face (Doom's two-seg slivers, Quake leaves
//                             without marksurfaces): drawn as nothing;
//   pvs_rows        (error)   the baked PVS has one row per region (per cell for a grid zone) of
//                             region_count bits;
//   pvs_self        (warning) rows that do not hold their own region;
//   pvs_neighbours  (warning) directed pairs of regions that share a portal (built from the
//                             tree) but whose row lacks the other: a camera crossing that
//                             boundary would see the region pop in;
//   pvs_sky_neighbours (note) the same at a sky region (vis tools differ on sky: id's vis saw
//                             nothing through it; check with SkyPortals::None for such maps);
//   pvs_symmetry    (note)    directed pairs a sees b whose reverse is not set (portal vis's
//                             flow is not symmetric; glVIS and Quake's vis leave such pairs).
// Zones without a tree (OBJ grids) get the face and PVS row checks only; the others are
// reported as not applicable. The verdict: errors() > 0 is an unhealthy zone.
// Cost: one portalization and a few traces per portal; the PVS checks decode each row once
// (the symmetry check keeps the decoded matrix, so it is skipped above kSymmetryMaxRegions).
#pragma once

#include "visibility/eval/portal_crossings.h"
#include "visibility/portal/media.h"
#include "visibility/zone.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pvs {

enum class CheckSeverity : uint8_t { Note, Warning, Error };
const char* check_severity_name(CheckSeverity severity); // "note", "warning", "error"

// Where an example failure is, for a viewer to go to: a region (-1: none), the other region of a
// pair (-1: none), and a point when the failure has one (a blocked portal crossing).
struct CheckPlace {
    int32_t region = -1;
    int32_t other = -1;
    bool has_point = false;
    glm::vec3 point{0.0f};
};

struct CheckItem {
    std::string name;        // "tree", "portal_crossings", ...
    CheckSeverity severity = CheckSeverity::Note; // what a failure of this check is
    bool applicable = true;  // false: the zone has nothing to check here (no tree, no PVS)
    size_t checked = 0;      // how many things were checked (nodes, portals, rows, pairs)
    size_t failed = 0;       // how many failed (0: the check passed)
    std::string summary;     // one line for people
    std::vector<std::string> examples; // the first few failures, for people
    std::vector<CheckPlace> places;    // where each example is (one per example)

    bool passed() const { return failed == 0; }
};

struct ZoneHealth {
    std::vector<CheckItem> items;
    CrossingReport tree_crossings; // over the portals built from the tree
    CrossingReport file_crossings; // over the zone's own portals (empty set when it has none)
    std::vector<int32_t> leak_regions; // regions of the open leaves that touch the world box

    size_t count(CheckSeverity severity) const; // failed items of that severity
    size_t errors() const { return count(CheckSeverity::Error); }
    size_t warnings() const { return count(CheckSeverity::Warning); }
    const CheckItem* item(const std::string& name) const;
};

struct CheckOptions {
    SkyPortals sky = SkyPortals::SkyToSky;
    double crossing_half_length = kCrossingHalfLength;
    size_t max_examples = 10;
};

inline constexpr uint32_t kSymmetryMaxRegions = 40000;

ZoneHealth check_zone(const Zone& zone, const CheckOptions& options = {});

} // namespace pvs
