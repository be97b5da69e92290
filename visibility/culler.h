// The runtime culler: camera -> region (grid-started BSP walk) -> that region's PVS row ->
// distance test (optional: EverQuest clients clip at the zone's far plane / fog distance) ->
// frustum test of each remaining region's bounds -> the regions to draw.
//
// The frustum stage tests the row's regions' boxes branch-free, four planes at a time
// (FrustumBoxes; the same answers as Frustum::intersects), and uses only the four side planes
// when the far plane lies beyond the whole zone. A row reads a word of 64 regions at a time and
// tests one box per word before its regions' boxes (RowWordBoxes: the same answers). On zones of kBlocksFrom regions or more, a frame
// with kBlocksFrom candidates or more (after the PVS) first tests boxes over blocks of 64 regions
// that lie together and over a tree of such blocks (RegionBlocks: the same answers), so a frame of
// tens of thousands of regions tests one by one only those the frustum's boundary crosses.
// It walks the row's words directly, so a frame allocates nothing once `visible` has grown.
//
// Grid zones (Zone::view_grid: OBJ + .hepvs) find the camera's view cell on the grid instead
// of walking a tree, and cull with that cell's row; a camera off the grid is "outside".
//
// Policy for a camera that is not in a region (inside a wall, outside the world, NaN): the PVS
// stage is skipped and every region goes to the frustum test, and CullStats::camera says so.
// Engines do the same (Quake's leaf 0 and a missing row give the all-visible row): the frame is
// never empty and never stale. The camera's own region is always drawn, even if its row lacks
// its own bit (a damaged file; every vis tool sets it). A zone without a PVS, or mode None/Frustum, skips the PVS stage too.
//
// There is no cache keyed by camera position: every call walks the tree, because a camera that
// moved one unit may have crossed a split plane. The only reuse is the decoded row of a region
// (PvsRowCursor), keyed by the region the walk just found, which is exact.
//
// Not thread-safe: one Culler per thread. It borrows the zone and the PVS, which must outlive it.
#pragma once

#include "visibility/camera.h"
#include "visibility/math/frustum_boxes.h"
#include "visibility/pvs.h"
#include "visibility/region_blocks.h"
#include "visibility/region_locator.h"
#include "visibility/row_word_boxes.h"
#include "visibility/zone.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace pvs {

enum class CullMode : uint8_t { None, Frustum, Pvs, PvsFrustum };

// Zones with at least this many regions get the block stage (RegionBlocks), used on frames with at
// least this many candidates after the PVS.
inline constexpr size_t kBlocksFrom = 512;
const char* cull_mode_name(CullMode mode);
std::optional<CullMode> parse_cull_mode(const std::string& name); // "none", "frustum", "pvs", "pvs+frustum"

enum class CameraPlace : uint8_t { InRegion, InSolid, Outside };

struct CullStats {
    CameraPlace camera = CameraPlace::Outside;
    int32_t region = -1;          // the camera's region, or -1 (always -1 in a grid zone)
    int32_t cell = -1;            // grid zones: the camera's view cell (its PVS row), or -1
    bool pvs_used = false;        // false: no PVS, a mode without it, or the camera not in a region
    uint32_t regions_total = 0;
    uint32_t regions_after_pvs = 0;
    uint32_t regions_after_distance = 0; // = regions_after_pvs without CullOptions::far_distance
    uint32_t regions_after_frustum = 0; // = regions drawn
    // Distinct faces' triangles (a face listed by several regions counts once); filled only
    // when CullOptions::count_triangles is set.
    uint64_t triangles_total = 0;
    uint64_t triangles_after_pvs = 0;
    uint64_t triangles_after_frustum = 0;
    double lookup_us = 0, pvs_us = 0, distance_us = 0, frustum_us = 0;
    // The frame's work (cull_work.h), the same for the same zone, PVS and camera on any machine.
    CullWork work;
    double cull_us() const { return lookup_us + pvs_us + distance_us + frustum_us; }
};

struct CullOptions {
    CullMode mode = CullMode::PvsFrustum;
    bool count_triangles = false;
    // Fill CullStats' stage times. Tools want them; an engine's frame loop can save the four
    // clock reads (a few hundred ns on a VM) by turning them off.
    bool time_stages = true;
    // Cull from this region instead of locating the camera: for callers that decide the region
    // themselves, such as the stale region cache an engine keeps (eval/stale_region_cache.h),
    // whose popping pvscope measures. A value outside [0, regions) means "not in a region"
    // (CameraPlace::Outside). In a grid zone the value is a view cell (its rows are cells). Unset:
    // the tree walk (the grid lookup), as always.
    std::optional<int32_t> forced_region = std::nullopt;
    // A stage of its own after the PVS, for clients that clip at a far plane or fog distance
    // (EverQuest: the zone's far clip): drops every region whose box lies beyond the reach of the
    // camera's far plane (Camera::far_distance), a sphere of radius far_distance / cos(the half
    // diagonal of the field of view) about the eye. Nothing the far plane lets through is
    // dropped, and one test per region is cheaper than the frustum's six planes.
    bool distance_stage = false;
};

class Culler {
public:
    Culler(const Zone& zone, const Pvs* pvs);

    // Fills `visible` (region ids, ascending) and returns the stats. `visible` is reused across
    // frames so a frame allocates nothing once it has grown.
    CullStats cull(const Camera& camera, const CullOptions& options, std::vector<uint32_t>& visible);

    const Zone& zone() const { return *zone_; }

private:
    uint64_t count_triangles(const std::vector<uint32_t>& regions);
    void count_stage_triangles(std::span<const uint64_t> row, int32_t region, CullStats& stats,
                               const std::vector<uint32_t>& visible);
    bool far_plane_reaches_everything(const Camera& camera) const;
    size_t keep_near(const Camera& camera, std::vector<uint32_t>& regions, size_t count, CullWork& work) const;

    const Zone* zone_;
    const Pvs* pvs_;
    RegionLocator locator_;
    FrustumBoxes boxes_; // the regions' bounds, packed for the frustum stage
    // Zones of kBlocksFrom regions or more: boxes over runs of ids, so the frustum decides whole
    // blocks (region_blocks.h; the same answers), and the all-visible row for frames without a PVS.
    std::optional<RegionBlocks> blocks_;
    RowWordBoxes words_; // a box per row word: sparse rows (fewer than kBlocksFrom candidates)
    float plane_scale_ = 0.0f;          // the largest box coordinate: the planes' round-off margins
    FrustumBoxes::PlaneGroups planes_;  // the frame's planes, refilled each frame
    std::vector<uint64_t> every_region_;
    std::vector<uint64_t> near_; // the distance stage's survivors, as a row
    RegionBlocks::Scratch block_scratch_;
    std::vector<uint32_t> block_out_; // the block stage's output, before it is copied to `visible`
    Aabb zone_bounds_;
    std::optional<PvsRowCursor> cursor_;
    std::vector<uint32_t> candidates_; // the PVS stage's regions, only when counting triangles
    std::vector<uint32_t> face_stamp_; // per face: the last counting pass that saw it
    uint32_t stamp_ = 0;
};

} // namespace pvs
