#include "ui/gui/inspector_state.h"

#include "gen/demo_zone.h"
#include "ui/gui/camera_math.h"
#include "visibility/area_flood.h"
#include "visibility/math/frustum.h"
#include "visibility/region_lookup.h"
#include "wld/player_start.h"
#include "wld/zone_file.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace pvs::gui {

namespace {

double ms_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// How far a point can go from `from` along the horizontal `direction` and stay in regions
// (sampled every `step`, up to `limit`).
float free_distance(const Zone& zone, glm::vec3 from, glm::vec3 direction, float step, float limit)
{
    float t = 0.0f;
    while (t + step <= limit && locate_point(zone.tree, from + direction * (t + step)).in_region())
        t += step;
    return t;
}

struct StartView {
    glm::vec3 position;
    float yaw_degrees;
    float pitch_degrees = -10.0f; // a little floor in the picture
};

// Regions a first view should not stand in: the void above a Quake level, a zone line (an
// outdoor zone's edge, facing the next zone), and liquids.
// A first view that culls to fewer regions than this looks at a wall.
constexpr size_t kFirstViewRegions = 20;

constexpr uint32_t kNoStartFlags = kRegionSky | kRegionZoneLine | kRegionWater | kRegionLava | kRegionSlime;

// The view a zone opens with when the map names no player start: from the centres of its
// largest regions (whose centre is in them; a Quake leaf's box can stick out of its convex
// volume), the one of 8 horizontal directions with the longest free line of sight, so the first
// picture looks down a room or corridor rather than at a wall. About 32 x 8 x 512 point lookups.
std::optional<StartView> find_start_view(const Zone& zone, float diagonal)
{
    constexpr size_t kCandidates = 32;
    constexpr int kDirections = 8;
    std::vector<std::pair<float, uint32_t>> by_volume; // (volume, region)
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        const Aabb& b = zone.regions[r].bounds;
        if (b.empty() || zone.regions[r].flags & kNoStartFlags)
            continue;
        const glm::vec3 s = b.size();
        by_volume.emplace_back(s.x * s.y * s.z, r);
    }
    std::sort(by_volume.begin(), by_volume.end(), std::greater<>());
    const float step = std::max(diagonal / 512.0f, 1.0f), limit = diagonal / 2.0f;
    std::optional<StartView> best;
    float best_distance = -1.0f;
    size_t tried = 0;
    for (const auto& [volume, r] : by_volume) {
        const glm::vec3 centre = zone.regions[r].bounds.center();
        if (locate_point(zone.tree, centre).region != int32_t(r))
            continue;
        for (int d = 0; d < kDirections; ++d) {
            const float yaw = float(d) * (360.0f / kDirections);
            const glm::vec3 direction{std::cos(glm::radians(yaw)), std::sin(glm::radians(yaw)), 0.0f};
            const float distance = free_distance(zone, centre, direction, step, limit);
            if (distance > best_distance) {
                best_distance = distance;
                best = StartView{centre, yaw};
            }
        }
        if (++tried == kCandidates)
            break;
    }
    return best;
}

// Where the map puts its player (wld/player_start.h), when that point is in an open region,
// facing the map's angle unless that looks at a near wall: then the one of 8 horizontal
// directions with the longest free line of sight (a start in a booth or facing a door).
std::optional<StartView> player_start_view(const Zone& zone, float diagonal)
{
    const std::optional<PlayerStart> start = find_zone_player_start(zone);
    if (!start || !locate_point(zone.tree, start->eye).in_region())
        return std::nullopt;
    const float step = std::max(diagonal / 512.0f, 1.0f), limit = diagonal / 2.0f;
    const auto free_along = [&](float yaw) {
        const glm::vec3 direction{std::cos(glm::radians(yaw)), std::sin(glm::radians(yaw)), 0.0f};
        return free_distance(zone, start->eye, direction, step, limit);
    };
    float longest_yaw = start->yaw_degrees, longest = free_along(start->yaw_degrees);
    const float own = longest;
    for (int d = 1; d < 8; ++d) {
        const float yaw = start->yaw_degrees + float(d) * 45.0f, distance = free_along(yaw);
        if (distance > longest) {
            longest = distance;
            longest_yaw = yaw;
        }
    }
    return StartView{start->eye, own >= 0.5f * longest ? start->yaw_degrees : longest_yaw, 0.0f};
}

} // namespace

