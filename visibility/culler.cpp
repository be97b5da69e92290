#include "visibility/culler.h"

#include "visibility/bit_row.h"
#include "visibility/math/frustum.h"
#include "visibility/math/frustum_boxes.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace pvs {

namespace {
using Clock = std::chrono::steady_clock;

// The stage clock: one reading per stage boundary, each stage's time the difference of two
// consecutive readings. Disabled, it reads nothing (a clock read costs 30-80 ns on a VM, a
// tenth of a whole frame).
class StageClock {
public:
    explicit StageClock(bool enabled) : enabled_(enabled), last_(enabled ? Clock::now() : Clock::time_point{}) {}
    // Microseconds since the previous boundary (0 when disabled).
    double lap()
    {
        if (!enabled_)
            return 0.0;
        const Clock::time_point now = Clock::now();
        const double us = std::chrono::duration<double, std::micro>(now - last_).count();
        last_ = now;
        return us;
    }

private:
    bool enabled_;
    Clock::time_point last_;
};

std::vector<Aabb> region_bounds(const Zone& zone)
{
    std::vector<Aabb> bounds(zone.region_count());
    for (size_t r = 0; r < bounds.size(); ++r)
        bounds[r] = zone.regions[r].bounds;
    return bounds;
}
} // namespace

const char* cull_mode_name(CullMode mode)
{
    switch (mode) {
    case CullMode::None: return "none";
    case CullMode::Frustum: return "frustum";
    case CullMode::Pvs: return "pvs";
    case CullMode::PvsFrustum: return "pvs+frustum";
    }
    return "?";
}

std::optional<CullMode> parse_cull_mode(const std::string& name)
{
    for (CullMode m : {CullMode::None, CullMode::Frustum, CullMode::Pvs, CullMode::PvsFrustum})
        if (name == cull_mode_name(m))
            return m;
    return std::nullopt;
}

Culler::Culler(const Zone& zone, const Pvs* pvs)
    : zone_(&zone), pvs_(pvs), locator_(zone.tree, zone.bounds()), boxes_(region_bounds(zone)),
      words_(region_bounds(zone)), zone_bounds_(zone.bounds()), face_stamp_(zone.mesh.faces.size(), 0)
{
    plane_scale_ = words_.coordinate_scale();
    if (zone.region_count() >= kBlocksFrom) {
        blocks_.emplace(region_bounds(zone));
        plane_scale_ = std::max(plane_scale_, blocks_->coordinate_scale());
        every_region_.assign(bits::words_for(zone.region_count()), 0);
        bits::fill(every_region_, zone.region_count());
    }
    const uint64_t rows = zone.view_grid ? zone.view_grid->cell_count() : zone.region_count();
    if (pvs_ && pvs_->region_count() == zone.region_count() && pvs_->row_count() == rows)
        cursor_.emplace(*pvs_);
    else
        pvs_ = nullptr; // a PVS of another zone is unusable: cull as if there were none
}

uint64_t Culler::count_triangles(const std::vector<uint32_t>& regions)
{
    if (++stamp_ == 0) { // wrapped: restart the stamps
        std::fill(face_stamp_.begin(), face_stamp_.end(), 0);
        stamp_ = 1;
    }
    uint64_t triangles = 0;
    for (uint32_t r : regions)
        for (uint32_t f : zone_->faces_of_region(r))
            if (face_stamp_[f] != stamp_) {
                face_stamp_[f] = stamp_;
                triangles += zone_->mesh.faces[f].triangle_count;
            }
    return triangles;
}

bool Culler::far_plane_reaches_everything(const Camera& camera) const
{
    // The farthest corner of the zone's box from the camera, against the far distance.
    const glm::vec3 d = glm::max(glm::abs(zone_bounds_.min - camera.position), glm::abs(zone_bounds_.max - camera.position));
    return glm::dot(d, d) < camera.far_distance * camera.far_distance;
}

// The distance the far plane reaches from the eye: at the frustum's far corners.
static double far_plane_reach(const Camera& camera)
{
    const double tan_y = std::tan(glm::radians(double(camera.fov_y_degrees)) * 0.5);
    const double tan_x = tan_y * double(camera.aspect);
    return double(camera.far_distance) * std::sqrt(1.0 + tan_x * tan_x + tan_y * tan_y);
}

// The squared distance a region's box may be from the eye and be kept.
static float reach_limit(const Camera& camera)
{
    const double reach = far_plane_reach(camera);
    return float(reach * reach) * (1.0f + 1e-5f); // float rounding: never drop a reached box
}

