#include "render/zone_overlays.h"

#include "render/line_batch.h"
#include "render/overlay_fill.h"
#include "render/overlay_layer.h"
#include "render/overlay_lines.h"
#include "visibility/math/frustum.h"

#include <algorithm>

namespace pvs::ui {

namespace {

void paint_split_planes(Image& image, const OverlayScene& scene, const LineProjection& lines)
{
    if (!scene.node_polygons || scene.path_nodes.empty())
        return;
    const int32_t highlighted = scene.highlighted_node >= 0 ? scene.highlighted_node : int32_t(scene.path_nodes.back());
    const std::vector<Winding>& polygons = *scene.node_polygons;
    for (uint32_t node : scene.path_nodes)
        if (node < polygons.size() && int32_t(node) != highlighted) {
            fill_polygon_3d(image, scene.view, polygons[node].points, kSplitPlaneColor, kSplitPlaneAlpha);
            outline_polygon_3d(image, lines, polygons[node].points, kSplitPlaneColor);
        }
    // The highlighted one last, so it reads on top; it may be a node off the path (a selection).
    if (highlighted >= 0 && size_t(highlighted) < polygons.size()) {
        const Winding& w = polygons[size_t(highlighted)];
        fill_polygon_3d(image, scene.view, w.points, kCurrentSplitPlaneColor, kCurrentSplitPlaneAlpha);
        outline_polygon_3d(image, lines, w.points, kCurrentSplitPlaneColor);
    }
}

// The boxes of the regions the picture's own frustum can show (an outdoor zone has tens of
// thousands; drawing every one cost 40 ms a frame), culled first so the drawn and current boxes
// end on top where edges meet.
void collect_membership_boxes(const OverlayScene& scene, OverlayLines& lines)
{
    const Zone& zone = *scene.zone;
    const Frustum view = Frustum::from_view_projection(scene.view.view_projection());
    for (std::vector<uint32_t>& list : lines.by_class)
        list.clear();
    membership_tints(zone, scene.cull_region, scene.visible, scene.after_pvs, lines.tints, scene.area_culled);
    for (uint32_t r = 0; r < zone.region_count(); ++r)
        if (view.intersects(zone.regions[r].bounds))
            lines.by_class[lines.tints[r] - kMembershipTintBase].push_back(r);
    for (Membership pass : {Membership::CulledByPvs, Membership::CulledByFrustum, Membership::CulledByArea,
                            Membership::Drawn, Membership::Current})
        for (uint32_t r : lines.by_class[size_t(pass)])
            lines.membership_boxes.add_box(zone.regions[r].bounds, membership_color(pass));
}

void collect_region_bounds(const OverlayScene& scene, LineBatch& edges)
{
    for (uint32_t r : scene.visible)
        if (r < scene.zone->region_count())
            edges.add_box(scene.zone->regions[r].bounds, region_color(r));
}

// The outlines of the portals with a drawn region on either side.
void collect_portals(const OverlayScene& scene, OverlayLines& lines)
{
    if (!scene.portals)
        return;
    std::vector<uint8_t>& drawn = lines.drawn;
    drawn.assign(scene.zone->region_count(), 0);
    for (uint32_t r : scene.visible)
        if (r < drawn.size())
            drawn[r] = 1;
    const auto is_drawn = [&](int32_t r) { return r >= 0 && size_t(r) < drawn.size() && drawn[size_t(r)]; };
    const PortalSet& set = *scene.portals;
    for (const Portal& p : set.portals) {
        if (!(is_drawn(p.regions[0]) || is_drawn(p.regions[1])) || size_t(p.first_point) + p.point_count > set.points.size())
            continue;
        lines.portals.add_outline(std::span(set.points).subspan(p.first_point, p.point_count), kPortalColor);
    }
}

// Quake 2 areaportals: each brush's box, green when open and red when closed, labelled.
void paint_area_portals(Image& image, const OverlayScene& scene, const LineProjection& lines,
                        std::vector<OverlayLabel>& labels)
{
    const std::vector<AreaPortal>& portals = scene.zone->area_portals;
    for (size_t p = 0; p < portals.size(); ++p) {
        const AreaPortal& portal = portals[p];
        if (portal.bounds.empty())
            continue;
        const bool closed = p < scene.closed_area_portals.size() && scene.closed_area_portals[p];
        const uint32_t colour = closed ? kClosedAreaPortalColor : kOpenAreaPortalColor;
        draw_box_3d(image, lines, portal.bounds, colour);
        if (const auto at = project_to_pixel(scene.view, image.width, image.height, portal.bounds.center()))
            if (at->x >= 0.0f && at->y >= 0.0f && at->x < float(image.width) && at->y < float(image.height))
                labels.push_back({*at,
                                  "areaportal " + std::to_string(portal.number) + " (areas " +
                                      std::to_string(portal.areas[0]) + "-" + std::to_string(portal.areas[1]) +
                                      (closed ? ") closed" : ") open"),
                                  colour});
    }
}

void paint_zone_lines(Image& image, const OverlayScene& scene, const LineProjection& lines,
                      std::vector<OverlayLabel>& labels)
{
    const Zone& zone = *scene.zone;
    std::vector<bool> drawn(zone.zone_lines.size(), false);
    auto show = [&](const Aabb& box, const std::string& target) {
        draw_box_3d(image, lines, box, kZoneLineColor);
        if (box.empty())
            return;
        if (const auto at = project_to_pixel(scene.view, image.width, image.height, box.center()))
            if (at->x >= 0.0f && at->y >= 0.0f && at->x < float(image.width) && at->y < float(image.height))
                labels.push_back({*at, "-> " + (target.empty() ? std::string("(no target)") : target), kZoneLineColor});
    };
    // A zone line with its own trigger box once; one without, at each region that leads there.
    for (size_t i = 0; i < zone.zone_lines.size(); ++i)
        if (!zone.zone_lines[i].bounds.empty()) {
            show(zone.zone_lines[i].bounds, zone.zone_lines[i].target);
            drawn[i] = true;
        }
    for (const Region& region : zone.regions) {
        if (!(region.flags & kRegionZoneLine))
            continue;
        const bool known = region.zone_line >= 0 && size_t(region.zone_line) < zone.zone_lines.size();
        if (known && drawn[size_t(region.zone_line)])
            continue;
        show(region.bounds, known ? zone.zone_lines[size_t(region.zone_line)].target : std::string());
    }
}

// The explained pair: its chain's portals numbered in order (the label at each one's centre),
// the windows the flow saw through them, and the sight line on top.
void paint_pair(Image& image, const OverlayScene& scene, const LineProjection& lines, std::vector<OverlayLabel>& labels)
{
    const PairOverlay& pair = *scene.pair;
    for (size_t k = 0; k < pair.chain_portals.size(); ++k) {
        const std::vector<glm::vec3>& polygon = pair.chain_portals[k];
        if (polygon.empty())
            continue;
        outline_polygon_3d(image, lines, polygon, kChainPortalColor);
        if (k < pair.chain_windows.size() && pair.chain_windows[k].size() >= 2)
            outline_polygon_3d(image, lines, pair.chain_windows[k], kChainWindowColor);
        glm::vec3 centre(0.0f);
        for (const glm::vec3& p : polygon)
            centre += p;
        centre /= float(polygon.size());
        if (const auto at = project_to_pixel(scene.view, image.width, image.height, centre))
            if (at->x >= 0.0f && at->y >= 0.0f && at->x < float(image.width) && at->y < float(image.height))
                labels.push_back({*at, std::to_string(k + 1), kChainPortalColor});
    }
    if (pair.sight_line)
        draw_line_3d(image, lines, (*pair.sight_line)[0], (*pair.sight_line)[1], kSightLineColor);
}

} // namespace

void membership_tints(const Zone& zone, int32_t current, std::span<const uint32_t> visible,
                      std::span<const uint32_t> after_pvs, std::vector<uint32_t>& out,
                      std::span<const uint32_t> area_culled)
{
    // A list at a time (a binary search per region cost milliseconds a frame on an outdoor zone).
    out.assign(zone.region_count(), kMembershipTintBase + uint32_t(Membership::CulledByPvs));
    const auto mark = [&](std::span<const uint32_t> regions, Membership membership) {
        for (uint32_t r : regions)
            if (r < out.size())
                out[r] = kMembershipTintBase + uint32_t(membership);
    };
    mark(after_pvs, Membership::CulledByFrustum);
    mark(area_culled, Membership::CulledByArea);
    mark(visible, Membership::Drawn);
    if (current >= 0 && size_t(current) < out.size())
        out[size_t(current)] = kMembershipTintBase + uint32_t(Membership::Current);
}

uint32_t membership_color(Membership membership)
{
    switch (membership) {
    case Membership::Current: return kCurrentRegionColor;
    case Membership::Drawn: return kDrawnRegionColor;
    case Membership::CulledByFrustum: return kFrustumCulledColor;
    case Membership::CulledByPvs: return kPvsCulledColor;
    case Membership::CulledByArea: return kAreaCulledColor;
    }
    return 0;
}

const char* membership_name(Membership membership)
{
    switch (membership) {
    case Membership::Current: return "camera's region";
    case Membership::Drawn: return "in PVS, drawn";
    case Membership::CulledByFrustum: return "in PVS, culled by frustum";
    case Membership::CulledByPvs: return "culled by PVS";
    case Membership::CulledByArea: return "in PVS and frustum, behind a shut areaportal";
    }
    return "?";
}

uint32_t paint_line_overlays(Image& image, const OverlaySettings& settings, const OverlayScene& scene,
                             OverlayLines& lines)
{
    lines.membership_boxes.clear();
    lines.region_bounds.clear();
    lines.portals.clear();
    if (!scene.zone || image.rgba.empty())
        return 0;
    if (settings.pvs_membership_boxes)
        collect_membership_boxes(scene, lines);
    if (settings.region_bounds)
        collect_region_bounds(scene, lines.region_bounds);
    if (settings.portals)
        collect_portals(scene, lines);
    LineProjection view(scene.view);
    view.occlusion = scene.occlusion;
    view.hidden_lines = settings.hidden_lines;
    return lines.membership_boxes.draw(image, view) + lines.region_bounds.draw(image, view) +
           lines.portals.draw(image, view);
}

void paint_overlays(Image& image, const OverlaySettings& settings, const OverlayScene& scene,
                    std::vector<OverlayLabel>& labels, const Image* line_layer)
{
    labels.clear();
    if (!scene.zone || image.rgba.empty())
        return;
    LineProjection lines(scene.view); // the camera's matrices, once for every line
    lines.occlusion = scene.occlusion;
    lines.hidden_lines = settings.hidden_lines;
    if (settings.split_planes)
        paint_split_planes(image, scene, lines);
    if (line_layer) {
        composite_layer(*line_layer, image);
    } else {
        static thread_local OverlayLines scratch;
        paint_line_overlays(image, settings, scene, scratch);
    }
    for (uint32_t r : scene.edited_regions)
        if (r < scene.zone->region_count())
            draw_box_3d(image, lines, scene.zone->regions[r].bounds, kEditedPairColor);
    if (settings.zone_lines)
        paint_zone_lines(image, scene, lines, labels);
    if (settings.area_portals)
        paint_area_portals(image, scene, lines, labels);
    if (settings.view_cell && scene.zone->view_grid && scene.cull_cell >= 0)
        draw_box_3d(image, lines, scene.zone->view_grid->cell_bounds(uint32_t(scene.cull_cell)), kViewCellColor);
    if (settings.locked_frustum && scene.locked)
        draw_frustum(image, lines, scene.cull, kLockedFrustumColor);
    if (settings.pair_view && scene.pair)
        paint_pair(image, scene, lines, labels);
}

const char* hidden_lines_name(HiddenLines mode)
{
    switch (mode) {
    case HiddenLines::Shown: return "shown";
    case HiddenLines::Faint: return "faint";
    case HiddenLines::Hidden: return "hidden";
    }
    return "?";
}

std::vector<LegendEntry> overlay_legend(const OverlaySettings& settings, bool grid_zone, bool edited_pairs, bool pair,
                                        bool area_portals)
{
    std::vector<LegendEntry> legend;
    if (settings.split_planes) {
        legend.push_back({"split plane on camera path", kSplitPlaneColor});
        legend.push_back({"current / selected split plane", kCurrentSplitPlaneColor});
    }
    if (settings.pvs_membership || settings.pvs_membership_boxes)
        for (Membership m : {Membership::Current, Membership::Drawn, Membership::CulledByFrustum,
                             Membership::CulledByPvs, Membership::CulledByArea})
            if (m != Membership::CulledByArea || area_portals)
                legend.push_back({membership_name(m), membership_color(m)});
    if (settings.region_bounds)
        legend.push_back({"drawn region bounds (region colour)", 0xC0C0C0});
    if (settings.portals)
        legend.push_back({"portal of a drawn region", kPortalColor});
    if (settings.zone_lines)
        legend.push_back({"zone line (-> target)", kZoneLineColor});
    if (settings.area_portals && area_portals) {
        legend.push_back({"areaportal, open", kOpenAreaPortalColor});
        legend.push_back({"areaportal, closed", kClosedAreaPortalColor});
    }
    if (settings.locked_frustum)
        legend.push_back({"locked culling frustum", kLockedFrustumColor});
    if (settings.view_cell && grid_zone)
        legend.push_back({"the camera's view cell (its PVS row)", kViewCellColor});
    if (edited_pairs)
        legend.push_back({"hand-edited pair with the camera's region", kEditedPairColor});
    if (pair && settings.pair_view) {
        legend.push_back({"sight line A -> B", kSightLineColor});
        legend.push_back({"portal chain A -> B (numbered)", kChainPortalColor});
        legend.push_back({"window the flow saw through", kChainWindowColor});
    }
    return legend;
}

} // namespace pvs::ui
