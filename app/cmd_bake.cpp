#include "app/cmd_bake.h"

#include "app/bake_input.h"
#include "app/bake_output.h"
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
#include <optional>
#include <stdexcept>

namespace pvs::app {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The argument errors that need the input's format; empty when there are none.
std::string check_against_input(const BakeOptions& o, const BakeInput& in)
{
    if (in.format == ZoneFormat::ObjHepvs && o.method != "raster" && o.method != "reference")
        return "'" + o.input + "' is an OBJ level: " + o.method +
               " needs a BSP tree, which it has not; bake it with --method raster (or reference: sight lines "
               "against the mesh)";
    if (in.format != ZoneFormat::DoomWad && (o.in_place || o.reject || o.heights || !o.map.empty()))
        return "--in-place, --reject, --heights and --map are for Doom WADs";
    if (o.reject && !o.in_place && in.doom_source.gl_path != in.doom_source.wad_path)
        return "--reject: REJECT lives in " + in.doom_source.wad_path + " but the GL nodes (and -o) are in " +
               in.doom_source.gl_path + "; use --in-place to write both";
    if (!o.in_place && lowercase_extension(o.output) != format_extension(in))
        return "'" + o.input + "' is in the " + format_name(in) +
               " format and bake writes its PVS in the same format, so the output must end in " + format_extension(in) +
               ", not '" + o.output +
               "' (to change the format, run `pvscope convert` on the "
               "result)";
    if (in.format == ZoneFormat::DoomWad && (!o.prt_in.empty() || !o.prt_out.empty()))
        return "--prt / --write-prt: a Doom map's portals are its GL nodes' segs, not a portal file";
    return {};
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

int run_checked(const BakeOptions& o, std::FILE* err, const std::atomic<bool>* cancel)
{
    const auto load_start = std::chrono::steady_clock::now();
    BakeInput in = load_bake_input(o, err);
    const double load_seconds = seconds_since(load_start);
    if (const std::string problem = check_against_input(o, in); !problem.empty())
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
