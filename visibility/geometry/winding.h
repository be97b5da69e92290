// A winding: a convex planar polygon, the unit of every clip in BSP and portal work (Quake
// faces into EverQuest region meshes, BSP split planes in the inspector, portalization).
// After id's and ericw-tools' polylib (qbsp winding_t, vis ClipStackWinding), with the
// conventions of this project:
//  - points are counter-clockwise seen from the front: normal() follows the right-hand rule,
//    as for Mesh triangles (id's windings are clockwise; ours are not);
//  - planes are Plane (dot(normal, p) == dist), normals expected unit length so distances and
//    epsilons are in the zone's units;
//  - all side tests and interpolations are computed in double and stored as float.
//
// Epsilon semantics (one rule for clip and split, as ericw's ON_EPSILON; see
// ../shared/formats/quake-doom-hepvs.md §3.3 "Clipping"). For a point p let d = plane.distance(p):
//     d >  +epsilon   FRONT
//     d <  -epsilon   BACK
//     otherwise       ON      (also when d is NaN)
//  - ON points are kept as they are (never moved onto the plane); FRONT/BACK sign changes get
//    a new point interpolated at d == 0. For an axial plane (a normal component exactly ±1) the
//    new point's coordinate on that axis is snapped to exactly ±dist.
//  - clip() keeps the front part: no BACK point -> the input unchanged (a polygon lying on the
//    plane, all ON, is kept, as ericw vis does since its fix for issue #261); no FRONT point but
//    some BACK -> empty (a polygon touching the plane from behind is gone). So every kept point
//    has d >= -epsilon.
//  - split() is the two clips in one pass: ON points go to both parts, so the areas of the parts
//    add up to the input's. A polygon with no BACK point is all front, one with no FRONT point
//    all back; an all-ON polygon goes to the side its own normal faces (front when
//    dot(normal(), plane.normal) >= 0).
//  - A negative or NaN epsilon counts as 0. A plane with a non-finite normal or dist carries no
//    side information: clip returns the input unchanged and split puts it all in front.
//    A point with NaN coordinates classifies ON and is kept: garbage in, garbage out, no crash.
//
// Allocation: a clip allocates at most once (the exact output size is counted first); clip_into
// and clip_in_place reuse the caller's storage, so a loop of clips ping-ponging two windings
// stops allocating once their capacity is reached. Windings are short (tens of points), so the
// passes are plain loops.
#pragma once

#include "visibility/math/aabb.h"
#include "visibility/math/plane.h"

#include <cstddef>
#include <glm/vec3.hpp>
#include <initializer_list>
#include <utility>
#include <vector>

namespace pvs {

// ericw-tools VIS_ON_EPSILON / qbsp ON_EPSILON: the classic side tolerance for Quake-scale units.
inline constexpr float kWindingOnEpsilon = 0.1f;

struct WindingSplit;

struct Winding {
    std::vector<glm::vec3> points;

    Winding() = default;
    explicit Winding(std::vector<glm::vec3> pts) : points(std::move(pts)) {}
    Winding(std::initializer_list<glm::vec3> pts) : points(pts) {}

    size_t size() const { return points.size(); }
    // Fewer than three points is no polygon: every operation treats it as empty.
    bool empty() const { return points.size() < 3; }
    const glm::vec3& operator[](size_t i) const { return points[i]; }
    glm::vec3& operator[](size_t i) { return points[i]; }

    // The part on the front side of `plane` (see the epsilon rules above). Empty result = no points.
    Winding clip(const Plane& plane, float epsilon) const;
    // The same, written into `out` (which must not be *this), reusing its capacity.
    void clip_into(const Plane& plane, float epsilon, Winding& out) const;
    // The same, in place; `scratch` is storage to swap with. Returns !empty() afterwards.
    bool clip_in_place(const Plane& plane, float epsilon, Winding& scratch);
    // Front and back parts in one pass (see above).
    WindingSplit split(const Plane& plane, float epsilon) const;

    // Area, in squared units; 0 for an empty winding. Computed in double.
    float area() const;
    // Area-weighted centroid; the mean of the points when the area is 0; (0,0,0) when there are none.
    glm::vec3 centroid() const;
    // Unit normal from the points (Newell's method, counter-clockwise = front); (0,0,0) for a
    // winding with no area.
    glm::vec3 normal() const;
    // The plane through the points: {normal(), dot(normal(), centroid())}; normal (0,0,0) and
    // dist 0 when the winding has no area.
    Plane plane() const;
    Aabb bounds() const;
    // The same polygon seen from the other side (points in reverse order).
    Winding reversed() const;

    // Removes points closer than `epsilon` to the previous point (cyclically), then points whose
    // distance to the line through their neighbours is at most `epsilon` (colinear), repeating
    // until none is left to remove. A winding left with fewer than three points is cleared.
    // Returns the number of points removed.
    size_t remove_degenerate_points(float epsilon);
};

struct WindingSplit {
    Winding front;
    Winding back;
};

// A square of side 2 * half_size lying on `plane`, counter-clockwise seen from the plane's front
// (so its normal() is plane.normal), centred on the point of the plane closest to `center`
// (ericw's BaseWindingForPlane, re-centred so a modest half_size covers a box away from the
// origin: to cover a box, pass its centre and at least half its diagonal). The normal is
// normalised first. Empty for a zero, non-finite or NaN plane, or a non-positive half_size.
Winding base_winding_for_plane(const Plane& plane, float half_size, const glm::vec3& center = glm::vec3(0.0f));

} // namespace pvs
