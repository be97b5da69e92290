#include "render/method_compare.h"

#include "render/accuracy_walk.h"
#include "visibility/eval/camera_set.h"
#include "visibility/eval/pvs_gap.h"

#include <chrono>
#include <stdexcept>
#include <sys/resource.h>

namespace pvs::ui {

namespace {

double cpu_seconds()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    auto seconds = [](const timeval& t) { return double(t.tv_sec) + double(t.tv_usec) * 1e-6; };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// The peak memory of one bake through the caller's probe, if any (CompareOptions::memory_probe).
class PeakMemory {
public:
    explicit PeakMemory(const std::optional<PeakMemoryProbe>& probe) : probe_(probe)
    {
        if (probe_ && probe_->begin)
            probe_->begin();
    }
    // The rise in MiB, or a negative value when there is no probe or it cannot tell.
    double rise_mib() const { return probe_ && probe_->rise_mib ? probe_->rise_mib() : -1.0; }

private:
    const std::optional<PeakMemoryProbe>& probe_;
};

// Level 0 (no separating planes) is left out: its flow explodes on real levels (e1m1: more than
// 12 minutes on 2 cores, against 2 s at level 1).
constexpr int kLowestComparedLevel = 1;

// The raster baker's points on the chart, from coarse to dense, a curve rather than one point:
// (pixels per cube face side, points per region, or per grid cell in open space).
constexpr std::pair<uint32_t, uint32_t> kRasterRegionCurve[] = {{32, 4}, {64, 8}, {64, 32}};
constexpr std::pair<uint32_t, uint32_t> kRasterGridCurve[] = {{32, 8}, {64, 8}, {64, 32}};

// Every method but the reference (baked first anyway); on a zone without a tree, only those that
// need none (portal vis, clustering and the terrain's heightfield build on the tree).
std::vector<std::string> all_methods(const Zone& zone)
{
    std::vector<std::string> names;
    for (const VisMethod& m : vis_methods())
        if (m.name != "reference" &&
            (zone.tree.exists() ||
             (m.name != "portal-fast" && m.name != "portal-full" && m.name != "clustered" && m.name != "terrain")))
            names.emplace_back(m.name);
    return names;
}

MethodSettings base_settings(const CompareOptions& o)
{
    MethodSettings s;
    s.sky = o.sky;
    s.threads = o.threads;
    s.seed = o.seed;
    s.samples = o.reference_samples;
    return s;
}

CompareRow measured_row(const VisMethod& method, const MethodSettings& settings, MethodRun run, double cpu_s,
                        const PeakMemory& memory)
{
    CompareRow row;
    row.method = std::string(method.name);
    row.params = method.label(settings);
    row.bound = method.bound;
    row.baked = method.bakes;
    row.wall_s = run.seconds;
    row.cpu_s = method.bakes ? cpu_s : 0.0;
    row.estimate_mib = double(run.peak_bytes_estimate) / (1024.0 * 1024.0);
    const double measured = method.bakes ? memory.rise_mib() : -1.0;
    row.peak_mib = !method.bakes ? 0.0 : measured >= 0.0 ? measured : row.estimate_mib;
    row.summary = run.summary;
    row.pvs_bytes = run.pvs ? run.pvs->memory_bytes() : 0;
    row.pvs = std::move(run.pvs);
    return row;
}

// Bakes one entry; progress goes through `progress` with the entry's name.
CompareRow run_entry(const Zone& zone, const CompareEntry& entry, const CompareOptions& o, bool& cancelled)
{
    const VisMethod& method = *find_vis_method(entry.method);
    MethodSettings settings = entry.settings;
    const std::string stage = std::string(method.name) + " " + method.label(settings);
    settings.progress = [&](double fraction) { return !o.progress || o.progress(stage, fraction); };
    const PeakMemory memory(o.memory_probe);
    const double cpu_before = cpu_seconds();
    MethodRun run = method.run(zone, settings);
    cancelled = run.cancelled;
    return measured_row(method, settings, std::move(run), cpu_seconds() - cpu_before, memory);
}

// The reference, one row per doubling round; the last is the reference itself.
std::vector<CompareRow> run_reference(const Zone& zone, const CompareOptions& o, bool& cancelled)
{
    const VisMethod& method = *find_vis_method("reference");
    MethodSettings settings = base_settings(o);
    settings.progress = [&](double fraction) { return !o.progress || o.progress("reference", fraction); };
    std::vector<CompareRow> rounds;
    const PeakMemory memory(o.memory_probe);
    const double cpu_before = cpu_seconds();
    settings.on_reference_round = [&](const ReferenceRound& round, const Pvs& rows) {
        MethodSettings at = settings;
        at.samples = round.samples_per_region;
        MethodRun run;
        run.pvs = rows;
        run.seconds = round.seconds;
        run.summary = "reference after " + std::to_string(round.samples_per_region) + " lines and " +
                      std::to_string(round.eyes_per_region) + " eyes per region";
        rounds.push_back(measured_row(method, at, std::move(run), cpu_seconds() - cpu_before, memory));
    };
    MethodRun run = method.run(zone, settings);
    cancelled = run.cancelled;
    if (!rounds.empty()) { // the last round is the final rows; keep the run's own figures for it
        rounds.back().summary = run.summary;
        rounds.back().estimate_mib = double(run.peak_bytes_estimate) / (1024.0 * 1024.0);
    }
    return rounds;
}

void measure_walk(const Zone& zone, const CompareOptions& o, CompareResult& result)
{
    Camera lens;
    lens.aspect = float(o.width) / float(o.height);
    const std::vector<Camera> cameras = random_cameras_in_regions(zone, o.cameras, o.seed, lens);
    result.cameras = cameras.size();
    std::vector<const Pvs*> pvss;
    for (const CompareRow& row : result.rows)
        pvss.push_back(row.pvs ? &*row.pvs : nullptr);
    WalkOptions walk;
    walk.width = o.width;
    walk.height = o.height;
    walk.sky = o.sky;
    walk.progress = [&](size_t done, size_t total) {
        return !o.progress || o.progress("walk", double(done) / double(std::max<size_t>(total, 1)));
    };
    const std::vector<std::vector<WalkRow>> walks = run_accuracy_walks(zone, pvss, cameras, walk);
    for (size_t p = 0; p < walks.size(); ++p) {
        result.cancelled = result.cancelled || walks[p].size() < cameras.size();
        CompareRow& row = result.rows[p];
        double overdraw = 0.0;
        for (const WalkRow& w : walks[p]) {
            row.popping_pixels += w.popping_confirmed;
            row.crack_pixels += w.popping_cracks;
            row.unknown_pixels += w.popping_unknown;
            row.grazing_pixels += w.popping_grazing;
            row.unfaced_pixels += w.popping_unfaced;
            overdraw += w.accuracy.triangle_overdraw();
        }
        row.triangle_overdraw = walks[p].empty() ? 0.0 : overdraw / double(walks[p].size());
    }
}

} // namespace

std::vector<CompareEntry> compare_entries(const std::string& name, const CompareOptions& options, bool grid_zone,
                                          bool extruded)
{
    const VisMethod* method = find_vis_method(name);
    if (!method)
        return {};
    const MethodSettings base = base_settings(options);
    if (name == "raster") { // its knobs as a curve
        std::vector<CompareEntry> entries;
        if (grid_zone)
            for (const auto& [resolution, points] : kRasterGridCurve) {
                CompareEntry e{name, base};
                e.settings.raster_resolution = resolution;
                e.settings.raster_points = points;
                entries.push_back(e);
            }
        else
            for (const auto& [resolution, points] : kRasterRegionCurve) {
                CompareEntry e{name, base};
                e.settings.raster_resolution = resolution;
                e.settings.raster_points = points;
                entries.push_back(e);
            }
        return entries;
    }
    if (name != "portal-full")
        return {{name, base}};
    std::vector<CompareEntry> entries;
    if (extruded) {
        for (int level : {0, 2}) {
            CompareEntry e{name, base};
            e.settings.level = level;
            entries.push_back(e);
        }
        CompareEntry heights{name, base};
        heights.settings.heights = true;
        entries.push_back(heights);
        return entries;
    }
    for (int level = kLowestComparedLevel; level <= 4; ++level) {
        CompareEntry e{name, base};
        e.settings.level = level;
        entries.push_back(e);
    }
    CompareEntry no_passages{name, base}, no_checks{name, base};
    no_passages.settings.passages = false;
    no_checks.settings.target_checks = false;
    entries.push_back(no_passages);
    entries.push_back(no_checks);
    return entries;
}

CompareResult run_compare(const Zone& zone, const CompareOptions& options)
{
    std::vector<CompareEntry> entries;
    for (const std::string& name : options.methods.empty() ? all_methods(zone) : options.methods) {
        if (name == "reference")
            continue; // always baked, first
        std::vector<CompareEntry> more = compare_entries(name, options, zone.view_grid.has_value(), zone.tree.has_height_nodes());
        if (more.empty())
            throw std::invalid_argument("unknown method '" + name + "' (" + vis_method_names() + ")");
        entries.insert(entries.end(), more.begin(), more.end());
    }
    CompareResult result;
    result.rows = run_reference(zone, options, result.cancelled);
    if (result.rows.empty() || result.cancelled) {
        result.cancelled = true;
        return result;
    }
    const Pvs reference = *result.rows.back().pvs;
    result.reference_params = result.rows.back().params;
    for (const CompareEntry& entry : entries) {
        result.rows.push_back(run_entry(zone, entry, options, result.cancelled));
        if (result.cancelled) {
            result.rows.pop_back();
            return result;
        }
    }
    // What drawing a region for nothing costs: its triangles.
    std::vector<uint64_t> triangles(zone.region_count(), 0);
    if (reference.region_count() == zone.region_count())
        for (uint32_t r = 0; r < zone.region_count(); ++r)
            for (uint32_t face : zone.faces_of_region(r))
                if (face < zone.mesh.faces.size())
                    triangles[r] += zone.mesh.faces[face].triangle_count;
    for (CompareRow& row : result.rows) {
        // The file's PVS may be absent: then it is "none" too, and says so in its summary.
        const PvsGap gap = pvs_gap(row.pvs ? &*row.pvs : nullptr, reference);
        if (triangles.size() == reference.region_count())
            row.worst_overdraw_pairs =
                worst_excess_pairs(row.pvs ? &*row.pvs : nullptr, reference, triangles, kListedWorstPairs);
        row.missing_bits = gap.missing_bits;
        row.excess_bits = gap.excess_bits;
        row.rows_missing_bits = gap.rows_missing_bits;
        row.missing_pairs = gap.missing_pairs;
        row.mean_visible = gap.mean_visible;
    }
    result.reference_bits = pvs_gap(&reference, reference).bits;
    if (options.cameras > 0)
        measure_walk(zone, options, result);
    return result;
}

} // namespace pvs::ui
