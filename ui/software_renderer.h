// Headless rendering of a zone with Irrlicht 1.8's software renderer (Burning's Video): the
// regions a culler kept, from a pvs::Camera, into an RGBA image. No window, no display, no GPU:
// the console device (EIDT_CONSOLE) owns a Burning's Video driver that draws into a render-target
// texture, which is read back with lock(). This header does not expose Irrlicht.
//
// Modes:
//  - Textured: the materials' pixels (nearest texel, mipmapped), modulated by a fixed fake
//    light from the face normal so walls stay apart; materials without pixels get a flat colour.
//  - RegionColors: every face in the flat colour of the first visible region (ascending id) that
//    lists it; region_color(region) is stable across runs and machines.
//  - IdBuffer: every pixel holds face id + 1 (0 = background), see encode_id below. Exact: no
//    lighting, texture, filtering, fog, antialiasing or mipmaps are involved.
//  - Flags: the Textured picture with every face tinted by the flags of the first visible region
//    (ascending id) that lists it, in the colour kFlagTints gives that flag (water blue, lava
//    orange, ...); faces of regions without flags are exactly the Textured pixels. The tint is
//    blended into the material's texels before the fake light (kFlagTintAlpha, 50 %), by drawing
//    the face with a tinted copy of its texture (made once per material and tint, when first
//    needed): the same rasteriser, coverage and texel lookup as the Textured picture, no second
//    pass. A material without pixels has its flat colour tinted the same way. Which faces are
//    tinted follows the regions' face lists: a Quake leaf lists the faces that bound it from its
//    own side, so a liquid is tinted seen from inside it, not its surface seen from the air.
//
// The ID encoding and its limit. Burning's Video interpolates vertex colours perspective-correct
// (c/w interpolated, then multiplied by w) and truncates to 8 bits, so a constant colour c
// comes back as c or c - 1 in each channel (measured over 10^8 pixels of random triangles at
// every depth and angle: the difference is always 0 or -1, never anything else). So each channel
// carries 7 bits in its high bits with the low bit set: written 2b+1, read 2b+1 or 2b; before
// an IdBuffer or RegionColors image is returned, the low bit of every non-background channel is
// set back, which gives exactly the colour written. A full 24-bit code cannot survive the -1, so
// the limit is 21 bits: face id + 1 <= 2^21 - 1, i.e. at most kMaxIdFaces = 2,097,151 faces;
// render() throws for a larger zone in IdBuffer mode.
//
// Thread-safety: one SoftwareRenderer per thread. Creating and destroying one briefly points
// file descriptor 1 at /dev/null (the console device writes terminal escape codes to stdout)
// and restores the SIGINT/SIGTERM/SIGABRT handlers the device installs: do not create renderers
// while another thread writes to stdout or changes those handlers.
#pragma once

#include "visibility/camera.h"
#include "visibility/culler.h"
#include "visibility/zone.h"

#include <array>
#include <span>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace pvs::ui {

enum class RenderMode : uint8_t { Textured, RegionColors, IdBuffer, Flags };
inline constexpr std::array<RenderMode, 4> kRenderModes{RenderMode::Textured, RenderMode::RegionColors,
                                                        RenderMode::IdBuffer, RenderMode::Flags};
const char* render_mode_name(RenderMode mode); // "textured", "regions", "ids", "flags"
std::optional<RenderMode> parse_render_mode(std::string_view name);

struct Image {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba; // width*height*4 bytes, rows top to bottom, alpha always 255

    const uint8_t* pixel(uint32_t x, uint32_t y) const { return rgba.data() + (size_t(y) * width + x) * 4; }
};

// Writes an 8-bit RGBA PNG. Throws std::runtime_error naming the path when it cannot.
void save_png(const Image& image, const std::string& path);

// ---- Colour codes (0xRRGGBB) -------------------------------------------------------------------

inline constexpr uint32_t kIdBitsPerChannel = 7;
inline constexpr uint32_t kMaxIdValue = (1u << (3 * kIdBitsPerChannel)) - 1; // largest face id + 1
inline constexpr uint32_t kMaxIdFaces = kMaxIdValue; // faces 0 .. kMaxIdFaces-1 are encodable
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

// ---- Renderer ----------------------------------------------------------------------------------

struct RenderStats {
    double scene_ms = 0;   // building the Irrlicht scene from the zone (0 when it was reused)
    double draw_ms = 0;    // clearing, drawing and reading back the frame
    uint32_t faces_drawn = 0;
    uint64_t triangles_drawn = 0;
};

class SoftwareRenderer {
public:
    // Creates the console device, the Burning's Video driver and a width x height render target
    // (1 .. 8192 each). Throws std::runtime_error when Irrlicht cannot provide them.
    SoftwareRenderer(uint32_t width, uint32_t height);
    ~SoftwareRenderer();
    SoftwareRenderer(const SoftwareRenderer&) = delete;
    SoftwareRenderer& operator=(const SoftwareRenderer&) = delete;

    uint32_t width() const;
    uint32_t height() const;

    // Draws the faces of `visible_regions` (region ids; ids out of range are ignored) seen from
    // `camera`, each face once. The camera's own aspect is used as given (the culler used it too):
    // pass width/height for an undistorted picture. The scene built from `zone` (textures,
    // vertices) is kept while the same Zone object with the same buffers is passed again; call
    // forget_zone() after changing a zone in place. Throws std::runtime_error in IdBuffer mode
    // for a zone of more than kMaxIdFaces faces. `region_tints`, when not empty (one palette
    // index or kNoTint per region of the zone), tints each region's faces as Flags mode tints
    // them, in place of the mode's own tints (Textured and Flags modes).
    Image render(const Zone& zone, const Camera& camera, const std::vector<uint32_t>& visible_regions,
                 RenderMode mode, std::span<const uint32_t> region_tints = {});
    // The IdBuffer picture without the translucent faces (kMaterialTranslucent: Quake 2 glass
    // and translucent water): where render(..., IdBuffer) shows such a face, the face seen
    // through it (behind every translucent layer). The accuracy walk measures those faces too.
    Image render_ids_behind_translucent(const Zone& zone, const Camera& camera,
                                        const std::vector<uint32_t>& visible_regions);
    void forget_zone();
    const RenderStats& last_stats() const;

private:
    Image draw_frame(const Zone& zone, const Camera& camera, const std::vector<uint32_t>& visible_regions,
                     RenderMode mode, std::span<const uint32_t> region_tints, bool opaque_only);
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// ---- One culled frame --------------------------------------------------------------------------

// A frame as `pvscope render` makes it: the regions are culled from the culling camera and drawn
// seen from `view`. Normally the culling camera is `view` itself; with `locked_cull_camera` set
// (an inspector's "lock culling camera", Source's r_lockpvs) culling
// stays with that camera while the view moves, so what the culler keeps can be looked at from
// outside. The stats and the visible set are then the locked camera's (exactly what culling
// from it alone gives), and its view volume is drawn over the picture in kLockedFrustumColor
// (ui/overlay_lines.h), except in IdBuffer mode, whose pixels must stay face codes.
struct CulledFrame {
    CullStats cull;
    std::vector<uint32_t> visible; // region ids, ascending
    Image image;
};
CulledFrame render_culled(SoftwareRenderer& renderer, Culler& culler, const Camera& view,
                          const std::optional<Camera>& locked_cull_camera, const CullOptions& cull_options,
                          RenderMode mode);

} // namespace pvs::ui
