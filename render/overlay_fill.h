// Translucent convex polygons and wire boxes over a rendered Image, on the CPU after read-back:
// the inspector's BSP split planes, portals and region bounds (ui/zone_overlays.h).
//
// Same pixel and projection conventions as ui/overlay_lines.h: a zone point is placed with the
// view camera's view() and projection(); pixel (i, j) covers [i, i+1) x [j, j+1).
//
// Filling: the 3-D polygon (convex, planar; the points in order around it) is first cut to the
// part in front of the view camera's near plane, so nothing behind the camera is projected; the
// projected polygon stays convex. A pixel is covered when its centre (i + 0.5, j + 0.5) is inside
// the projected polygon, found per row from the polygon's edges in double precision (the left
// end of a span inclusive, the right end exclusive, as rasterisers do, so two polygons sharing
// an edge cover each pixel once). Covered pixels are blended as blend_over below. There is no
// depth test: overlays are drawn on top of the picture, so a plane behind a wall still shows.
// The work is bounded by the image, not by the polygon: a huge or far-off polygon costs at most
// one pass over the rows it covers.
#pragma once

#include "render/overlay_lines.h"
#include "render/colour_codes.h"
#include "render/image.h"
#include "visibility/camera.h"
#include "visibility/math/aabb.h"

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <span>

namespace pvs::ui {

// `rgb` blended over the pixel's colour with weight `alpha` out of 256 per channel:
// (c * (256 - alpha) + t * alpha + 128) / 256 (the same rounding as blend_tint). alpha 256 = opaque.
constexpr uint8_t blend_channel(uint8_t under, uint8_t over, uint32_t alpha)
{
    return uint8_t((uint32_t(under) * (256 - alpha) + uint32_t(over) * alpha + 128) >> 8);
}

// Where a zone point lands in a width x height picture seen from `view`, or nullopt when it is
// not in front of the near plane (or not finite).
std::optional<glm::vec2> project_to_pixel(const Camera& view, uint32_t width, uint32_t height, const glm::vec3& point);

// Fills the pixels the polygon covers (see above) with `rgb` (0xRRGGBB) at `alpha` (1 .. 256,
// clamped). Returns how many pixels were blended: 0 for fewer than three points, a polygon
// entirely behind the near plane or off the image, or a non-finite point.
uint32_t fill_polygon_3d(Image& image, const Camera& view, std::span<const glm::vec3> polygon, uint32_t rgb,
                         uint32_t alpha);

// The polygon's outline (each edge with draw_line_3d). Returns the pixels set.
uint32_t outline_polygon_3d(Image& image, const Camera& view, std::span<const glm::vec3> polygon, uint32_t rgb);

// The 12 edges of a box (nothing for an empty box). Returns the pixels set.
uint32_t draw_box_3d(Image& image, const Camera& view, const Aabb& box, uint32_t rgb);

// The same two with the camera's matrices computed once (many boxes or polygons per frame).
uint32_t outline_polygon_3d(Image& image, const LineProjection& view, std::span<const glm::vec3> polygon, uint32_t rgb);
uint32_t draw_box_3d(Image& image, const LineProjection& view, const Aabb& box, uint32_t rgb);

} // namespace pvs::ui
