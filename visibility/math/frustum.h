// A view frustum as six inward-facing planes, extracted from a view-projection matrix
// (Gribb & Hartmann, "Fast Extraction of Viewing Frustum Planes from the World-View-Projection
// Matrix", 2001). Works for OpenGL-style clip space (-w <= z <= w) as produced by
// glm::perspective; points with distance >= 0 to every plane are inside.
#pragma once

#include "visibility/math/aabb.h"
#include "visibility/math/plane.h"

#include <array>
#include <glm/mat4x4.hpp>

namespace pvs {

struct Frustum {
    // Order: left, right, bottom, top, near, far. Normals point into the frustum and are unit length.
    std::array<Plane, 6> planes;

    static Frustum from_view_projection(const glm::mat4& view_projection);

    // Conservative box test: false only when the box lies entirely outside one plane
    // (the "positive vertex" test). A box that straddles a corner may be reported visible.
    bool intersects(const Aabb& box) const
    {
        for (const Plane& plane : planes)
            if (entirely_behind(plane, box))
                return false;
        return true;
    }
    // The same test against the four side planes only. They meet at the eye, so together they
    // already reject everything behind it; leaving out the near plane keeps at most the boxes
    // lying wholly in the thin slab between the eye and the near plane (conservative), and
    // leaving out the far plane is exact when nothing lies farther than it. A third fewer plane
    // tests for every box that is kept.
    bool intersects_sides(const Aabb& box) const
    {
        for (size_t i = 0; i < 4; ++i)
            if (entirely_behind(planes[i], box))
                return false;
        return true;
    }
    // The box's "positive vertex" (the corner farthest along the normal) is behind the plane.
    static bool entirely_behind(const Plane& plane, const Aabb& box)
    {
        const glm::vec3 positive{plane.normal.x >= 0.0f ? box.max.x : box.min.x,
                                 plane.normal.y >= 0.0f ? box.max.y : box.min.y,
                                 plane.normal.z >= 0.0f ? box.max.z : box.min.z};
        return plane.distance(positive) < 0.0f;
    }
    bool contains(const glm::vec3& p) const
    {
        for (const Plane& plane : planes)
            if (plane.distance(p) < 0.0f)
                return false;
        return true;
    }
};

} // namespace pvs