// Keeps, in order, the first `count` regions whose box is within the far plane's reach.
size_t Culler::keep_near(const Camera& camera, std::vector<uint32_t>& regions, size_t count, CullWork& work) const
{
    work.boxes += uint32_t(count);
    const glm::vec3 eye = camera.position;
    const float limit = reach_limit(camera);
    size_t kept = 0;
    for (size_t i = 0; i < count; ++i) {
        regions[kept] = regions[i];
        kept += size_t(boxes_.squared_distance(regions[i], eye) <= limit);
    }
    return kept;
}

// Whether the frustum is the first stage after the PVS (no distance stage in between).
static bool frustum_now_possible(const FrustumBoxes::PlaneGroups* planes, bool want_distance)
{
    return planes != nullptr && !want_distance;
}

CullStats Culler::cull(const Camera& camera, const CullOptions& options, std::vector<uint32_t>& visible)
{
    CullStats stats;
    const auto region_count = static_cast<uint32_t>(zone_->region_count());
    stats.regions_total = region_count;

    // Stage 1: where is the camera? Its region (the tree), or in a grid zone its view cell.
    StageClock clock(options.time_stages);
    int32_t row_index = -1; // the PVS row to use: the region, or the grid cell
    if (zone_->view_grid) { // a forced value is a cell here: the rows are cells
        const uint64_t cells = zone_->view_grid->cell_count();
        row_index = !options.forced_region ? zone_->view_grid->cell_at(camera.position)
                    : *options.forced_region >= 0 && uint64_t(*options.forced_region) < cells ? *options.forced_region
                                                                                              : -1;
        stats.cell = row_index;
        stats.camera = row_index >= 0 ? CameraPlace::InRegion : CameraPlace::Outside;
    } else {
        PointLocation at;
        if (options.forced_region)
            at.region = *options.forced_region >= 0 && uint32_t(*options.forced_region) < region_count
                            ? *options.forced_region
                            : kLeafOutside;
        else
            at = locator_.locate(camera.position);
        row_index = at.region >= 0 ? at.region : -1;
        stats.region = row_index;
        stats.camera = at.region >= 0 ? CameraPlace::InRegion
                       : at.region == kLeafSolid ? CameraPlace::InSolid
                                                 : CameraPlace::Outside;
    }
    stats.lookup_us = clock.lap();

    // Stage 2: the PVS row (a view of the dense matrix, or a decoded compressed row), or none.
    const bool want_pvs = options.mode == CullMode::Pvs || options.mode == CullMode::PvsFrustum;
    stats.pvs_used = want_pvs && pvs_ && row_index >= 0;
    std::span<const uint64_t> row;
    bool add_own_region = false; // a damaged row that lacks the camera's own region (not in grid zones)
    if (stats.pvs_used) {
        row = cursor_->row(uint32_t(row_index));
        add_own_region = stats.region >= 0 && !bits::test(row, uint32_t(stats.region));
        stats.regions_after_pvs = uint32_t(bits::count(row)) + (add_own_region ? 1u : 0u);
    } else {
        stats.regions_after_pvs = region_count;
    }
    stats.pvs_us = clock.lap();

    // Stage 3 (optional): distance. The row's regions (or all of them) within the far plane's
    // reach, into `visible`; the frustum then tests those in place.
    const bool want_distance = options.distance_stage;
    const bool want_frustum = options.mode == CullMode::Frustum || options.mode == CullMode::PvsFrustum;
    const FrustumBoxes::PlaneGroups* planes = nullptr;
    if (want_frustum) {
        const Frustum frustum = Frustum::from_view_projection(camera.view_projection());
        FrustumBoxes::prepare(frustum,
                              far_plane_reaches_everything(camera) ? FrustumBoxes::Planes::SidesOnly
                                                                   : FrustumBoxes::Planes::All,
                              plane_scale_, planes_);
        planes = &planes_;
    }
    // Big zones with many candidates: whole blocks of ids at a time, for the distance and the
    // frustum (the same answers). A sparse row (a Quake map's ~150 of 1 200) is cheaper region by
    // region than the walk of the block tree over the whole zone.
    const size_t candidate_count = stats.pvs_used ? stats.regions_after_pvs : region_count;
    const bool by_blocks = blocks_ && !add_own_region && (planes || want_distance) && candidate_count >= kBlocksFrom;
    // The row a word at a time, through the word boxes (RowWordBoxes): a sparse row with the
    // frustum stage first.
    const bool by_words = !by_blocks && stats.pvs_used && frustum_now_possible(planes, want_distance) && !add_own_region;
    if (!(by_blocks && planes) && !by_words) // the block and word stages fill `visible` themselves
        visible.resize(stats.regions_after_pvs);
    size_t kept = 0;
    // The first stage after the PVS: every candidate is written and the count advances only for
    // the ones kept, no branch on the test's answer. With a distance stage the frustum runs after.
    const bool frustum_now = frustum_now_possible(planes, want_distance);
    const auto consider = [&](uint32_t r) {
        visible[kept] = r;
        kept += frustum_now ? size_t(boxes_.intersects(r, *planes)) : 1u;
    };
    if (by_blocks) {
        const std::span<const uint64_t> candidates = stats.pvs_used ? row : std::span<const uint64_t>(every_region_);
        std::span<const uint64_t> survivors = candidates;
        if (want_distance) {
            stats.pvs_us += clock.lap();
            near_.resize(candidates.size());
            stats.regions_after_distance =
                uint32_t(blocks_->keep_near(candidates, boxes_, camera.position, reach_limit(camera), near_, stats.work));
            survivors = near_;
            stats.distance_us = clock.lap();
        }
        if (planes) {
            // Into scratch of the zone's size, then only the kept ids into `visible`: growing
            // `visible` to the row's size would zero tens of thousands of entries a frame.
            block_out_.resize(region_count);
            kept = blocks_->collect(survivors, boxes_, *planes, block_scratch_, block_out_.data(), stats.work);
            visible.assign(block_out_.begin(), block_out_.begin() + std::ptrdiff_t(kept));
        } else {
            stats.work.row_words += uint32_t(survivors.size());
            bits::for_each_set(survivors, [&](size_t r) { visible[kept++] = uint32_t(r); });
        }
    } else if (by_words) {
        // Into scratch of the zone's size, then only the kept ids into `visible` (as the block stage).
        block_out_.resize(region_count);
        kept = words_.collect(row, boxes_, *planes, block_out_.data(), stats.work);
        visible.assign(block_out_.begin(), block_out_.begin() + std::ptrdiff_t(kept));
    } else if (stats.pvs_used) {
        stats.work.row_words += uint32_t(row.size());
        stats.work.boxes += frustum_now ? stats.regions_after_pvs : 0;
        bits::for_each_set(row, [&](size_t r) {
            if (add_own_region && r > size_t(stats.region)) { // keep the list ascending
                consider(uint32_t(stats.region));
                add_own_region = false;
            }
            consider(uint32_t(r));
        });
        if (add_own_region)
            consider(uint32_t(stats.region));
    } else if (frustum_now) {
        kept = boxes_.collect_all(*planes, visible.data()); // every region, four boxes at a time
        stats.work.boxes += region_count;
    } else {
        for (uint32_t r = 0; r < region_count; ++r)
            consider(r);
    }
    if (want_distance && !by_blocks) {
        stats.pvs_us += clock.lap(); // walking the row's bits is the PVS stage's work
        kept = keep_near(camera, visible, kept, stats.work);
        stats.regions_after_distance = uint32_t(kept);
        stats.distance_us = clock.lap();
        if (planes) {
            size_t inside = 0;
            stats.work.boxes += uint32_t(kept);
            for (size_t i = 0; i < kept; ++i) {
                visible[inside] = visible[i];
                inside += size_t(boxes_.intersects(visible[i], *planes));
            }
            kept = inside;
        }
    }
    visible.resize(kept);
    stats.frustum_us = clock.lap();
    stats.regions_after_frustum = static_cast<uint32_t>(visible.size());
    if (!want_distance)
        stats.regions_after_distance = stats.regions_after_pvs;

    if (options.count_triangles)
        count_stage_triangles(row, stats.region, stats, visible);
    return stats;
}

void Culler::count_stage_triangles(std::span<const uint64_t> row, int32_t region, CullStats& stats,
                                   const std::vector<uint32_t>& visible)
{
    stats.triangles_total = zone_->mesh.triangle_count();
    candidates_.clear();
    if (stats.pvs_used) {
        bits::for_each_set(row, [&](size_t r) { candidates_.push_back(uint32_t(r)); });
        if (region >= 0 && !bits::test(row, uint32_t(region)))
            candidates_.push_back(uint32_t(region));
        stats.triangles_after_pvs = count_triangles(candidates_);
    } else {
        stats.triangles_after_pvs = stats.triangles_total;
    }
    stats.triangles_after_frustum = count_triangles(visible);
}

} // namespace pvs
