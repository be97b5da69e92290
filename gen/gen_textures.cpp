#include "gen/gen_textures.h"

#include <algorithm>
#include <cmath>

namespace pvs::gen {

namespace {

constexpr uint32_t kSize = 64;

// A 32-bit integer hash (lowbias32 by Chris Wellons): cheap and well mixed.
uint32_t hash(uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

// Noise in 32 steps, so that every texture keeps to at most 256 colours and is stored
// palettized (visibility/material_pixels.h): a quarter of the memory of RGBA.
float noise(uint32_t seed, uint32_t x, uint32_t y)
{
    return float(hash(seed ^ hash(x * 73856093U ^ y * 19349663U)) & 0x1F) / 31.0f;
}

struct Rgb {
    float r, g, b;
};

Material make(const char* name, uint32_t flags, Rgb (*texel)(uint32_t x, uint32_t y))
{
    Material m;
    m.name = name;
    m.flags = flags;
    std::vector<uint8_t> rgba(size_t(kSize) * kSize * 4);
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            const Rgb c = texel(x, y);
            uint8_t* p = &rgba[(size_t(y) * kSize + x) * 4];
            p[0] = uint8_t(std::clamp(c.r, 0.0f, 1.0f) * 255.0f);
            p[1] = uint8_t(std::clamp(c.g, 0.0f, 1.0f) * 255.0f);
            p[2] = uint8_t(std::clamp(c.b, 0.0f, 1.0f) * 255.0f);
            p[3] = 255;
        }
    set_material_rgba(m, kSize, kSize, rgba);
    return m;
}

Rgb wall(uint32_t x, uint32_t y)
{
    // Bricks 32x16 with offset rows and dark mortar.
    const uint32_t row = y / 16, bx = (x + (row % 2) * 16) % 32, by = y % 16;
    const bool mortar = bx < 2 || by < 2;
    const float n = 0.75f + 0.25f * noise(1, x, y);
    return mortar ? Rgb{0.25f, 0.23f, 0.2f} : Rgb{0.55f * n, 0.42f * n, 0.32f * n};
}
Rgb floor_tiles(uint32_t x, uint32_t y)
{
    const bool dark = ((x / 16) + (y / 16)) % 2 == 0;
    const float n = 0.85f + 0.15f * noise(2, x, y);
    const float v = (dark ? 0.35f : 0.5f) * n;
    return {v, v, v * 0.95f};
}
Rgb ceiling(uint32_t x, uint32_t y)
{
    const float v = 0.3f + 0.1f * noise(3, x / 2, y / 2);
    return {v, v, v};
}
Rgb water(uint32_t x, uint32_t y)
{
    const float w = 0.5f + 0.5f * std::sin(float(x) * 0.2f + std::sin(float(y) * 0.15f) * 2.0f);
    return {0.1f, 0.3f + 0.15f * w, 0.6f + 0.2f * w};
}
Rgb lava(uint32_t x, uint32_t y)
{
    const float n = std::round((noise(5, x / 4, y / 4) * 0.6f + noise(6, x, y) * 0.4f) * 63.0f) / 63.0f;
    return {0.8f + 0.2f * n, 0.25f + 0.4f * n, 0.05f};
}
Rgb slime(uint32_t x, uint32_t y)
{
    const float n = noise(7, x / 3, y / 3);
    return {0.2f + 0.1f * n, 0.55f + 0.3f * n, 0.15f};
}
Rgb pvp(uint32_t x, uint32_t y)
{
    const bool red = ((x / 8) + (y / 8)) % 2 == 0;
    return red ? Rgb{0.7f, 0.1f, 0.1f} : Rgb{0.1f, 0.1f, 0.1f};
}
Rgb zone_line(uint32_t x, uint32_t y)
{
    const float stripe = 0.5f + 0.5f * std::sin(float(x + y) * 0.4f);
    return {0.5f + 0.3f * stripe, 0.2f, 0.7f + 0.3f * stripe};
}

} // namespace

std::vector<Material> make_gen_materials()
{
    return {make("gen_wall", 0, wall),         make("gen_floor", 0, floor_tiles),
            make("gen_ceiling", 0, ceiling),   make("gen_water", kMaterialLiquid, water),
            make("gen_lava", kMaterialLiquid, lava), make("gen_slime", kMaterialLiquid, slime),
            make("gen_pvp", 0, pvp),           make("gen_zoneline", 0, zone_line)};
}

} // namespace pvs::gen
