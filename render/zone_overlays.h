// The inspector's overlays, drawn over a rendered picture on the CPU (ui/overlay_fill.h,
// ui/overlay_lines.h), each behind its own toggle, and the legend that names their colours:
//  - PVS membership: the class of each region this frame (membership_tints: the culling camera's
//    region, drawn, culled by the frustum — in the PVS but outside the view volume —, culled by
//    the PVS) as a tint of its faces: the caller renders every region with membership_tints
//    (depth-correct: a PVS-culled wall shows red only where it is really in sight). With
//    pvs_membership_boxes, each region's bounds box in its class colour too (wireframe, on top).
//  - BSP split planes: the plane of every node on the path from the root to the culling
//    camera's leaf, as a translucent polygon clipped to its node's cell (node_plane_polygons,
//    visibility/geometry/bsp_volume.h), the highlighted node (the BSP panel's selection, else
//    the deepest on the path) stronger; every plane's outline is drawn too, so planes that
//    overlap stay apart.
//  - Portals: the outline of every portal with a drawn region on either side.
//  - Region bounds: the bounds box of every drawn region in its region_color.
//  - Zone lines: each zone line's trigger box (its region's bounds when the file gives none) and
//    a label with its target, returned as text for the UI to draw (an Image has no font).
//  - Areaportals (Quake 2): each areaportal's brush box, open or closed (OverlayScene::
//    closed_area_portals), labelled with its number and areas.
//  - Locked frustum: the culling camera's view volume while it is locked (kLockedFrustumColor).
//  - View cell (grid zones: OBJ + .hepvs): the culling camera's grid cell, whose PVS row culls
//    (kViewCellColor); with PVS membership on, its objects are the drawn and frustum-culled boxes.
// Lines (plane outlines, portals, boxes, zone lines, the frustum, the view cell) are depth-tested
// when the scene carries a LineOcclusion (ui/picture_occlusion.h): the parts behind the
// picture's walls are drawn faint or hidden (OverlaySettings::hidden_lines). The translucent
// plane fills are not tested (one ray per filled pixel would cost a frame); their outlines are.
// IdBuffer pictures must stay face codes, so callers do not paint them.
#pragma once

