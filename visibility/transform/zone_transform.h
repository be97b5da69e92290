// Transforms of a whole zone that change nothing a player could see: the perturbations of the
// stability suite (`pvscope stability`, visibility/eval/stability.h). Every part of the model
// that holds coordinates moves together — split planes, region bounds, mesh positions, portals,
// zone-line boxes — and region, face and leaf numbering stay the same, so a PVS baked on the
// transformed zone compares with the original row for row.
//
//   translate   by an offset (powers of two: exact wherever the sum fits a float's 24 bits;
//               float precision is what is under test far from the origin)
//   rotate      by quarter turns about +z (x, y) -> (-y, x): exact in float
//   mirror      x -> -x: exact; triangle winding is swapped so faces still face their regions
//   jitter      every vertex, plane distance and portal point moved by a deterministic uniform
//               amount in [-amount, amount] (a robust method should absorb it)
//
// Planes: a rotation or mirror M maps n.p = d to (Mn).(Mp) = d, so normals turn with the points
// and distances stay (front stays front); a translation t adds n.t to the distance (in double,
// rounded once to float). The tie rule is kept.
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pvs {

struct ZoneTransform {
    enum class Kind : uint8_t { Translate, Rotate, Mirror, Jitter };
    Kind kind = Kind::Translate;
    std::string name;         // for tables: "translate 2^12", "rotate 90", "mirror x", "jitter 0.001"
    glm::dvec3 offset{0.0};   // Translate
    int quarter_turns = 0;    // Rotate, 1..3
    double amount = 0.0;      // Jitter
    uint64_t seed = 1;        // Jitter
    bool exact = false;       // the transform is exact in float for coordinates of moderate size
};

Zone transform_zone(const Zone& zone, const ZoneTransform& transform);

// The suite: translations by 2^k (k = 4, 8, 12, 14, 16) along (1, 1, 1), quarter turns of 90,
// 180 and 270 degrees, the mirror, and a jitter of 1e-3 units.
std::vector<ZoneTransform> stability_transforms();

} // namespace pvs
