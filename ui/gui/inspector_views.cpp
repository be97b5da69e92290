// InspectorState's views beyond the frame itself: the overlays' inputs (camera path, node
// polygons, portals, what the PVS stage kept), the PVS source switch and the bake, the field of
// view and the orbit camera.
#include "ui/gui/inspector_state.h"

#include "ui/gui/camera_math.h"
#include "visibility/methods/vis_method.h"
#include "visibility/portal/portalize.h"
#include "gen/stability_cases.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace pvs::gui {

const char* pvs_source_name(PvsSource source)
{
    switch (source) {
    case PvsSource::File: return "file";
    case PvsSource::None: return "none";
    case PvsSource::Baked: return "baked";
    case PvsSource::Edited: return "edited";
    }
    return "?";
}

// ---- Overlays ----------------------------------------------------------------------------------

const std::vector<Winding>& InspectorState::node_polygons()
{
    if (!node_polygons_) {
        // The same world box as the portals: the zone with a margin, so no plane lies on it.
        node_polygons_ = zone_ ? node_plane_polygons(zone_->tree, zone_portal_world(*zone_)) : std::vector<Winding>{};
    }
    return *node_polygons_;
}

void InspectorState::request_portals()
{
    if (!zone_ || zone_->portals || built_portals_ || portal_build_.valid())
        return;
    portal_build_ = std::async(std::launch::async, [zone = zone_.get()] {
        try {
            return build_zone_portals(*zone);
        } catch (const std::exception&) { // bad_alloc on a hostile tree: no portals
            return PortalSet{};
        }
    });
}

void InspectorState::take_finished_portals()
{
    if (portal_build_.valid() && portal_build_.wait_for(std::chrono::seconds(0)) == std::future_status::ready)
        built_portals_ = portal_build_.get();
}

const PortalSet* InspectorState::ready_portals() const
{
    if (zone_ && zone_->portals)
        return &*zone_->portals;
    return built_portals_ ? &*built_portals_ : nullptr;
}

const PortalSet& InspectorState::wait_for_portals()
{
    static const PortalSet kNone;
    request_portals();
    if (portal_build_.valid())
        built_portals_ = portal_build_.get();
    const PortalSet* set = ready_portals();
    return set ? *set : kNone;
}

std::vector<uint32_t> InspectorState::regions_under(int32_t node) const
{
    std::vector<uint32_t> regions;
    if (!zone_)
        return regions;
    const BspTree& tree = zone_->tree;
    std::vector<int32_t> stack{node};
    std::vector<bool> seen(tree.nodes.size(), false); // a bad tree with a cycle must not hang
    while (!stack.empty()) {
        const int32_t child = stack.back();
        stack.pop_back();
        if (BspTree::is_leaf(child)) {
            const int32_t leaf = BspTree::leaf_index(child);
            if (size_t(leaf) < tree.leaf_region.size() && tree.leaf_region[size_t(leaf)] >= 0)
                regions.push_back(uint32_t(tree.leaf_region[size_t(leaf)]));
            continue;
        }
        if (size_t(child) >= tree.nodes.size() || seen[size_t(child)])
            continue;
        seen[size_t(child)] = true;
        stack.push_back(tree.nodes[size_t(child)].children[1]);
        stack.push_back(tree.nodes[size_t(child)].children[0]);
    }
    std::sort(regions.begin(), regions.end());
    regions.erase(std::unique(regions.begin(), regions.end()), regions.end());
    return regions;
}

void InspectorState::update_after_pvs()
{
    trace_point(zone_->tree, cull_.position, path_);
    path_nodes_.clear();
    for (const PathStep& step : path_)
        path_nodes_.push_back(step.node);
    if (!overlays.pvs_membership && !overlays.pvs_membership_boxes) {
        after_pvs_.clear();
        return;
    }
    // What the PVS stage alone keeps from the same camera (the frame's own stats keep only counts).
    const bool pvs_stage = cull_mode == CullMode::Pvs || cull_mode == CullMode::PvsFrustum;
    culler_->cull(cull_, {pvs_stage ? CullMode::Pvs : CullMode::None, false}, after_pvs_);
}

ui::OverlayScene InspectorState::overlay_scene()
{
    ui::OverlayScene scene;
    scene.zone = zone_.get();
    scene.view = view_;
    scene.cull = cull_;
    scene.locked = locked_;
    scene.cull_region = last_cull_.region;
    scene.cull_cell = last_cull_.cell;
    scene.visible = visible_;
    scene.after_pvs = after_pvs_;
    scene.area_culled = area_culled_;
    scene.path_nodes = path_nodes_;
    scene.highlighted_node = selected_node;
    if (overlays.split_planes)
        scene.node_polygons = &node_polygons();
    if (overlays.portals) {
        request_portals();
        scene.portals = ready_portals();
    }
    update_edited_pairs();
    scene.edited_regions = edited_pairs_;
    scene.pair = explanation_ ? &pair_overlay_ : nullptr;
    scene.closed_area_portals = closed_area_portals;
    return scene;
}

