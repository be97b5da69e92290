#include "app/cmd_bake.h"

#include "app/bake_input.h"
#include "app/bake_output.h"
#include "app/bake_shard.h"
#include "app/error_path.h"
#include "app/output_files.h"
#include "app/process_memory.h"
#include "app/progress_bar.h"
#include "report/bake_report_json.h"
#include "visibility/file_error.h"
#include "visibility/methods/vis_method.h"
#include "wld/common/read_file.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace pvs::app {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The portals the bake is handed: a portal file's, or with --write-prt the tree's built here (so
// they can be written); none, and the method builds them.
std::optional<PortalInput> given_portals(const BakeOptions& o, const BakeInput& in, const MethodSettings& settings)
{
    if (!o.prt_in.empty())
        return portal_input_from_file(o.prt_in, in);
    if (!o.prt_out.empty())
        return zone_portal_input(in.zone, settings);
    return std::nullopt;
}

// The method through the registry with a progress bar on `err`; the reference's rounds are
// noted on the bar.
MethodRun run_method(const VisMethod& method, const Zone& zone, MethodSettings settings, std::FILE* err,
                     const std::atomic<bool>* cancel)
{
    ProgressBar bar(err, "bake");
    settings.on_reference_round = [&](const ReferenceRound& round, const Pvs&) {
        char line[240];
        std::snprintf(line, sizeof line,
                      "reference: %8s lines and %6s eyes per region, %9s bits, +%s new (%.3f%%), %.1f s",
                      std::to_string(round.samples_per_region).c_str(), std::to_string(round.eyes_per_region).c_str(),
                      std::to_string(round.bits).c_str(), std::to_string(round.new_bits).c_str(),
                      100.0 * round.new_share(), round.seconds);
        bar.note(line);
    };
    settings.progress = [&](double fraction) {
        bar.update(fraction);
        return !(cancel && cancel->load());
    };
    MethodRun run = method.run(zone, settings);
    bar.finish(run.cancelled ? "cancelled" : "done");
    return run;
}

report::BakeReportHeader report_header(const BakeOptions& o, const BakeInput& in, const VisMethod& method,
                                       const MethodSettings& settings)
{
    report::BakeReportHeader h;
    h.input = o.input;
    h.output = o.output_name.empty() ? o.output : o.output_name;
    h.format = format_name(in);
    h.method = o.method;
    h.params = method.label(settings);
    h.bound = method.bound;
    return h;
}

// --shard K/N: the shard's sources baked and written as a part file (bake_shard.h).
int run_shard(const BakeOptions& o, const BakeInput& in, const VisMethod& method, MethodSettings settings,
              std::FILE* err, const std::atomic<bool>* cancel)
{
    const auto start = std::chrono::steady_clock::now();
    const ShardSpec shard = *parse_shard_spec(o.shard);
    const std::vector<double> costs = method.source_costs(in.zone, settings);
    const std::vector<uint32_t> sources = shard_sources(costs, shard);
    const uint32_t rows =
        in.zone.view_grid ? uint32_t(in.zone.view_grid->cell_count()) : uint32_t(in.zone.region_count());
    std::optional<Pvs> pvs;
    if (sources.empty()) { // more shards than rows: an empty part, and nothing baked (empty sources = every row)
        pvs =
            Pvs::build_rows(rows, uint32_t(in.zone.region_count()), [](uint32_t, std::span<uint64_t>) { return true; });
    } else {
        settings.sources = sources;
        MethodRun run = run_method(method, in.zone, settings, err, cancel);
        if (run.cancelled) {
            std::fprintf(err, "pvscope: bake cancelled: nothing was written\n");
            return kExitCancelled;
        }
        pvs = std::move(run.pvs);
    }
    // A method whose sources set bits in any row (the reference) hands over every row, to be ORed.
    std::vector<uint32_t> every_row;
    if (method.shard_rows_union) {
        every_row.resize(rows);
        std::iota(every_row.begin(), every_row.end(), 0u);
    }
    const PvsPart part =
        make_pvs_part(*pvs, method.shard_rows_union ? every_row : sources, shard, bake_zone_hash(o, in),
                      bake_settings_text(o), method.shard_rows_union ? PartRows::Union : PartRows::Own);
    replace_atomically(o.output, encode_pvs_part(part));
    double cost = 0;
    for (uint32_t s : sources)
        cost += costs[s];
    std::fprintf(err, "wrote %s: shard %u of %u, %zu of %u sources (cost %.0f of %.0f)\n", o.output.c_str(),
                 shard.index, shard.count, sources.size(), rows, cost,
                 std::accumulate(costs.begin(), costs.end(), 0.0));
    if (!o.report.empty())
        write_report(o.report, {{"shard", shard.index},
                                {"shards", shard.count},
                                {"method", o.method},
                                {"sources", sources.size()},
                                {"rows_total", rows},
                                {"cost", cost},
                                {"seconds", seconds_since(start)},
                                {"cpu_seconds", process_cpu_seconds()},
                                {"peak_rss_bytes", peak_rss_bytes()}});
    return 0;
}