InspectorState::InspectorState() = default;
InspectorState::~InspectorState() = default;

// ---- Zone --------------------------------------------------------------------------------------

bool InspectorState::open_zone(const std::string& path, const ZoneLoadOptions& load)
{
    try {
        const auto start = std::chrono::steady_clock::now();
        auto zone = std::make_unique<Zone>(load_zone(path, load));
        adopt_zone(std::move(zone), ms_since(start));
        zone_load_ = load;
        return true;
    } catch (const std::exception& e) { // FileError for bad files; bad_alloc and the like too
        error_ = e.what();
        return false;
    }
}

void InspectorState::open_demo()
{
    const auto start = std::chrono::steady_clock::now();
    auto zone = std::make_unique<Zone>(gen::demo_zone()); // made once, then read from the cache
    adopt_zone(std::move(zone), ms_since(start));
}

void InspectorState::adopt_zone(std::unique_ptr<Zone> zone, double load_ms)
{
    // The bake, the culler and the renderer's scene borrow the old zone: stop and drop them
    // before it goes.
    bake_.stop();
    compare_.stop();
    check_.stop();
    if (portal_build_.valid())
        portal_build_.wait(); // it reads the zone about to go
    portal_build_ = {};
    clear_explanation(); // waits for a job in flight: it reads the zone too
    occlusion_.reset();
    occlusion_frame_ = 0;
    culler_.reset();
    if (renderer_)
        renderer_->forget_zone();
    zone_ = std::move(zone);
    ++zone_generation_;
    load_ms_ = load_ms;
    error_.clear();
    zone_stats_ = compute_zone_stats(*zone_);
    face_regions_ = build_face_regions(*zone_);
    baked_pvs_.reset();
    editor_.reset();
    edited_pvs_.reset();
    baked_summary_.clear();
    node_polygons_.reset();
    built_portals_.reset();
    selected_node = -1;
    orbit_target_.reset();
    case_name_.clear();
    case_missing_.clear();
    closed_area_portals.assign(zone_->area_portals.size(), 0); // every door open, as vis sees them
    area_dropped_ = 0;
    pvs_source_ = zone_->baked_pvs ? PvsSource::File : PvsSource::None;
    rebuild_culler();

    image_ = {};
    visible_.clear();
    last_cull_ = {};
    last_render_ = {};
    history_.clear();
    totals_ = {};
    selection_ = {};
    locked_ = false;
    const glm::vec3 size = zone_stats_.bounds.empty() ? glm::vec3(3200.0f) : zone_stats_.bounds.size();
    set_move_speed(glm::length(size) / 10.0f);
    reset_camera();
}

std::span<const uint32_t> InspectorState::regions_of_face(uint32_t face) const { return face_regions_.of(face); }

uint64_t InspectorState::region_triangles(uint32_t region) const
{
    if (!zone_ || region >= zone_->region_count())
        return 0;
    uint64_t triangles = 0;
    for (uint32_t face : zone_->faces_of_region(region))
        if (face < zone_->mesh.faces.size())
            triangles += zone_->mesh.faces[face].triangle_count;
    return triangles;
}

// ---- Cameras -----------------------------------------------------------------------------------

void InspectorState::set_lock(bool locked)
{
    locked_ = locked;
    if (!locked_)
        cull_ = view_;
}

void InspectorState::set_move_speed(float speed)
{
    move_speed_ = std::isfinite(speed) ? std::clamp(speed, 1.0f, 100000.0f) : 320.0f;
}

void InspectorState::step_camera(const CameraInput& input, float dt_seconds)
{
    if (input.wheel != 0.0f)
        set_move_speed(move_speed_ * std::pow(kSpeedStep, input.wheel));
    // Mouse right turns right: yaw is counter-clockwise about +z, so it decreases.
    view_.yaw_degrees = std::remainder(view_.yaw_degrees - input.look.x * kLookDegreesPerPixel, 360.0f);
    view_.pitch_degrees =
        std::clamp(view_.pitch_degrees - input.look.y * kLookDegreesPerPixel, -kMaxPitchDegrees, kMaxPitchDegrees);

    const glm::vec3 forward = view_.forward();
    const float yaw = glm::radians(view_.yaw_degrees);
    const glm::vec3 right{std::sin(yaw), -std::cos(yaw), 0.0f}; // forward's horizontal part turned -90°
    glm::vec3 move{0.0f};
    move += forward * (float(input.forward) - float(input.back));
    move += right * (float(input.right) - float(input.left));
    move.z += float(input.up) - float(input.down);
    if (glm::length(move) > 0.0f && dt_seconds > 0.0f)
        view_.position += glm::normalize(move) * move_speed_ * (input.fast ? kFastFactor : 1.0f) * dt_seconds;
    if (!locked_)
        cull_ = view_;
}

