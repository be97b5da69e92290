// The registry of visibility methods: one entry per way pvscope can come by a PVS, so that
// `bake`, `compare`, `--pvs` and the inspector list the same methods with the same names, and a
// method added here appears in all of them at once.
//
//   file         the PVS the zone file carries (nothing is baked; absent when the file has none)
//   none         no PVS: culling falls back to the frustum (every region "visible")
//   portal-fast  base portal vis (portal_vis.h, Method::Fast): loose, conservative
//   portal-full  clipped portal flow at settings.level, with or without passages and target
//                checks: conservative (an upper bound of the true PVS)
//   clustered    portal-full over clusters of regions (cluster_vis.h): box clusters where the
//                regions are boxes, else BSP subtree clusters; looser, conservative
//   terrain      the ground as the only occluder (terrain/terrain_vis.h): a horizon sweep over the
//                zone's heightfield; conservative; for open zones
//   reference    sampled sight lines through the tree (reference/reference_vis.h): a lower bound
//   raster       cube maps rendered from sample points in each cell (raster/raster_vis.h): a
//                lower bound at its density; the cells are the zone's view grid (OBJ + .hepvs)
//                or its regions
//
// Each entry says which side of the truth it sits on (Bound), so compare can say which failures
// matter: an upper bound must miss nothing the reference finds, a lower bound may pop. Bakes run
// on settings.threads workers, call settings.progress and stop when it returns false (the run is
// then `cancelled` and holds whatever the method had). Library code: no output, no exit; bad zones
// throw as the bakers do (std::invalid_argument, e.g. the reference on a zone without a tree).
#pragma once

#include "visibility/methods/portal_input.h"
#include "visibility/portal/media.h"
#include "visibility/portal/portal_vis.h"
#include "visibility/pvs.h"
#include "visibility/raster/raster_vis.h"
#include "visibility/reference/reference_vis.h"
#include "visibility/methods/report_field.h"
#include "visibility/zone.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pvs {

enum class Bound : uint8_t {
    Upper, // conservative: holds every true sight line (and more)
    Lower, // holds only proven sight lines (and may miss some)
    Unknown, // the file's: whatever its tool did
    Everything, // none: every region
};
const char* bound_name(Bound bound);

struct MethodSettings {
    SkyPortals sky = SkyPortals::SkyToSky; // portals and sight lines at sky leaves
    unsigned threads = 0;                  // 0 = all cores
    // portal-full and clustered:
    int level = 4;
    bool passages = true;
    bool target_checks = true;
    // portal-fast and portal-full: the portals to bake on, when the caller has them (a portal
    // file's, with its clusters; must outlive the run); nullptr: zone_portal_input builds them,
    // grouped into box clusters with `box_clusters` where the regions are boxes.
    const PortalInput* portals = nullptr;
    bool box_clusters = false;
    // portal-full over regions (no clusters): when given, the flow records the chains along which
    // it reached chain_probe->to from chain_probe->from (flow_chain.h), as `why` shows them; the
    // rows are the same. Must outlive the run.
    ChainProbe* chain_probe = nullptr;
    // portal methods on zones extruded from 2-D maps (Doom, BspTree::first_height_node): false
    // = ignore floors and ceilings, as glVIS (safe while doors and lifts move); true = the
    // heights as built block sight (closed doors, floor/ceiling gaps): only for static maps.
    bool heights = false;
    // reference: lines per region at most (0: the default, until converged), and the seed.
    uint64_t samples = 0;
    uint64_t seed = 1;
    // reference: each region's walks aim by its own lines (ReferenceParams::per_source), so with
    // `samples` set each region's lines depend on it alone and the bake splits into shards.
    bool reference_per_source = false;
    // raster: pixels per cube face side, sample points per region (region cells), lattice step in
    // grid units (grid cells; 0 = each cell's centre only), and the back-face rule.
    uint32_t raster_resolution = 64;
    uint32_t raster_points = 16;
    float raster_step = 0.0f;
    Lattice raster_lattice = Lattice::OpenRandom; // grid cells (raster_vis.h)
    bool cull_back_faces = true;
    RasterEngine raster_engine = RasterEngine::Rays; // pixel rays (Embree packets) or the rasteriser
    RasterDevice raster_device = RasterDevice::Cpu;  // where the views are drawn (raster_vis.h)
    uint32_t raster_gpu_batch = 0;                   // GPU views per compute pass (0: gpu_cube.h's default)
    // A shard's sources (source_shards.h): compute only these rows, the others stay empty. Only
    // for methods with source_costs; empty: every row. Must outlive the run.
    std::span<const uint32_t> sources;
    std::function<bool(double fraction)> progress;
    std::function<void(const ReferenceRound& round, const Pvs& rows)> on_reference_round;
};

struct MethodRun {
    std::optional<Pvs> pvs;         // none: no PVS; file: a copy of the zone's (absent if it has none)
    double seconds = 0.0;           // the bake's wall clock (0 for file and none)
    size_t peak_bytes_estimate = 0; // the baker's own estimate of its largest heap use
    bool cancelled = false;
    std::string summary;            // one line for a user: what ran and what it found
    // What the method measured, for reports (report_field.h): times, counts and, under "work.",
    // its work counters - deterministic for a zone, a method and its settings, on any machine and
    // at any thread count, so a rise is a regression that no clock noise hides.
    std::vector<ReportField> fields;
    // What a user should hear besides the summary, one line each ("warning: ...", "note: ...").
    std::vector<std::string> notes;
};

struct VisMethod {
    std::string_view name;
    std::string_view description;
    Bound bound;
    bool bakes;                     // false for file and none: nothing to compute
    bool reads_drawing;             // reads the zone's mesh or textures (false: a caller may free them first)
    MethodRun (*run)(const Zone& zone, const MethodSettings& settings);
    // The settings this method reads, for a label such as "level=2 passages=off" (compare, chart).
    std::string (*label)(const MethodSettings& settings);
    // Methods whose rows are computed source by source, each row independent of the others: the
    // cost of each source's row, for splitting the bake into shards (source_shards.h; the method
    // then reads MethodSettings::sources). nullptr: the method cannot be split (shard_refusal
    // says why).
    std::vector<double> (*source_costs)(const Zone& zone, const MethodSettings& settings) = nullptr;
    // Why a method without source_costs cannot be split (or, with them, what it needs to split),
    // for a user's message.
    std::string_view shard_refusal = {};
    // How shards' rows join: false, each row is its own source's (a part holds its sources' rows);
    // true, a source's work sets bits in any row (the reference's lines prove pairs of every
    // region they cross), so a part holds every row and the merge ORs them.
    bool shard_rows_union = false;
};

std::span<const VisMethod> vis_methods();

// The portals portal-fast and portal-full bake on when none are given (zone_portal_input's,
// without clusters), and whether they go to the 2-D baker (bake_portal_vis_2d) rather than
// bake_portal_vis. Throw as those methods do (no tree).
PortalSet method_portals(const Zone& zone, const MethodSettings& settings);
bool method_uses_2d_vis(const Zone& zone, const MethodSettings& settings);

// nullptr when no method has that name.
const VisMethod* find_vis_method(std::string_view name);
// "file, none, portal-fast, ..." for messages and --help.
std::string vis_method_names();
// The same for the methods that bake (all but file and none).
std::string baking_method_names();

} // namespace pvs
