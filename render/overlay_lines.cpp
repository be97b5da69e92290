#include "render/overlay_lines.h"

#include "render/overlay_layer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>

namespace pvs::ui {

namespace {

// Liang-Barsky: the part [t0, t1] of the segment p0-p1 inside [0, width] x [0, height]. False
// when nothing is left.
bool clip_params(double x0, double y0, double x1, double y1, double width, double height, double& t0, double& t1)
{
    t0 = 0.0;
    t1 = 1.0;
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
    return true;
}

// Cuts the segment p0-p1 to [0, width] x [0, height]. False when nothing is left.
bool clip_to_rect(double& x0, double& y0, double& x1, double& y1, double width, double height)
{
    double t0 = 0.0, t1 = 1.0;
    if (!clip_params(x0, y0, x1, y1, width, height, t0, t1))
        return false;
    const double dx = x1 - x0, dy = y1 - y0, ox = x0, oy = y0;
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

bool image_ok(const Image& image)
{
    return image.width > 0 && image.height > 0 && image.rgba.size() == size_t(image.width) * image.height * 4;
}

// The pixel ends of the segment a-b cut to the image. False when it misses the image or has a
// non-finite end; a segment that only touches the right or bottom edge holds no pixel.
struct PixelSpan {
    int32_t x, y, xe, ye;
    uint32_t steps() const { return uint32_t(std::max(std::abs(xe - x), std::abs(ye - y))); }
};
bool pixel_span(const Image& image, glm::vec2 a, glm::vec2 b, PixelSpan& span)
{
    if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y))
        return false;
    double x0 = a.x, y0 = a.y, x1 = b.x, y1 = b.y;
    if (!clip_to_rect(x0, y0, x1, y1, double(image.width), double(image.height)))
        return false;
    if ((x0 >= image.width && x1 >= image.width) || (y0 >= image.height && y1 >= image.height))
        return false;
    span = {pixel_index(x0, image.width), pixel_index(y0, image.height), pixel_index(x1, image.width),
            pixel_index(y1, image.height)};
    return true;
}

// Bresenham from (x, y) to (xe, ye), both pixels set; alpha_at(step) gives each pixel's alpha
// (negative: the pixel is skipped). Returns how many pixels were set.
template <class AlphaAt>
uint32_t trace_pixels(Image& image, const PixelSpan& span, uint32_t rgb, AlphaAt&& alpha_at)
{
    int32_t x = span.x, y = span.y;
    const int32_t xe = span.xe, ye = span.ye;
    const int32_t dx = std::abs(xe - x), dy = -std::abs(ye - y);
    const int32_t sx = x < xe ? 1 : -1, sy = y < ye ? 1 : -1;
    int32_t error = dx + dy;
    uint32_t set = 0;
    for (uint32_t step = 0;; ++step) {
        if (const int32_t alpha = alpha_at(step); alpha >= 0) {
            blend_over(image.rgba.data() + (size_t(uint32_t(y)) * image.width + uint32_t(x)) * 4, rgb, uint32_t(alpha));
            ++set;
        }
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

} // namespace

uint32_t draw_line_2d(Image& image, glm::vec2 a, glm::vec2 b, uint32_t rgb, uint32_t alpha)
{
    PixelSpan span;
    if (!image_ok(image) || !pixel_span(image, a, b, span))
        return 0;
    return trace_pixels(image, span, rgb, [alpha](uint32_t) { return int32_t(std::min<uint32_t>(alpha, 255)); });
}

LineProjection::LineProjection(const Camera& view)
    : to_view(view.view()), projection(view.projection()), near_distance(view.near_distance)
{
}

uint32_t draw_line_3d(Image& image, const Camera& view, const glm::vec3& a, const glm::vec3& b, uint32_t rgb)
{
    return draw_line_3d(image, LineProjection(view), a, b, rgb);
}

namespace {

// The projected segment pa-pb drawn once, its pixels taken kDepthPiecePixels at a time; each
// piece is drawn in full or as hidden_lines says, by the occlusion of its middle point. wa/wb are
// the zone points of pa/pb and da/db their view-space depths: the screen fraction s maps back to
// the segment at s*da / (s*da + (1-s)*db) (depth is linear in 1/w on the screen, so the 3-D
// parameter is not s itself).
uint32_t draw_depth_tested(Image& image, const LineProjection& view, glm::vec2 pa, glm::vec2 pb,
                           const glm::vec3& wa, const glm::vec3& wb, float da, float db, uint32_t rgb)
{
    double s0 = 0.0, s1 = 1.0;
    PixelSpan span;
    if (!pixel_span(image, pa, pb, span) ||
        !clip_params(pa.x, pa.y, pb.x, pb.y, double(image.width), double(image.height), s0, s1))
        return 0;
    const double steps = std::max(1.0, double(span.steps()));
    int32_t alpha = 255;
    return trace_pixels(image, span, rgb, [&](uint32_t step) {
        if (step % kDepthPiecePixels == 0) { // a new piece: its middle pixel decides for it
            const double middle = std::min(steps, double(step) + 0.5 * (kDepthPiecePixels - 1)) / steps;
            const double s = s0 + (s1 - s0) * middle;
            const double t = s * da / (s * da + (1.0 - s) * db);
            const bool hidden = view.occlusion->hidden(wa + (wb - wa) * float(t));
            alpha = !hidden ? 255 : view.hidden_lines == HiddenLines::Hidden ? -1 : int32_t(kFaintLineAlpha);
        }
        return alpha;
    });
}

} // namespace

uint32_t draw_line_3d(Image& image, const LineProjection& view, const glm::vec3& a, const glm::vec3& b, uint32_t rgb)
{
    const glm::mat4& to_view = view.to_view;
    glm::vec4 va = to_view * glm::vec4(a, 1.0f), vb = to_view * glm::vec4(b, 1.0f);
    glm::vec3 wa = a, wb = b;
    // View space looks down -z: depth = -z. Keep the part with depth >= near.
    const float near_plane = view.near_distance;
    float da = -va.z, db = -vb.z;
    if (!(da >= near_plane) && !(db >= near_plane))
        return 0; // entirely behind the near plane (or NaN)
    if (da < near_plane || db < near_plane) {
        const float t = (near_plane - da) / (db - da); // da != db: one is in front, one behind
        const glm::vec4 cut = va + (vb - va) * t;
        const glm::vec3 world_cut = a + (b - a) * t;
        if (da < near_plane) {
            va = cut, wa = world_cut, da = near_plane;
        } else {
            vb = cut, wb = world_cut, db = near_plane;
        }
    }
    const glm::mat4& projection = view.projection;
    const float w = float(image.width), h = float(image.height);
    auto to_pixel = [&](const glm::vec4& v) {
        const glm::vec4 c = projection * v;
        const glm::vec2 ndc(c.x / c.w, c.y / c.w);
        return glm::vec2((ndc.x * 0.5f + 0.5f) * w, (0.5f - ndc.y * 0.5f) * h);
    };
    if (view.occlusion && view.hidden_lines != HiddenLines::Shown && image_ok(image))
        return draw_depth_tested(image, view, to_pixel(va), to_pixel(vb), wa, wb, da, db, rgb);
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
    return draw_frustum(image, LineProjection(view), frustum, rgb);
}

uint32_t draw_frustum(Image& image, const LineProjection& view, const Camera& frustum, uint32_t rgb)
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
