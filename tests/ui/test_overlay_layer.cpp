// Overlay layers (ui/overlay_layer.h): a mark drawn into a transparent layer and composited over
// a picture gives the picture the mark would have given drawn on it, to the bit; overlapping
// translucent marks to within 8-bit rounding; a layer of another size changes nothing.
#include "render/overlay_layer.h"
#include "render/overlay_lines.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace pvs {
namespace {

// An opaque picture of varied colours (so blends differ pixel to pixel).
ui::Image picture(uint32_t width, uint32_t height)
{
    ui::Image image;
    image.width = width;
    image.height = height;
    image.rgba.resize(size_t(width) * height * 4);
    for (size_t i = 0; i < image.rgba.size(); ++i)
        image.rgba[i] = i % 4 == 3 ? 255 : uint8_t((i * 37 + i / 7) % 256);
    return image;
}

TEST(OverlayLayer, OneMarkCompositedIsTheMarkDrawnOnThePicture)
{
    for (uint32_t alpha : {255u, 70u, 1u, 254u}) {
        ui::Image direct = picture(40, 30), composited = direct;
        ui::draw_line_2d(direct, {1.5f, 2.5f}, {37.5f, 27.5f}, 0x3080F0, alpha);
        ui::Image layer = ui::new_layer(40, 30);
        ui::draw_line_2d(layer, {1.5f, 2.5f}, {37.5f, 27.5f}, 0x3080F0, alpha);
        ASSERT_TRUE(ui::composite_layer(layer, composited));
        EXPECT_EQ(direct.rgba, composited.rgba) << alpha;
    }
}

TEST(OverlayLayer, OverlappingTranslucentMarksWithinRounding)
{
    ui::Image direct = picture(40, 30), composited = direct;
    ui::Image layer = ui::new_layer(40, 30);
    const auto draw = [](ui::Image& image) {
        ui::draw_line_2d(image, {0.5f, 10.5f}, {39.5f, 10.5f}, 0xFF0000, 70);  // across
        ui::draw_line_2d(image, {20.5f, 0.5f}, {20.5f, 29.5f}, 0x00FF00, 120); // crosses it
        ui::draw_line_2d(image, {0.5f, 10.5f}, {39.5f, 10.5f}, 0x0000FF, 70);  // over the first
        ui::draw_line_2d(image, {5.5f, 0.5f}, {5.5f, 29.5f}, 0xFFFFFF, 255);   // opaque on top
    };
    draw(direct);
    draw(layer);
    ASSERT_TRUE(ui::composite_layer(layer, composited));
    int worst = 0;
    for (size_t i = 0; i < direct.rgba.size(); ++i)
        worst = std::max(worst, std::abs(int(direct.rgba[i]) - int(composited.rgba[i])));
    EXPECT_LE(worst, 2);
    // Untouched pixels are the picture's own.
    EXPECT_EQ(composited.pixel(30, 25)[0], picture(40, 30).pixel(30, 25)[0]);
}

TEST(OverlayLayer, ALayerOfAnotherSizeChangesNothing)
{
    ui::Image target = picture(40, 30);
    const ui::Image before = target;
    ui::Image layer = ui::new_layer(30, 40);
    ui::draw_line_2d(layer, {0.5f, 0.5f}, {20.5f, 20.5f}, 0xFFFFFF);
    EXPECT_FALSE(ui::composite_layer(layer, target));
    EXPECT_EQ(target.rgba, before.rgba);
}

} // namespace
} // namespace pvs
