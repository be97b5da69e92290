#include "render/overlay_fill.h"

#include "render/overlay_lines.h"

#include <algorithm>
#include <cmath>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <vector>

namespace pvs::ui {

namespace {

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// View-space points (depth = -z) cut to depth >= near (Sutherland-Hodgman against one plane).
void clip_to_near(const std::vector<glm::vec4>& in, float near_plane, std::vector<glm::vec4>& out)
{
    out.clear();
    for (size_t i = 0; i < in.size(); ++i) {
        const glm::vec4& a = in[i];
        const glm::vec4& b = in[(i + 1) % in.size()];
        const float da = -a.z - near_plane, db = -b.z - near_plane;
        if (da >= 0.0f)
            out.push_back(a);
        if ((da >= 0.0f) != (db >= 0.0f))
            out.push_back(a + (b - a) * (da / (da - db)));
    }
}

glm::dvec2 to_pixel(const glm::mat4& projection, const glm::vec4& view_point, uint32_t width, uint32_t height)
{
    const glm::vec4 c = projection * view_point;
    const double x = double(c.x) / double(c.w), y = double(c.y) / double(c.w);
    return {(x * 0.5 + 0.5) * double(width), (0.5 - y * 0.5) * double(height)};
}

// Blends one row's pixels whose centres lie in [x0, x1).
uint32_t blend_span(Image& image, uint32_t row, double x0, double x1, uint32_t rgb, uint32_t alpha)
{
    // Centre i + 0.5 in [x0, x1)  <=>  i in [ceil(x0 - 0.5), ceil(x1 - 0.5)).
    const double first = std::max(std::ceil(x0 - 0.5), 0.0), end = std::min(std::ceil(x1 - 0.5), double(image.width));
    if (!(first < end))
        return 0;
    const uint8_t r = uint8_t(rgb >> 16), g = uint8_t(rgb >> 8), b = uint8_t(rgb);
    uint8_t* p = image.rgba.data() + (size_t(row) * image.width + size_t(first)) * 4;
    const auto count = uint32_t(end - first);
    for (uint32_t i = 0; i < count; ++i, p += 4) {
        p[0] = blend_channel(p[0], r, alpha);
        p[1] = blend_channel(p[1], g, alpha);
        p[2] = blend_channel(p[2], b, alpha);
    }
    return count;
}

} // namespace

std::optional<glm::vec2> project_to_pixel(const Camera& view, uint32_t width, uint32_t height, const glm::vec3& point)
{
    if (!finite(point))
        return std::nullopt;
    const glm::vec4 v = view.view() * glm::vec4(point, 1.0f);
    if (!(-v.z >= view.near_distance))
        return std::nullopt;
    const glm::dvec2 p = to_pixel(view.projection(), v, width, height);
    return glm::vec2(float(p.x), float(p.y));
}

uint32_t fill_polygon_3d(Image& image, const Camera& view, std::span<const glm::vec3> polygon, uint32_t rgb,
                         uint32_t alpha)
{
    if (polygon.size() < 3 || image.width == 0 || image.height == 0 ||
        image.rgba.size() != size_t(image.width) * image.height * 4)
        return 0;
    if (!std::all_of(polygon.begin(), polygon.end(), finite))
        return 0;
    alpha = std::clamp<uint32_t>(alpha, 1, 256);

    const glm::mat4 to_view = view.view();
    std::vector<glm::vec4> in, clipped;
    in.reserve(polygon.size());
    for (const glm::vec3& p : polygon)
        in.push_back(to_view * glm::vec4(p, 1.0f));
    clip_to_near(in, view.near_distance, clipped);
    if (clipped.size() < 3)
        return 0;

    const glm::mat4 projection = view.projection();
    std::vector<glm::dvec2> points;
    points.reserve(clipped.size());
    double top = INFINITY, bottom = -INFINITY;
    for (const glm::vec4& v : clipped) {
        points.push_back(to_pixel(projection, v, image.width, image.height));
        top = std::min(top, points.back().y);
        bottom = std::max(bottom, points.back().y);
    }
    // Rows whose centre j + 0.5 lies in [top, bottom).
    const double first_row = std::max(std::ceil(top - 0.5), 0.0);
    const double end_row = std::min(std::ceil(bottom - 0.5), double(image.height));
    uint32_t blended = 0;
    for (double row = first_row; row < end_row; row += 1.0) {
        const double y = row + 0.5;
        double left = INFINITY, right = -INFINITY;
        // Convex: the row's centre line crosses the outline at most twice; take the extremes.
        for (size_t i = 0; i < points.size(); ++i) {
            const glm::dvec2 a = points[i], b = points[(i + 1) % points.size()];
            if ((a.y <= y) == (b.y <= y))
                continue; // the edge does not cross this row's centre line (or is horizontal)
            const double x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
            left = std::min(left, x);
            right = std::max(right, x);
        }
        if (left < right)
            blended += blend_span(image, uint32_t(row), left, right, rgb, alpha);
    }
    return blended;
}

uint32_t outline_polygon_3d(Image& image, const Camera& view, std::span<const glm::vec3> polygon, uint32_t rgb)
{
    return outline_polygon_3d(image, LineProjection(view), polygon, rgb);
}

uint32_t draw_box_3d(Image& image, const Camera& view, const Aabb& box, uint32_t rgb)
{
    return draw_box_3d(image, LineProjection(view), box, rgb);
}

uint32_t outline_polygon_3d(Image& image, const LineProjection& view, std::span<const glm::vec3> polygon, uint32_t rgb)
{
    if (polygon.size() < 2)
        return 0;
    uint32_t set = 0;
    for (size_t i = 0; i < polygon.size(); ++i)
        set += draw_line_3d(image, view, polygon[i], polygon[(i + 1) % polygon.size()], rgb);
    return set;
}

uint32_t draw_box_3d(Image& image, const LineProjection& view, const Aabb& box, uint32_t rgb)
{
    if (box.empty())
        return 0;
    const glm::vec3 lo = box.min, hi = box.max;
    const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                            {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    uint32_t set = 0;
    for (size_t k = 0; k < 4; ++k) {
        set += draw_line_3d(image, view, c[k], c[(k + 1) % 4], rgb);         // bottom
        set += draw_line_3d(image, view, c[4 + k], c[4 + (k + 1) % 4], rgb); // top
        set += draw_line_3d(image, view, c[k], c[4 + k], rgb);               // vertical
    }
    return set;
}

} // namespace pvs::ui
