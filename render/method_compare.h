// Every visibility method on one zone, judged against the sampled reference: the engine of
// `pvscope compare` and of the inspector's Compare panel (headless, no output of its own).
//
// For each entry (a registry method with its settings, visibility/methods/vis_method.h) the run
// bakes the PVS and measures: wall and CPU seconds, peak memory (below), the PVS's size in memory,
// mean visible regions, missing and excess bits against the reference (visibility/eval/pvs_gap.h),
// and over one seeded set of cameras the exact popping pixels and triangle overdraw
// (accuracy_walk.h: each camera's ID buffer rendered once for all methods).
//
// The reference is always baked (first), with the given samples and seed; each of its doubling
// rounds is kept as a row of its own ("reference", samples=N), measured against the final rows:
// the curve shows what more samples buy. The last round is the reference itself (0 missing,
// 0 excess by definition). Methods other than the reference are listed by name; portal-full and
// clustered expand to their variants (levels 1-4; level 4 without passages, without target checks;
// level 0, without separators, takes over 12 minutes on e1m1 and is left out).
//
// Memory: with CompareOptions::memory_probe (where Linux allows it), the process's peak RSS is reset before
// each bake and peak_mib is how far it rose above the RSS before the bake; elsewhere the
// baker's own estimate (estimate_mib, always reported). CPU seconds are the process's user+system
// time during the bake (nothing else runs then).
#pragma once

#include "visibility/eval/pvs_gap.h"
#include "visibility/methods/vis_method.h"
#include "visibility/zone.h"

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pvs::ui {

struct CompareEntry {
    std::string method;
    MethodSettings settings;
};

// Measures the process's peak memory over one bake: begin() before it, rise_mib() after it (a
// negative value: it cannot). It touches process-wide state (the heap, the kernel's peak-RSS mark), so
// the process supplies it (app/process_memory.h); without one, a row's peak_mib is the baker's
// own estimate.
struct PeakMemoryProbe {
    std::function<void()> begin;
    std::function<double()> rise_mib;
};

struct CompareOptions {
    std::vector<std::string> methods;   // registry names other than reference; empty: all of them
                                        // (on a zone without a tree: all that need none)
    uint64_t reference_samples = 0;     // the reference's lines per region (0: its default)
    uint64_t seed = 1;                  // the reference's and the cameras' seed
    size_t cameras = 200;               // 0: no walk (popping and overdraw are then not measured)
    uint32_t width = 320, height = 240; // of each camera's ID buffer
    SkyPortals sky = SkyPortals::SkyToSky;
    unsigned threads = 0;
    // Called with what runs now ("portal-full level=2 ...", "walk") and its fraction; false cancels.
    std::function<bool(const std::string& stage, double fraction)> progress;
    std::optional<PeakMemoryProbe> memory_probe; // none: the bakers' estimates (above)
};

struct CompareRow {
    std::string method, params;
    Bound bound = Bound::Unknown;
    bool baked = false;             // false for file and none (their times are 0)
    double wall_s = 0, cpu_s = 0;
    double peak_mib = 0, estimate_mib = 0;
    size_t pvs_bytes = 0;           // in memory (0: no PVS)
    double mean_visible = 0;
    uint64_t missing_bits = 0, excess_bits = 0;
    uint32_t rows_missing_bits = 0;
    std::vector<std::pair<uint32_t, uint32_t>> missing_pairs; // the first few (row, region) missing, pvs_gap.h
    // The excess pairs that draw the most triangles for nothing (worst_excess_pairs, pvs_gap.h).
    std::vector<CostlyPair> worst_overdraw_pairs;
    uint64_t popping_pixels = 0;    // confirmed by the tree trace, over all cameras
    uint64_t crack_pixels = 0;      // raster popping the trace rejected (blocked by a wall)
    uint64_t unknown_pixels = 0;    // raster popping the trace cannot decide (a face seen edge-on, no tree)
    uint64_t grazing_pixels = 0;    // raster popping open only by less than kSightMargin
    uint64_t unfaced_pixels = 0;    // raster popping across a boundary the content rule makes opaque, no face there
    double triangle_overdraw = 0;   // mean over cameras (drawn / needed triangles)
    std::string summary;
    std::optional<Pvs> pvs;         // the rows (none: empty), for the panel to cull with
};

struct CompareResult {
    std::vector<CompareRow> rows;
    std::string reference_params;
    uint64_t reference_bits = 0;
    size_t cameras = 0;
    bool cancelled = false;         // rows hold what finished
};

// The entries a method name stands for (portal-full: levels 1-4 and its switches); empty for an
// unknown name.
// grid_zone: the zone has a view grid (raster's points are then per cell, in open space).
// extruded: a 2-D map (Doom, BspTree::has_height_nodes): portal-full runs the 2-D baker at
// levels 0 and 2 (1 and 3 are the same there, passages and target checks do not apply) and the
// 3-D baker with --heights.
std::vector<CompareEntry> compare_entries(const std::string& method, const CompareOptions& options,
                                          bool grid_zone = false, bool extruded = false);

// Throws std::invalid_argument for an unknown method name, and what the reference throws (a zone
// without a tree).
CompareResult run_compare(const Zone& zone, const CompareOptions& options);

} // namespace pvs::ui