int run_checked(const BakeOptions& o, std::FILE* err, const std::atomic<bool>* cancel)
{
    const auto load_start = std::chrono::steady_clock::now();
    BakeInput in = load_bake_input(o, err);
    const double load_seconds = seconds_since(load_start);
    if (const std::string problem = check_output_against_input(o, in); !problem.empty())
        return bad_arguments(err, problem);
    const VisMethod& method = *find_vis_method(o.method);
    if (!method.reads_drawing)
        drop_drawing(in);
    MethodSettings settings = bake_method_settings(o);
    const bool quake = in.format == ZoneFormat::QuakeBsp || in.format == ZoneFormat::Quake2Bsp;
    settings.box_clusters = o.clusters == "auto" && !quake;
    if (o.clusters == "auto" && quake && o.prt_in.empty())
        std::fprintf(err, "note: --clusters auto: a Quake map is baked per leaf (its PVS is per leaf)\n");
    const std::optional<PortalInput> portals = given_portals(o, in, settings);
    settings.portals = portals ? &*portals : nullptr;
    if (!o.shard.empty())
        return run_shard(o, in, method, settings, err, cancel);
    MethodRun run = run_method(method, in.zone, settings, err, cancel);
    for (const std::string& note : run.notes)
        std::fprintf(err, "%s\n", note.c_str());
    if (run.cancelled) {
        std::fprintf(err, "pvscope: bake cancelled: nothing was written\n");
        return kExitCancelled;
    }
    Pvs pvs = std::move(*run.pvs);
    report::BakeReportHeader header = report_header(o, in, method, settings);
    header.load_seconds = load_seconds;
    header.edits_applied = apply_edit_list(o, pvs, err);
    const auto write_start = std::chrono::steady_clock::now();
    header.written = write_bake_output(o, in, pvs, err);
    if (portals && !o.prt_out.empty())
        write_portal_file(o.prt_out, in.zone, *portals, err);
    header.write_seconds = seconds_since(write_start);
    std::fprintf(err, "%s%s\n", run.summary.c_str(), header.edits_applied ? " (before the edits)" : "");
    if (!o.report.empty()) {
        header.peak_rss_bytes = peak_rss_bytes();
        write_report(o.report,
                     report::bake_report_json(header, run, pvs, in.zone.baked_pvs ? &*in.zone.baked_pvs : nullptr));
    }
    return 0;
}

} // namespace

int run_bake(const BakeOptions& options, std::FILE* err, const std::atomic<bool>* cancel)
{
    if (const std::string problem = check_bake_options(options); !problem.empty())
        return bad_arguments(err, problem);
    return run_reporting_errors(options.input, err, [&] { return run_checked(options, err, cancel); });
}

} // namespace pvs::app