void InspectorState::reset_camera()
{
    view_ = Camera{};
    view_.aspect = float(width_) / float(height_);
    if (zone_ && !zone_stats_.bounds.empty()) {
        const float diagonal = glm::length(zone_stats_.bounds.size());
        view_.far_distance = std::max(view_.far_distance, diagonal * 2.0f);
        view_.position = zone_stats_.bounds.center();
        const auto regions_seen_from = [&](const StartView& v) {
            Camera c = view_;
            c.position = v.position;
            c.yaw_degrees = v.yaw_degrees;
            c.pitch_degrees = v.pitch_degrees;
            std::vector<uint32_t> seen;
            culler_->cull(c, CullOptions{}, seen);
            return seen.size();
        };
        std::optional<StartView> start = player_start_view(*zone_, diagonal);
        if (start && culler_ && regions_seen_from(*start) < kFirstViewRegions)
            start.reset(); // a start in a booth or before a door: the view down the largest room instead
        if (!start)
            start = find_start_view(*zone_, diagonal);
        if (start) {
            view_.position = start->position;
            view_.yaw_degrees = start->yaw_degrees;
            view_.pitch_degrees = start->pitch_degrees;
        }
    }
    cull_ = view_;
}

void InspectorState::go_to_region(uint32_t region)
{
    if (!zone_ || region >= zone_->region_count() || zone_->regions[region].bounds.empty())
        return;
    view_.position = zone_->regions[region].bounds.center();
    if (!locked_)
        cull_ = view_;
}

// ---- Frame -------------------------------------------------------------------------------------

void InspectorState::set_viewport_size(uint32_t width, uint32_t height)
{
    width_ = std::clamp<uint32_t>(width, 1, 8192);
    height_ = std::clamp<uint32_t>(height, 1, 8192);
}

void InspectorState::ensure_renderer()
{
    if (renderer_ && renderer_->width() == width_ && renderer_->height() == height_)
        return;
    renderer_.reset(); // one Irrlicht device at a time
    renderer_ = std::make_unique<ui::SoftwareRenderer>(width_, height_);
}

