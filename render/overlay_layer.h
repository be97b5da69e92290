// Transparent overlay layers: a picture-sized Image that starts fully transparent, is drawn into
// with the same line functions as a picture (ui/overlay_lines.h), and is composited over the
// picture afterwards. It lets overlays that need no picture be drawn on another core while the
// picture renders (the inspector's many-line overlays).
//
// Pixels are blended with the "over" operator, which is associative: drawing A then B into a
// transparent layer and compositing it over a picture gives what drawing A then B onto the
// picture gives, up to 8-bit rounding where two translucent marks overlap. Where one mark alone
// covers a pixel, the result is that of drawing it on the picture, to the bit: the layer keeps
// its colour and alpha, and the composite blends them as a line blends over a picture.
#pragma once

#include "render/colour_codes.h"
#include "render/image.h"

#include <cstdint>
#include <cstring>

namespace pvs::ui {

// A width x height layer, every pixel transparent (alpha 0); clear_layer makes `layer` one again,
// keeping its memory (a layer a frame).
Image new_layer(uint32_t width, uint32_t height);
void clear_layer(Image& layer, uint32_t width, uint32_t height);

// `rgb` (0xRRGGBB) at `alpha` (0 .. 255) over the pixel p (4 bytes RGBA): onto an opaque pixel
// (a picture's) the line blend (rgb * alpha + p * (255 - alpha)) / 255, rounded; onto a
// translucent one (a layer's) the "over" operator, alpha included.
// Inline: lines call it per pixel.
inline void blend_over(uint8_t* p, uint32_t rgb, uint32_t alpha)
{
    if (alpha == 0)
        return;
    if (alpha >= 255) {
        const uint8_t opaque[4] = {uint8_t(rgb >> 16), uint8_t(rgb >> 8), uint8_t(rgb), 255};
        std::memcpy(p, opaque, 4);
        return;
    }
    const uint32_t below = p[3];
    if (below == 255) { // a picture's pixel
        for (int c = 0; c < 3; ++c) {
            const uint32_t line = (rgb >> (16 - 8 * c)) & 0xFF;
            p[c] = uint8_t((line * alpha + p[c] * (255 - alpha) + 127) / 255);
        }
        return;
    }
    if (below == 0) { // a layer's empty pixel: the mark itself
        const uint8_t mark[4] = {uint8_t(rgb >> 16), uint8_t(rgb >> 8), uint8_t(rgb), uint8_t(alpha)};
        std::memcpy(p, mark, 4);
        return;
    }
    // Over: alpha_out = a + b (1 - a); colour_out = (c_a a + c_b b (1 - a)) / alpha_out, in 255ths.
    const uint32_t below_kept = below * (255 - alpha); // b (1 - a), in 255^2ths
    const uint32_t out = alpha * 255 + below_kept;     // alpha_out, in 255^2ths (> 0: alpha > 0)
    for (int c = 0; c < 3; ++c) {
        const uint32_t line = (rgb >> (16 - 8 * c)) & 0xFF;
        p[c] = uint8_t((line * alpha * 255 + p[c] * below_kept + out / 2) / out);
    }
    p[3] = uint8_t((out + 127) / 255);
}


// Composites `layer` over `picture` (the same size; otherwise nothing happens and false is
// returned): each layer pixel blended over the picture's with its own alpha.
bool composite_layer(const Image& layer, Image& picture);

} // namespace pvs::ui
