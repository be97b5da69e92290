// The colours pictures are coded in (0xRRGGBB): face ids in an ID buffer (the encoding and its
// 21-bit limit are explained in software_renderer.h), each region's stable colour, and the tints
// of region flags and of PVS membership, with the blend that applies them.
#pragma once

#include "render/image.h"
#include "visibility/zone.h"

#include <array>
#include <cstdint>

namespace pvs::ui {

inline constexpr uint32_t kIdBitsPerChannel = 7;
inline constexpr uint32_t kMaxIdValue = (1u << (3 * kIdBitsPerChannel)) - 1; // largest face id + 1
inline constexpr uint32_t kMaxIdFaces = kMaxIdValue;                         // faces 0 .. kMaxIdFaces-1 are encodable
inline constexpr uint32_t kNoFace = 0xFFFFFFFFu;

// value = face id + 1 (1 .. kMaxIdValue): each channel 2b+1 with b = 7 bits of the value.
constexpr uint32_t encode_id(uint32_t value)
{
    const uint32_t r = (value >> 14) & 0x7F, g = (value >> 7) & 0x7F, b = value & 0x7F;
    return ((r << 1 | 1) << 16) | ((g << 1 | 1) << 8) | (b << 1 | 1);
}
// Inverse of encode_id for a colour as written or as read back (low bits ignored); 0 = background.
constexpr uint32_t decode_id(uint8_t r, uint8_t g, uint8_t b)
{
    if ((r | g | b) == 0)
        return 0;
    return (uint32_t(r >> 1) << 14) | (uint32_t(g >> 1) << 7) | uint32_t(b >> 1);
}
// The face whose id a pixel of an IdBuffer image holds, or kNoFace for the background.
inline uint32_t face_at(const Image& ids, uint32_t x, uint32_t y)
{
    const uint8_t* p = ids.pixel(x, y);
    const uint32_t value = decode_id(p[0], p[1], p[2]);
    return value == 0 ? kNoFace : value - 1;
}
// Stable colour of a region (a hash of its id): every channel odd and >= 49, so never the
// background and unchanged by restore_written_color. Distinct for almost all pairs (104^3 codes).
uint32_t region_color(uint32_t region);

// ---- Region-flag tints (Flags mode) ------------------------------------------------------------

// The one table of flag colours, in priority order: a region with several flags is tinted by the
// first entry whose flag it has. Zone lines first (the exits are what a zone inspector looks for,
// and an EverQuest zone line is often also water or lava), then PvP (a rule of the area), then the
// liquids by harm (lava, slime, water), then vwater, ice, and sky last (Quake sky leaves are the
// void above the level). Every RegionFlag has an entry.
struct FlagTint {
    uint32_t flag; // one RegionFlag bit
    uint32_t rgb;  // 0xRRGGBB
};
inline constexpr std::array<FlagTint, kRegionFlagCount> kFlagTints{{
    {kRegionZoneLine, 0xFF00FF}, // magenta
    {kRegionPvp, 0xFF2020},      // red
    {kRegionLava, 0xFF7A00},     // orange
    {kRegionSlime, 0x30E030},    // green
    {kRegionWater, 0x1E5AFF},    // blue
    {kRegionVWater, 0x00B0A0},   // teal
    {kRegionIce, 0xC0FFFF},      // pale cyan
    {kRegionSky, 0x87CEFA},      // light blue
}};
// The tint's weight in the blend, out of 256: 128 = half texel, half tint. Strong enough that a
// tinted face reads at a glance, weak enough that its texture still shows through.
inline constexpr uint32_t kFlagTintAlpha = 128;
inline constexpr uint32_t kNoTint = 0xFFFFFFFFu;

// The PVS membership tints (the inspector's membership overlay: a region's part in this frame's
// culling, ui/zone_overlays.h Membership order): the culling camera's region, drawn, culled by the
// frustum, culled by the PVS, culled by a shut Quake 2 areaportal. They follow the flag tints in
// one palette of tint indices.
inline constexpr std::array<uint32_t, 5> kMembershipTints{0xFFFFFF, 0x40E040, 0xFFA020, 0xE03030, 0xB060FF};
inline constexpr uint32_t kMembershipTintBase = uint32_t(kFlagTints.size());
inline constexpr uint32_t kTintPaletteSize = kMembershipTintBase + uint32_t(kMembershipTints.size());
// 0xRRGGBB of palette index `tint` (< kTintPaletteSize).
constexpr uint32_t tint_palette_rgb(uint32_t tint)
{
    return tint < kMembershipTintBase ? kFlagTints[tint].rgb : kMembershipTints[tint - kMembershipTintBase];
}

// Index into kFlagTints of the tint for a region with these RegionFlag bits, or kNoTint.
constexpr uint32_t flag_tint_index(uint32_t region_flags)
{
    for (uint32_t i = 0; i < kFlagTints.size(); ++i)
        if (region_flags & kFlagTints[i].flag)
            return i;
    return kNoTint;
}
// `rgb` (0xRRGGBB) blended with the tint `tint_rgb`: per channel (c * (256 - a) + t * a + 128) / 256
// with a = kFlagTintAlpha.
constexpr uint32_t blend_tint(uint32_t rgb, uint32_t tint_rgb)
{
    uint32_t out = 0;
    for (uint32_t shift : {16u, 8u, 0u}) {
        const uint32_t c = (rgb >> shift) & 0xFF, t = (tint_rgb >> shift) & 0xFF;
        out |= ((c * (256 - kFlagTintAlpha) + t * kFlagTintAlpha + 128) >> 8) << shift;
    }
    return out;
}

} // namespace pvs::ui