const CullStats& InspectorState::frame()
{
    if (!zone_)
        return last_cull_;
    view_.aspect = float(width_) / float(height_);
    view_.far_distance = far_clip > 0.0f ? far_clip : Camera{}.far_distance;
    if (!locked_)
        cull_ = view_;

    poll_bake();
    compare_.poll();
    check_.poll();
    take_finished_portals();
    take_finished_explanation();
    ++frame_number_; // first: the overlays' per-frame caches key on it
    CullOptions cull_options{cull_mode, true};
    cull_options.distance_stage = far_clip > 0.0f;
    last_cull_ = culler_->cull(cull_, cull_options, visible_);
    area_dropped_ = 0;
    area_culled_.clear();
    if (!zone_->area_portals.empty() && last_cull_.region >= 0 && size_t(last_cull_.region) < zone_->region_areas.size()) {
        const std::vector<uint8_t> reached =
            areas_reached(*zone_, zone_->region_areas[size_t(last_cull_.region)], closed_area_portals);
        area_culled_ = visible_;
        area_dropped_ = keep_reached_areas(*zone_, reached, visible_);
        last_cull_.regions_after_frustum -= uint32_t(area_dropped_);
        // What the areaportals dropped (both lists ascending), for the membership overlay.
        const auto end = std::set_difference(area_culled_.begin(), area_culled_.end(), visible_.begin(),
                                             visible_.end(), area_culled_.begin());
        area_culled_.erase(end, area_culled_.end());
    }
    update_after_pvs();
    try {
        ensure_renderer();
        const bool tinted = overlays.pvs_membership && render_mode != ui::RenderMode::IdBuffer;
        if (tinted) {
            // Every region the picture's frustum holds (the culler's own test: the others cannot
            // show), tinted by its part in this frame's culling: the depth test decides which of
            // them show, so a red (PVS-culled) face in sight is a region the PVS drops.
            const Frustum picture = Frustum::from_view_projection(view_.view_projection());
            picture_regions_.clear();
            for (uint32_t r = 0; r < zone_->region_count(); ++r)
                if (picture.intersects(zone_->regions[r].bounds))
                    picture_regions_.push_back(r);
            ui::membership_tints(*zone_, last_cull_.region, visible_, after_pvs_, region_tints_, area_culled_);
        }
        // The many-line overlays need no picture: they are drawn into a layer on the second
        // core while the picture renders, and composited in their place (ui/overlay_layer.h).
        ui::OverlayScene scene = overlay_scene();
        std::future<void> layer_job;
        if (render_mode != ui::RenderMode::IdBuffer &&
            (overlays.pvs_membership_boxes || overlays.region_bounds || overlays.portals))
            layer_job = std::async(std::launch::async, [&] { paint_line_layer(scene); });
        if (tinted)
            image_ = renderer_->render(*zone_, view_, picture_regions_, render_mode, region_tints_);
        else
            image_ = renderer_->render(*zone_, view_, visible_, render_mode);
        const auto overlays_start = std::chrono::steady_clock::now();
        const bool layered = layer_job.valid();
        if (layered)
            layer_job.get();
        last_render_ = renderer_->last_stats();
        paint_overlays(scene, layered ? &line_layer_ : nullptr);
        last_overlay_ms_ =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - overlays_start).count();
    } catch (const std::exception& e) { // no renderer, or an ID render of a zone too large to encode
        error_ = e.what();
        image_ = {};
        last_render_ = {};
        last_overlay_ms_ = 0;
        labels_.clear();
    }

    const CullStats& s = last_cull_;
    const FrameTimes times{float(s.lookup_us), float(s.pvs_us), float(s.distance_us), float(s.frustum_us),
                           float(last_render_.draw_ms)};
    history_.push(times);
    CullTotals& t = totals_;
    ++t.frames;
    t.lookup_us += s.lookup_us;
    t.pvs_us += s.pvs_us;
    t.distance_us += s.distance_us;
    t.frustum_us += s.frustum_us;
    t.render_ms += last_render_.draw_ms;
    t.max_cull_us = std::max(t.max_cull_us, double(times.cull_us()));
    t.max_render_ms = std::max(t.max_render_ms, last_render_.draw_ms);
    t.regions_after_pvs += s.regions_after_pvs;
    t.regions_drawn += s.regions_after_frustum;
    t.triangles_after_pvs += s.triangles_after_pvs;
    t.triangles_drawn += s.triangles_after_frustum;
    t.frames_in_region += s.camera == CameraPlace::InRegion ? 1 : 0;
    t.frames_pvs_used += s.pvs_used ? 1 : 0;
    return last_cull_;
}

// ---- Selection ---------------------------------------------------------------------------------

std::optional<Selection> InspectorState::pick(uint32_t x, uint32_t y)
{
    selection_ = {};
    if (!zone_ || !renderer_ || x >= image_.width || y >= image_.height || renderer_->width() != image_.width ||
        renderer_->height() != image_.height)
        return std::nullopt;
    // The same camera and visible set as the picture, so what is picked is what was drawn.
    uint32_t face = ui::kNoFace;
    try {
        face = ui::face_at(renderer_->render(*zone_, view_, visible_, ui::RenderMode::IdBuffer), x, y);
    } catch (const std::exception& e) { // more faces than an ID buffer can encode
        error_ = e.what();
    }
    if (face == ui::kNoFace)
        return std::nullopt;
    selection_.face = face;
    selection_.point = pixel_point(*zone_, view_, image_.width, image_.height, x, y);
    const auto regions = regions_of_face(face);
    selection_.face_regions.assign(regions.begin(), regions.end());
    // The region that drew it: the first visible one (ascending), as RegionColors colours it.
    for (uint32_t r : regions)
        if (std::binary_search(visible_.begin(), visible_.end(), r)) {
            selection_.region = int32_t(r);
            break;
        }
    if (selection_.region < 0 && !regions.empty())
        selection_.region = int32_t(regions.front());
    return selection_;
}

void InspectorState::select_region(int32_t region)
{
    selection_ = {};
    if (zone_ && region >= 0 && size_t(region) < zone_->region_count())
        selection_.region = region;
}

int32_t InspectorState::shown_region() const
{
    if (selection_.region >= 0)
        return selection_.region;
    return last_cull_.region;
}

} // namespace pvs::gui
