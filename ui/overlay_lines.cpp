#include "ui/overlay_lines.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>

namespace pvs::ui {

namespace {

// Liang-Barsky: cuts the segment p0-p1 to [0, width] x [0, height]. False when nothing is left.
bool clip_to_rect(double& x0, double& y0, double& x1, double& y1, double width, double height)
{
    double t0 = 0.0, t1 = 1.0;
    const double dx = x1 - x0, dy = y1 - y0;
    // Each boundary as p * t <= q.
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {x0, width - x0, y0, height - y0};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0)
                return false; // parallel to this boundary and outside it
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0.0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1)
            return false;
    }
    const double ox = x0, oy = y0;
    x0 = ox + t0 * dx;
    y0 = oy + t0 * dy;
    x1 = ox + t1 * dx;
    y1 = oy + t1 * dy;
    return true;
}

int32_t pixel_index(double coordinate, uint32_t size)
{
    return int32_t(std::clamp(std::floor(coordinate), 0.0, double(size - 1)));
}

} // namespace

uint32_t draw_line_2d(Image& image, glm::vec2 a, glm::vec2 b, uint32_t rgb)
{
    if (image.width == 0 || image.height == 0 || image.rgba.size() != size_t(image.width) * image.height * 4)
        return 0;
    if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y))
        return 0;
    double x0 = a.x, y0 = a.y, x1 = b.x, y1 = b.y;
    if (!clip_to_rect(x0, y0, x1, y1, double(image.width), double(image.height)))
        return 0;
    // A segment that only touches the right or bottom edge (x == width) holds no pixel.
    if ((x0 >= image.width && x1 >= image.width) || (y0 >= image.height && y1 >= image.height))
        return 0;

    int32_t x = pixel_index(x0, image.width), y = pixel_index(y0, image.height);
    const int32_t xe = pixel_index(x1, image.width), ye = pixel_index(y1, image.height);
    const int32_t dx = std::abs(xe - x), dy = -std::abs(ye - y);
    const int32_t sx = x < xe ? 1 : -1, sy = y < ye ? 1 : -1;
    int32_t error = dx + dy;
    const uint8_t r = uint8_t(rgb >> 16), g = uint8_t(rgb >> 8), bl = uint8_t(rgb);
    uint32_t set = 0;
    for (;;) {
        uint8_t* p = image.rgba.data() + (size_t(uint32_t(y)) * image.width + uint32_t(x)) * 4;
        p[0] = r;
        p[1] = g;
        p[2] = bl;
        p[3] = 255;
        ++set;
        if (x == xe && y == ye)
            break;
        const int32_t e2 = 2 * error;
        if (e2 >= dy) {
            error += dy;
            x += sx;
        }
        if (e2 <= dx) {
            error += dx;
            y += sy;
        }
    }
    return set;
}

LineProjection::LineProjection(const Camera& view)
    : to_view(view.view()), projection(view.projection()), near_distance(view.near_distance)
{
}

uint32_t draw_line_3d(Image& image, const Camera& view, const glm::vec3& a, const glm::vec3& b, uint32_t rgb)
{
    return draw_line_3d(image, LineProjection(view), a, b, rgb);
}

uint32_t draw_line_3d(Image& image, const LineProjection& view, const glm::vec3& a, const glm::vec3& b, uint32_t rgb)
{
    const glm::mat4& to_view = view.to_view;
    glm::vec4 va = to_view * glm::vec4(a, 1.0f), vb = to_view * glm::vec4(b, 1.0f);
    // View space looks down -z: depth = -z. Keep the part with depth >= near.
    const float near_plane = view.near_distance;
    const float da = -va.z, db = -vb.z;
    if (!(da >= near_plane) && !(db >= near_plane))
        return 0; // entirely behind the near plane (or NaN)
    if (da < near_plane || db < near_plane) {
        const float t = (near_plane - da) / (db - da); // da != db: one is in front, one behind
        const glm::vec4 cut = va + (vb - va) * t;
        (da < near_plane ? va : vb) = cut;
    }
    const glm::mat4& projection = view.projection;
    const float w = float(image.width), h = float(image.height);
    auto to_pixel = [&](const glm::vec4& v) {
        const glm::vec4 c = projection * v;
        const glm::vec2 ndc(c.x / c.w, c.y / c.w);
        return glm::vec2((ndc.x * 0.5f + 0.5f) * w, (0.5f - ndc.y * 0.5f) * h);
    };
    return draw_line_2d(image, to_pixel(va), to_pixel(vb), rgb);
}

std::array<glm::vec3, 8> frustum_corners(const Camera& camera)
{
    // glm::lookAt's basis with z up: forward f, side s = f x up, up u = s x f.
    const glm::vec3 f = camera.forward();
    const glm::vec3 s = glm::normalize(glm::cross(f, glm::vec3(0.0f, 0.0f, 1.0f)));
    const glm::vec3 u = glm::cross(s, f);
    const float tan_half = std::tan(glm::radians(camera.fov_y_degrees) * 0.5f);
    std::array<glm::vec3, 8> corners;
    size_t i = 0;
    for (float distance : {camera.near_distance, camera.far_distance}) {
        const glm::vec3 centre = camera.position + f * distance;
        const glm::vec3 up = u * (distance * tan_half), side = s * (distance * tan_half * camera.aspect);
        corners[i++] = centre - side - up;
        corners[i++] = centre + side - up;
        corners[i++] = centre + side + up;
        corners[i++] = centre - side + up;
    }
    return corners;
}

uint32_t draw_frustum(Image& image, const Camera& view, const Camera& frustum, uint32_t rgb)
{
    const std::array<glm::vec3, 8> c = frustum_corners(frustum);
    uint32_t set = 0;
    for (size_t k = 0; k < 4; ++k) {
        const size_t next = (k + 1) % 4;
        set += draw_line_3d(image, view, c[k], c[next], rgb);         // near rectangle
        set += draw_line_3d(image, view, c[4 + k], c[4 + next], rgb); // far rectangle
        set += draw_line_3d(image, view, c[k], c[4 + k], rgb);        // side edges
    }
    return set;
}

} // namespace pvs::ui