void InspectorState::paint_line_layer(ui::OverlayScene& scene)
{
    if (overlays.hidden_lines != ui::HiddenLines::Shown)
        scene.occlusion = picture_occlusion(); // depends on the regions drawn, not on the pixels
    ui::clear_layer(line_layer_, width_, height_);
    ui::paint_line_overlays(line_layer_, overlays, scene, overlay_lines_);
}

void InspectorState::paint_overlays(ui::OverlayScene& scene, const ui::Image* line_layer)
{
    labels_.clear();
    if (render_mode == ui::RenderMode::IdBuffer)
        return; // its pixels are face codes
    if (overlays.hidden_lines != ui::HiddenLines::Shown)
        scene.occlusion = picture_occlusion();
    ui::paint_overlays(image_, overlays, scene, labels_, line_layer);
    overlay_depth_rays_ = occlusion_ && scene.occlusion ? occlusion_->rays() : 0;
}

std::span<const uint32_t> InspectorState::drawn_regions() const
{
    const bool tinted = overlays.pvs_membership && render_mode != ui::RenderMode::IdBuffer;
    return tinted ? std::span<const uint32_t>(picture_regions_) : std::span<const uint32_t>(visible_);
}

const ui::PictureOcclusion* InspectorState::picture_occlusion()
{
    if (!zone_)
        return nullptr;
    if (!occlusion_) {
        try {
            occlusion_ = std::make_unique<ui::PictureOcclusion>(*zone_);
        } catch (const std::exception& e) {
            error_ = std::string("depth test of the overlay lines: ") + e.what();
            overlays.hidden_lines = ui::HiddenLines::Shown; // do not try again every frame
            return nullptr;
        }
    }
    if (occlusion_frame_ != frame_number_) {
        occlusion_->set_frame(*zone_, view_, width_, height_, drawn_regions()); // the size being rendered
        occlusion_frame_ = frame_number_;
    }
    return occlusion_.get();
}

void InspectorState::update_edited_pairs()
{
    edited_pairs_.clear();
    if (pvs_source_ != PvsSource::Edited || !editor_)
        return;
    // The row the culler uses: the view cell's on grid zones, the region's otherwise.
    const int32_t row = zone_->view_grid ? last_cull_.cell : last_cull_.region;
    if (row < 0 || uint32_t(row) >= editor_->row_count())
        return;
    for (uint32_t r = 0; r < editor_->region_count(); ++r)
        if (editor_->edited(uint32_t(row), r))
            edited_pairs_.push_back(r);
}

std::optional<HoverInfo> InspectorState::hover(uint32_t x, uint32_t y)
{
    if (!zone_ || x >= image_.width || y >= image_.height)
        return std::nullopt;
    const ui::PictureOcclusion* occlusion = picture_occlusion();
    if (!occlusion)
        return std::nullopt;
    const auto hit = occlusion->face_under(pixel_ray(view_, image_.width, image_.height, x, y).direction);
    if (!hit)
        return std::nullopt;
    HoverInfo info;
    info.face = hit->face;
    info.distance = hit->distance;
    info.regions = regions_of_face(hit->face);
    for (uint32_t r : info.regions)
        if (r < zone_->region_count())
            info.flags |= zone_->regions[r].flags;
    return info;
}

// ---- PVS source and bake -----------------------------------------------------------------------

bool InspectorState::has_pvs_source(PvsSource source) const
{
    switch (source) {
    case PvsSource::File: return zone_ && zone_->baked_pvs;
    case PvsSource::None: return zone_ != nullptr;
    case PvsSource::Baked: return zone_ && baked_pvs_;
    case PvsSource::Edited: return zone_ && edited_pvs_;
    }
    return false;
}

const Pvs* InspectorState::active_pvs() const
{
    if (!zone_)
        return nullptr;
    if (pvs_source_ == PvsSource::File && zone_->baked_pvs)
        return &*zone_->baked_pvs;
    if (pvs_source_ == PvsSource::Baked && baked_pvs_)
        return &*baked_pvs_;
    if (pvs_source_ == PvsSource::Edited && edited_pvs_)
        return &*edited_pvs_;
    return nullptr;
}

void InspectorState::rebuild_culler()
{
    culler_.reset();
    ++pvs_generation_;
    if (zone_)
        culler_ = std::make_unique<Culler>(*zone_, active_pvs());
}

bool InspectorState::set_pvs_source(PvsSource source)
{
    if (!has_pvs_source(source))
        return false;
    pvs_source_ = source;
    rebuild_culler();
    return true;
}

bool InspectorState::start_bake(const BakeRequest& request)
{
    return zone_ && bake_.start(*zone_, request);
}