#include "render/line_batch.h"
#include "render/overlay_lines.h"
#include "render/software_renderer.h"
#include "visibility/camera.h"
#include "visibility/geometry/winding.h"
#include "visibility/zone.h"

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace pvs::ui {

struct OverlaySettings {
    // PVS membership as a tint of the faces themselves (depth-correct: every region is drawn,
    // tinted by its Membership); the boxes of the first version are an option of their own.
    bool pvs_membership = false;
    bool pvs_membership_boxes = false;
    bool split_planes = false;
    bool portals = false;
    bool region_bounds = false;
    bool zone_lines = true;
    bool area_portals = true; // Quake 2: areaportal brushes, open or closed, labelled
    bool locked_frustum = true;
    bool view_cell = true;
    bool pair_view = true; // the explained pair's sight line and portal chain (OverlayScene::pair)
    // Lines behind the picture's walls (needs OverlayScene::occlusion; Shown = no depth test).
    HiddenLines hidden_lines = HiddenLines::Faint;
};
const char* hidden_lines_name(HiddenLines mode); // shown, faint, hidden

// A region's part in this frame's culling.
// CulledByArea: in the PVS and the frustum, but in an area a shut Quake 2 areaportal cuts off.
enum class Membership : uint8_t { Current, Drawn, CulledByFrustum, CulledByPvs, CulledByArea };

// Colours (0xRRGGBB) and fill weights (out of 256).
inline constexpr uint32_t kCurrentRegionColor = kMembershipTints[0]; // the same colours tint the faces
inline constexpr uint32_t kDrawnRegionColor = kMembershipTints[1];
inline constexpr uint32_t kFrustumCulledColor = kMembershipTints[2];
inline constexpr uint32_t kPvsCulledColor = kMembershipTints[3];
inline constexpr uint32_t kAreaCulledColor = kMembershipTints[4];
inline constexpr uint32_t kSplitPlaneColor = 0x30C0FF;
inline constexpr uint32_t kCurrentSplitPlaneColor = 0xFFE040;
inline constexpr uint32_t kPortalColor = 0x00FFC0;
inline constexpr uint32_t kZoneLineColor = 0xFF00FF; // as kFlagTints' zone line
inline constexpr uint32_t kOpenAreaPortalColor = 0x40FF80;
inline constexpr uint32_t kClosedAreaPortalColor = 0xFF4040;
inline constexpr uint32_t kViewCellColor = 0x60A0FF;
inline constexpr uint32_t kEditedPairColor = 0xFF60FF;
inline constexpr uint32_t kSightLineColor = 0xFF8000;  // the explained pair's witness
inline constexpr uint32_t kChainPortalColor = 0x40FF40; // its chain's portals, numbered
inline constexpr uint32_t kChainWindowColor = 0xFFFFFF; // the part of each the flow still saw
inline constexpr uint32_t kSplitPlaneAlpha = 24; // a dozen planes overlap: keep each faint
inline constexpr uint32_t kCurrentSplitPlaneAlpha = 90;

uint32_t membership_color(Membership membership);
// One tint palette index (kMembershipTintBase + Membership) per region of `zone`, into `out`:
// `current` (the culling camera's region, or -1) Current; the regions of `visible` Drawn; the
// others of `after_pvs` (what the PVS stage kept, every region when it did not run)
// CulledByFrustum, but those of `area_culled` (regions the frustum kept that shut areaportals
// then dropped) CulledByArea; the rest CulledByPvs.
void membership_tints(const Zone& zone, int32_t current, std::span<const uint32_t> visible,
                      std::span<const uint32_t> after_pvs, std::vector<uint32_t>& out,
                      std::span<const uint32_t> area_culled = {});
const char* membership_name(Membership membership);

// An explained pair (visibility/eval/pair_explanation.h) as the overlay draws it: the sight line
// from A to B, and per step of the flow's chain the portal crossed and the window seen through it.
struct PairOverlay {
    std::optional<std::array<glm::vec3, 2>> sight_line;
    std::vector<std::vector<glm::vec3>> chain_portals; // in chain order: labelled 1, 2, ...
    std::vector<std::vector<glm::vec3>> chain_windows; // empty entries where none is drawn
};

// One frame's inputs. Spans and pointers are borrowed for the call; null / empty = not available
// (that overlay then draws nothing).
struct OverlayScene {
    const Zone* zone = nullptr;
    Camera view;                         // the picture's camera (its aspect = the image's)
    Camera cull;                         // the culling camera
    bool locked = false;                 // cull is locked (draw its frustum)
    int32_t cull_region = -1;            // the culling camera's region
    int32_t cull_cell = -1;              // grid zones: the culling camera's view cell
    std::span<const uint32_t> visible;   // drawn regions, ascending
    std::span<const uint32_t> after_pvs; // kept by the PVS stage, ascending
    std::span<const uint32_t> area_culled; // kept by the frustum, dropped by shut areaportals
    std::span<const uint32_t> path_nodes; // node indices root -> camera leaf
    int32_t highlighted_node = -1;       // -1: the deepest of path_nodes
    const std::vector<Winding>* node_polygons = nullptr; // per node (node_plane_polygons)
    const PortalSet* portals = nullptr;
    const LineOcclusion* occlusion = nullptr; // depth test of the lines (null: none)
    // Regions r whose pair (cull_region, r) a hand edit changed (ascending): boxed in
    // kEditedPairColor so the edits show where they act.
    std::span<const uint32_t> edited_regions;
    const PairOverlay* pair = nullptr; // the explained pair (null: none)
    std::span<const uint8_t> closed_area_portals; // per Zone::area_portals entry: 1 = closed
};

// A text label at a pixel of the picture (a zone line's target).
struct OverlayLabel {
    glm::vec2 pixel;
    std::string text;
    uint32_t rgb;
};

// The many-line overlays (membership boxes, region bounds, portals), their segments joined where
// they share lines (ui/line_batch.h), drawn into `image`: the picture, or a transparent layer
// (new_layer) that paint_overlays composites in their place, which a caller can draw while the
// picture renders (the inspector does, on its second core: they need no picture, only the
// scene's occlusion, which depends on the regions drawn, not on the pixels). `lines` is working
// memory, reused across frames. Returns the pixels set.
struct OverlayLines {
    LineBatch membership_boxes, region_bounds, portals;
    std::vector<uint32_t> tints, by_class[5]; // the membership boxes' classes
    std::vector<uint8_t> drawn;               // per region, for the portals
};
uint32_t paint_line_overlays(Image& image, const OverlaySettings& settings, const OverlayScene& scene,
                             OverlayLines& lines);

// Draws the enabled overlays into `image` (back to front: planes, boxes, portals, zone lines,
// frustum) and replaces `labels` with the labels to draw over it. With `line_layer`, the
// many-line overlays are that layer (paint_line_overlays into new_layer) composited over the
// planes instead of being drawn here.
void paint_overlays(Image& image, const OverlaySettings& settings, const OverlayScene& scene,
                    std::vector<OverlayLabel>& labels, const Image* line_layer = nullptr);

// The legend: a name and colour per colour the enabled overlays use, in drawing order.
struct LegendEntry {
    const char* name;
    uint32_t rgb;
};
// grid_zone: the zone has a view grid (its view cell overlay is then listed); edited_pairs: the
// hand-edited pairs are boxed this frame; pair: an explained pair is drawn; area_portals: the
// zone has Quake 2 areaportals.
std::vector<LegendEntry> overlay_legend(const OverlaySettings& settings, bool grid_zone = false,
                                        bool edited_pairs = false, bool pair = false, bool area_portals = false);

} // namespace pvs::ui
