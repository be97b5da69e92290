// Lines drawn over a rendered Image, on the CPU after read-back: the locked culling camera's
// view volume (render_culled in ui/culled_frame.h), and anything else an overlay needs.
//
// Pixel coordinates: pixel (i, j) covers [i, i+1) x [j, j+1), x to the right, y down; the
// image's own rows are top to bottom. A zone point is placed in the image with the view
// camera's view_projection() (the view volume the renderer draws and the culler tests): NDC x
// -1 .. 1 maps to 0 .. width, NDC y 1 .. -1 to 0 .. height.
//
// Clipping: a 3-D segment is first cut to the part in front of the view camera's near plane
// (view-space depth >= near_distance), so points behind the camera are never projected (their
// projection would flip through infinity); the projected segment is then cut to the image in
// double precision before any rounding, so far-off endpoints cost nothing and cannot overflow.
// The far plane does not clip: a line beyond it is still drawn where it projects.
//
// Depth test: the picture's depth buffer stays inside Irrlicht, so a line is tested against the
// zone's geometry instead (a LineOcclusion, ui/picture_occlusion.h: rays against the faces the
// picture drew). The projected line is drawn in one pass, its pixels taken kDepthPiecePixels at
// a time; each piece's middle pixel, mapped back onto the 3-D segment perspective-correctly,
// decides for the whole piece (one test per piece, so an e1m1 frame with every overlay costs a
// few thousand; a line's hidden part can start up to half a piece early or late). Hidden
// pieces are drawn faint (kFaintLineAlpha of the colour over the picture) or not at all.
#pragma once

#include "render/colour_codes.h"
#include "render/image.h"
#include "visibility/camera.h"

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace pvs::ui {

// Whether a zone point is hidden from the view camera by the picture's own geometry.
class LineOcclusion {
public:
    virtual ~LineOcclusion() = default;
    virtual bool hidden(const glm::vec3& point) const = 0;
};

// What becomes of the parts of a line a LineOcclusion hides.
enum class HiddenLines : uint8_t { Shown, Faint, Hidden };
inline constexpr uint32_t kDepthPiecePixels = 6;
inline constexpr uint32_t kFaintLineAlpha = 70; // out of 255: behind a wall, still findable

// The colour render_culled draws a locked culling camera's view volume in: yellow, which no
// kFlagTints entry comes close to.
inline constexpr uint32_t kLockedFrustumColor = 0xFFFF00;

// Sets the pixels of the segment a-b (pixel coordinates, see above) that lie in the image to
// `rgb` (0xRRGGBB, alpha 255): Bresenham between the pixels that hold the ends of the part of
// the segment inside the image, so both end pixels are set when they are in the image. Returns
// how many pixels were set (0 for a segment that misses the image or has a non-finite end).
// With alpha < 255 the colour is blended over the pixels (alpha/255 of it).
uint32_t draw_line_2d(Image& image, glm::vec2 a, glm::vec2 b, uint32_t rgb, uint32_t alpha = 255);

// The zone segment a-b seen from `view` (its aspect should be the image's), clipped to the near
// plane and the image. Returns how many pixels were set: 0 when it lies entirely behind the near
// plane or projects off the image.
uint32_t draw_line_3d(Image& image, const Camera& view, const glm::vec3& a, const glm::vec3& b, uint32_t rgb);

// The same with the camera's matrices computed once by the caller (view.view(), view.projection()
// and its near distance): for drawing many segments from one camera. With `occlusion` set and
// hidden_lines not Shown, lines are depth-tested (see the top of this file); the occlusion
// object is borrowed and must outlive the projection's use.
struct LineProjection {
    glm::mat4 to_view, projection;
    float near_distance;
    const LineOcclusion* occlusion = nullptr;
    HiddenLines hidden_lines = HiddenLines::Shown;
    explicit LineProjection(const Camera& view);
};
uint32_t draw_line_3d(Image& image, const LineProjection& view, const glm::vec3& a, const glm::vec3& b, uint32_t rgb);

// The corners of `camera`'s view volume: the near rectangle then the far one, each bottom-left,
// bottom-right, top-right, top-left as that camera sees them. The same volume as
// camera.view_projection() (glm::lookAt with z up, glm::perspective), built from its vectors.
std::array<glm::vec3, 8> frustum_corners(const Camera& camera);

// The 12 edges of `frustum`'s view volume seen from `view`. Returns the pixels set.
uint32_t draw_frustum(Image& image, const Camera& view, const Camera& frustum, uint32_t rgb);
uint32_t draw_frustum(Image& image, const LineProjection& view, const Camera& frustum, uint32_t rgb);

} // namespace pvs::ui
