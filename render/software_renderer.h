// Headless rendering of a zone with Irrlicht 1.8's software renderer (Burning's Video): the
// regions a culler kept, from a pvs::Camera, into an RGBA image. No window, no display, no GPU:
// the console device (EIDT_CONSOLE) owns a Burning's Video driver that draws into a render-target
// texture, which is read back with lock(). This header does not expose Irrlicht.
//
// Modes:
//  - Textured: the materials' pixels (nearest texel, mipmapped), modulated by a fixed fake
//    light from the face normal so walls stay apart; materials without pixels get a flat colour,
//    and those and materials of one colour (stand-ins: Quake 2's textures live outside the map)
//    a stronger light by normal (zone_scene.cpp), their only cue for walls, floors and ceilings.
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

#include "render/colour_codes.h"
#include "render/image.h"
#include "render/render_mode.h"
#include "visibility/camera.h"
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

} // namespace pvs::ui
