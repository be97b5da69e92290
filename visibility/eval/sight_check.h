// Is the face a pixel shows really visible from the eye? The test behind "confirmed popping"
// (ui/accuracy_walk.h, pvscope walk and compare), decided by the geometry that bounds space,
// not by the triangles a rasteriser or a ray-triangle test can slip between.
//
// For the ray eye + t * direction through a pixel that shows `face`, the hit point is where
// the ray meets the face's plane (its first triangle with an area, in double). The segment from
// the eye to just before that point is traced through the zone's BSP tree (tree_trace.h, the
// content rule of media.h): it is Open when it stays in open leaves, Blocked when a solid,
// outside or opaque leaf cuts it first. A pixel of a face seen through a crack between two
// triangles of a wall (a T-junction gap, a "sparkle") is Blocked: the wall's leaf is solid
// whatever its triangles do. The segment stops short of the hit point by kSightBackoff units
// measured off the face's plane (at most kSightBackoffMax along the ray), because a face lies
// on its leaf's boundary only to within its file's vertex noise (Quake: 0.1 units).
//
// An Open segment that ends in a region not listing the face (the backoff stopped it short of a
// boundary it crosses just before the face, near the face's edge) is traced on to the face's
// plane: Unfaced if the content rule closes that boundary, more than kUnfacedMargin off the face's
// plane (nearer, it may be the face's own), and no face does; else it ends in the region there
// when that region lists the face.
//
// Grazing: the segment is open, but not as a beam (TreeTracer::open_beam: one of four
// companions, moved by kSightMargin across the ray, is blocked): the line passes within kSightMargin of a wall's edge
// or corner (or touches it exactly, where the tree walk sends it round the corner). Such a line
// is a real but hair-thin sight line, the kind portal vis drops by its epsilons (ON_EPSILON =
// 0.1) and a raster shows as a lone pixel at a wall edge; it is counted apart, not confirmed.
//
// Zones without a tree (OBJ levels) are checked against the mesh instead (mesh_tracer.h, Embree
// in robust mode): the pixel's ray is Open when the first face it meets is the pixel's face, seen
// from the front, and Blocked when another face is in front of it (the raster showed a face
// through a crack); end_region is then the region (object) listing the face. No Grazing there.
//
// Unfaced: Blocked, but by the content rule, not by a wall: the segment reaches a region its
// medium does not see into (media.h; Quake 2: translucent slime against plain slime, air against
// plain water) where the ray crosses no face of either region (none within kUnfacedMargin of the
// crossing along the ray, inside a triangle; the face the pixel shows does not count: a wall met
// just past the crossing is no cover for it). Light would cross there and so does the raster, but
// the game's vis counts the boundary opaque and the engine draws a hole; the line is
// not one any PVS of that rule owes, and not a crack either. A crack in a face that does close such
// a boundary (a sky or liquid surface) stays Blocked.
//
// Unknown: the zone has neither tree nor mesh, the ray does not meet the face's plane in front of the eye
// (a face seen edge-on, or a pixel centre just off its face), or the face has no area. Callers
// count Unknown with the cracks: it is never confirmed.
//
// Open gives end_region: the region the segment ends in, the one the face belongs to there,
// which a PVS row of the eye's region must hold. Thread-safe (const); each thread passes its
// own scratch. Borrows the zone, which must outlive the check.
#pragma once

#include "visibility/portal/media.h"
#include "visibility/reference/mesh_tracer.h"
#include "visibility/reference/tree_trace.h"
#include "visibility/zone.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

namespace pvs {

inline constexpr double kSightBackoff = 0.2;
inline constexpr double kSightBackoffMax = 2.0;
inline constexpr double kSightMargin = kBeamMargin; // the reference's margin (tree_trace.h)
// How near a face must come to a content-rule crossing to close it (zone units): Quake's vertex
// noise, so a T-junction gap in a closing face (zero wide in exact geometry) is still a crack.
inline constexpr double kUnfacedMargin = 0.1;

enum class Sight : uint8_t { Open, Blocked, Grazing, Unfaced, Unknown };

struct SightResult {
    Sight sight = Sight::Unknown;
    int32_t end_region = -1; // Open: the region the segment ends in
    double hit_distance = 0; // along the (unit) ray to the face's plane; 0 when Unknown
};

class SightCheck {
public:
    explicit SightCheck(const Zone& zone, SkyPortals sky = SkyPortals::SkyToSky);

    SightCheck(const SightCheck&) = delete;
    SightCheck& operator=(const SightCheck&) = delete;
    ~SightCheck();

    bool has_tree() const { return tracer_.has_tree(); }
    // `direction` must be unit length.
    SightResult face_along_ray(const glm::dvec3& eye, const glm::dvec3& direction, uint32_t face,
                               TreeTracer::Scratch& scratch) const;

private:
    struct FacePlane {
        glm::dvec3 normal{0.0};
        double dist = 0.0;
        bool valid = false;
    };
    SightResult face_along_mesh_ray(const glm::dvec3& eye, const glm::dvec3& direction, uint32_t face) const;
    // Whether the ray crosses, within kUnfacedMargin of t, a triangle of a face either region
    // lists, other than the face the pixel shows. (The face seen is never what closes the boundary
    // in front of it: the line stops short of it, so a wall just past the crossing must not count.)
    bool face_closes(const glm::dvec3& eye, const glm::dvec3& direction, double t, int32_t region_a, int32_t region_b,
                     uint32_t seen_face) const;
    bool region_lists(int32_t region, uint32_t face) const;
    void follow_to_the_face(const glm::dvec3& eye, const glm::dvec3& direction, double t_hit, double cos_incidence,
                            uint32_t face, TreeTracer::Scratch& scratch, SightResult& result) const;
    bool ray_crosses_triangle(uint32_t triangle, const glm::dvec3& eye, const glm::dvec3& direction, double t) const;

    const Zone* zone_;
    TreeTracer tracer_;
    std::vector<FacePlane> planes_;
    std::unique_ptr<MeshTracer> mesh_;    // zones without a tree
    std::vector<int32_t> face_region_;    // mesh_: the first region listing each face, or -1
};

} // namespace pvs