bool InspectorState::start_compare(const ui::CompareOptions& options)
{
    if (!zone_)
        return false;
    ui::CompareOptions with_probe = options;
    if (!with_probe.memory_probe)
        with_probe.memory_probe = memory_probe_;
    return compare_.start(*zone_, with_probe);
}

bool InspectorState::start_check(const CheckOptions& options)
{
    if (!zone_)
        return false;
    const Zone& zone = *zone_;
    return check_.start(
        [&zone, options](JobControl& control) {
            control.set_stage("checking");
            return check_zone(zone, options);
        },
        [](const ZoneHealth&) { return true; }); // no cancel point: a check runs to its end
}

void InspectorState::go_to_check_place(const CheckPlace& place)
{
    if (zone_ && place.region >= 0 && size_t(place.region) < zone_->region_count()) {
        select_region(place.region);
        if (!place.has_point)
            go_to_region(uint32_t(place.region));
    }
    if (place.has_point)
        view_.position = place.point;
}

bool InspectorState::use_compared_pvs(size_t row)
{
    const std::optional<ui::CompareResult>& result = compare_.result();
    if (!zone_ || !result || row >= result->rows.size())
        return false;
    const ui::CompareRow& chosen = result->rows[row];
    if (!chosen.pvs)
        return set_pvs_source(PvsSource::None);
    baked_pvs_ = *chosen.pvs;
    baked_label_ = chosen.method + (chosen.params.empty() ? "" : " " + chosen.params);
    pvs_source_ = PvsSource::Baked;
    rebuild_culler();
    return true;
}

void InspectorState::poll_bake()
{
    if (bake_.status() != JobStatus::Running || bake_.poll() != JobStatus::Done)
        return;
    baked_pvs_ = bake_.take_result();
    const VisMethod* method = find_vis_method(bake_.request().method);
    const std::string settings = method ? method->label(bake_.request().settings) : std::string();
    baked_label_ = bake_.request().method + (settings.empty() ? "" : " " + settings);
    baked_summary_ = bake_.report().summary;
    ++pvs_generation_;
    if (pvs_source_ == PvsSource::Baked)
        rebuild_culler(); // it pointed at the previous bake
}

// ---- Camera ------------------------------------------------------------------------------------

void InspectorState::set_fov(float degrees)
{
    view_.fov_y_degrees = std::isfinite(degrees) ? std::clamp(degrees, kMinFovDegrees, kMaxFovDegrees) : 70.0f;
    if (!locked_)
        cull_ = view_;
}

void InspectorState::set_orbit_target(std::optional<glm::vec3> target)
{
    orbit_target_ = target;
    if (target)
        aim_along(view_, *target - view_.position, kMaxPitchDegrees);
    if (!locked_)
        cull_ = view_;
}

void InspectorState::orbit(float yaw_degrees, float pitch_degrees)
{
    if (!orbit_target_)
        return;
    orbit_about(view_, *orbit_target_, yaw_degrees, pitch_degrees, kMaxPitchDegrees);
    if (!locked_)
        cull_ = view_;
}

} // namespace pvs::gui

namespace pvs::gui {

bool InspectorState::open_stability_case(const std::string& name, const std::string& method_name)
{
    const VisMethod* method = find_vis_method(method_name);
    if (!method || !method->bakes) {
        error_ = "'" + method_name + "' is not a method that bakes (" + vis_method_names() + ")";
        return false;
    }
    std::optional<gen::StabilityCase> crafted;
    try {
        crafted.emplace(gen::make_stability_case(name));
    } catch (const std::exception& e) {
        error_ = e.what();
        return false;
    }
    const auto start = std::chrono::steady_clock::now();
    auto zone = std::make_unique<Zone>(std::move(crafted->zone));
    adopt_zone(std::move(zone), std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    case_name_ = name;
    MethodSettings settings;
    settings.samples = 1024;
    MethodRun run = method->run(*zone_, settings);
    baked_pvs_ = std::move(run.pvs);
    baked_label_ = std::string(method->name) + " on case " + name;
    case_missing_.clear();
    for (uint32_t a = 0; a < crafted->truth.region_count(); ++a)
        for (uint32_t b = 0; b < crafted->truth.region_count(); ++b)
            if (crafted->truth.visible(a, b) && baked_pvs_ && !baked_pvs_->visible(a, b))
                case_missing_.push_back(crafted->region_names[a] + " -> " + crafted->region_names[b]);
    pvs_source_ = baked_pvs_ ? PvsSource::Baked : PvsSource::None;
    const Camera lens = view_;
    view_ = crafted->camera;
    view_.fov_y_degrees = lens.fov_y_degrees;
    view_.aspect = lens.aspect;
    if (!locked_)
        cull_ = view_;
    rebuild_culler();
    return true;
}

} // namespace pvs::gui
