// Rebuilding convex polygons from an EverQuest 0x36 mesh's triangles. The file stores triangles
// only, but writers (ours included) store each polygon's triangles one after another, and a
// polygon clipped into pieces (a Quake face cut to a region's cell) as pieces side by side.
// Joining such runs back into one zone Face gives the model its faces ("a convex polygon,
// triangulated") and saves most Face records.
//
// ConvexFaceBuilder holds the boundary of the face being built (mesh vertex indices, counter-
// clockwise seen from the side its first triangle's normal points to). try_add(t) joins
// triangle t when
//  - t has an edge that is a boundary edge walked the other way (same winding, shared edge),
//    and its third vertex is not on the boundary yet;
//  - t's normal is within about 0.8 degrees of the face's (positions sit on the file's grid,
//    so a planar polygon's triangles differ slightly), and t is not degenerate;
//  - the grown boundary keeps every corner convex (collinear counts as convex) and at most
//    kMaxCorners corners.
// Otherwise the face is unchanged and try_add returns false. Indices must be valid for the
// positions given to start().
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>

namespace pvs::eq {

using TriangleCorners = std::array<uint16_t, 3>;

class ConvexFaceBuilder {
public:
    static constexpr size_t kMaxCorners = 64;

    // Starts a face with one triangle; false (and an empty face) when it is degenerate.
    bool start(std::span<const glm::vec3> positions, const TriangleCorners& t);
    bool try_add(const TriangleCorners& t);

private:
    bool convex_corner(uint16_t before, uint16_t corner, uint16_t after) const;

    std::span<const glm::vec3> positions_;
    glm::vec3 normal_{0.0f}; // unit normal of the first triangle
    std::array<uint16_t, kMaxCorners> corners_{};
    size_t corner_count_ = 0;
};

} // namespace pvs::eq
