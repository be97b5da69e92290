#include "visibility/math/frustum.h"

#include <glm/geometric.hpp>

namespace pvs {

namespace {
// Row i of a column-major glm matrix.
glm::vec4 row(const glm::mat4& m, int i) { return {m[0][i], m[1][i], m[2][i], m[3][i]}; }

Plane normalized_plane(const glm::vec4& c)
{
    // c is (a, b, c, d) with a·x + b·y + c·z + d >= 0 inside; our form is dot(n, p) - dist.
    const glm::vec3 n{c.x, c.y, c.z};
    const float length = glm::length(n);
    return {n / length, -c.w / length};
}
} // namespace

Frustum Frustum::from_view_projection(const glm::mat4& m)
{
    const glm::vec4 r0 = row(m, 0), r1 = row(m, 1), r2 = row(m, 2), r3 = row(m, 3);
    Frustum f;
    f.planes[0] = normalized_plane(r3 + r0); // left
    f.planes[1] = normalized_plane(r3 - r0); // right
    f.planes[2] = normalized_plane(r3 + r1); // bottom
    f.planes[3] = normalized_plane(r3 - r1); // top
    f.planes[4] = normalized_plane(r3 + r2); // near
    f.planes[5] = normalized_plane(r3 - r2); // far
    return f;
}

} // namespace pvs
