// Material pixels kept palettized (visibility/material_pixels.h, set_material_rgba /
// material_rgba in visibility/zone.h): lossless for images of at most 256 colours, RGBA above;
// textures from Quake maps and generated zones take one byte per texel.
#include "tests/support/test_data.h"
#include "visibility/zone.h"
#include "gen/generate_zone.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace pvs {
namespace {

// `colors` distinct colours (all four channels vary), spread over `texels` texels in a scrambled order.
std::vector<uint8_t> image_with_colors(uint32_t colors, uint32_t texels)
{
    std::vector<uint8_t> rgba;
    for (uint32_t i = 0; i < texels; ++i) {
        const uint32_t c = (i * 7919u) % colors;
        rgba.insert(rgba.end(), {uint8_t(c * 37), uint8_t(c >> 3), uint8_t(255 - c), uint8_t(c % 2 ? 255 : c)});
    }
    return rgba;
}

TEST(MaterialPixels, AtMost256ColoursArePalettizedLosslessly)
{
    for (const uint32_t colors : {1u, 2u, 255u, 256u}) {
        const std::vector<uint8_t> rgba = image_with_colors(colors, 64 * 32);
        Material m{"m", 0, 0, {}, 0};
        set_material_rgba(m, 64, 32, rgba);
        EXPECT_TRUE(m.pixels.palettized()) << colors;
        EXPECT_EQ(m.pixels.palette_size(), colors);
        EXPECT_EQ(m.pixels.texel_count(), 64u * 32u);
        EXPECT_EQ(material_rgba(m), rgba) << colors << " colours";
        for (size_t i = 0; i < m.pixels.texel_count(); i += 97)
            EXPECT_EQ(m.pixels.texel(i), uint32_t(rgba[4 * i]) | uint32_t(rgba[4 * i + 1]) << 8 |
                                             uint32_t(rgba[4 * i + 2]) << 16 | uint32_t(rgba[4 * i + 3]) << 24);
        // One byte per texel plus the palette, against four bytes per texel.
        EXPECT_LE(m.pixels.memory_bytes(), 64u * 32u + 256u * 4u);
    }
}

TEST(MaterialPixels, TwoHundredFiftySevenColoursStayRgba)
{
    const std::vector<uint8_t> rgba = image_with_colors(257, 64 * 32);
    Material m{"m", 0, 0, {}, 0};
    set_material_rgba(m, 64, 32, rgba);
    EXPECT_FALSE(m.pixels.palettized());
    EXPECT_EQ(m.pixels.texel_count(), 64u * 32u);
    EXPECT_EQ(material_rgba(m), rgba);
    EXPECT_EQ(m.pixels.texel(5), uint32_t(rgba[20]) | uint32_t(rgba[21]) << 8 | uint32_t(rgba[22]) << 16 |
                                     uint32_t(rgba[23]) << 24);
}

TEST(MaterialPixels, EmptyAndWrongSizes)
{
    Material m{"m", 4, 4, {}, 0};
    EXPECT_FALSE(m.has_pixels());
    EXPECT_TRUE(material_rgba(m).empty());
    EXPECT_THROW(set_material_rgba(m, 4, 4, std::vector<uint8_t>(4 * 4 * 4 - 1)), std::invalid_argument);
    EXPECT_THROW(set_material_rgba(m, 4, 4, std::vector<uint8_t>(4 * 5 * 4)), std::invalid_argument);
    set_material_rgba(m, 2, 1, std::vector<uint8_t>{1, 2, 3, 4, 1, 2, 3, 4});
    EXPECT_TRUE(m.has_pixels());
    EXPECT_EQ(m.width, 2u);
    set_material_rgba(m, 0, 0, {});
    EXPECT_FALSE(m.has_pixels());
}

TEST(MaterialPixels, SameImageSameStorage)
{
    Material a{"a", 0, 0, {}, 0}, b{"b", 0, 0, {}, 0};
    set_material_rgba(a, 16, 16, image_with_colors(40, 256));
    set_material_rgba(b, 16, 16, image_with_colors(40, 256));
    EXPECT_EQ(a.pixels, b.pixels);
}

TEST(MaterialPixels, GeneratedTexturesArePalettized)
{
    const Zone z = gen::generate_zone({.rooms = 5, .seed = 1, .cell_size = 32.0f});
    ASSERT_FALSE(z.materials.empty());
    for (const Material& m : z.materials) {
        EXPECT_TRUE(m.pixels.palettized()) << m.name;
        EXPECT_EQ(material_rgba(m).size(), size_t(m.width) * m.height * 4) << m.name;
    }
}

TEST(MaterialPixels, QuakeTexturesArePalettized)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    const Zone& z = *test::shared_zone("quake/e1m1.bsp");
    for (const Material& m : z.materials) {
        if (m.has_pixels()) {
            EXPECT_TRUE(m.pixels.palettized()) << m.name; // Quake's palette has 256 entries
        }
    }
}

} // namespace
} // namespace pvs
