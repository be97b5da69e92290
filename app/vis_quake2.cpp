#include "app/vis_quake2.h"

#include "app/cmd_bake.h"
#include "app/error_path.h"
#include "app/output_files.h"
#include "app/process_memory.h"
#include "app/progress_bar.h"
#include "report/pvs_diff_json.h"
#include "report/report_fields_json.h"
#include "visibility/methods/vis_report_fields.h"
#include "wld/common/read_file.h"
#include "wld/quake/prt_file.h"
#include "wld/quake2/ibsp38_zone.h"
#include "wld/quake2/quake2_vis.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>

namespace pvs::app {

namespace {

namespace fs = std::filesystem;

quake2::PhsRule phs_rule_of(const VisCommandOptions& o)
{
    return o.phs_rule == "ericw" ? quake2::PhsRule::EricwTools : quake2::PhsRule::Quake2;
}

// --report for a Quake 2 map: what was written and the flow's figures (nulls with --phs-only).
nlohmann::json quake2_report(const VisCommandOptions& o, const std::string& map, std::span<const uint8_t> before,
                             const quake2::Quake2VisResult& r)
{
    const VisReport& v = r.report;
    const auto baked = [&](auto value) { return o.phs_only ? nlohmann::json(nullptr) : nlohmann::json(value); };
    nlohmann::json j = {{"input", map},
                        {"output", map},
                        {"format", "Quake 2 (IBSP 38)"},
                        {"method", o.phs_only ? "phs-only" : (o.fast ? "portal-fast" : o.method)},
                        {"level", baked(o.level)},
                        {"threads", baked(v.threads)},
                        {"portal_source", baked(fs::path(map).replace_extension(".prt").string())},
                        {"portals", baked(v.portals)},
                        {"portals_skipped", baked(v.portals_skipped)},
                        {"time_seconds", baked(v.seconds)},
                        {"base_seconds", baked(v.base_seconds)},
                        {"peak_rss_bytes", peak_rss_bytes()}};
    if (!o.phs_only)
        for (const ReportField& f : vis_report_fields(v, !(o.fast || o.method == "portal-fast"), false))
            if (f.name.starts_with(kWorkPrefix))
                report::add_report_fields(j, {f});
    // The PVS the map held before against the one written.
    const Zone old_zone = quake2::load_ibsp38(before, map), new_zone = quake2::load_ibsp38(r.map, map);
    j["regions"] = new_zone.region_count();
    report::add_report_fields(
        j, quake2::quake2_written_fields(r.clusters, r.mean_visible, r.mean_hearable, phs_rule_of(o)));
    j["file_pvs"] = old_zone.baked_pvs && new_zone.baked_pvs
                        ? report::pvs_diff_json(*new_zone.baked_pvs, *old_zone.baked_pvs)
                        : nlohmann::json(nullptr);
    return j;
}

} // namespace

int quake2_vis(const VisCommandOptions& o, const std::string& map, std::span<const uint8_t> bytes, std::FILE* err,
               const std::atomic<bool>* cancel)
{
    if (o.ambient_only)
        return bad_arguments(err, map + " is a Quake 2 map: --ambient-only is for Quake maps (Quake 2 keeps no ambient "
                                        "sounds in the map)");
    quake2::Quake2VisOptions q;
    q.vis.method = o.fast || o.method == "portal-fast" ? VisParams::Method::Fast : VisParams::Method::Full;
    q.vis.level = o.level;
    q.vis.threads = o.threads;
    std::optional<quake::PrtFile> prt;
    const std::string prt_path = (fs::path(map).replace_extension(".prt")).string();
    if (!o.phs_only) {
        if (!fs::is_regular_file(prt_path))
            return file_error(err, prt_path + ": no portal file beside the map (qbsp writes it)");
        prt = quake::load_prt(prt_path);
    }
    std::optional<ProgressBar> bar;
    if (!o.phs_only)
        bar.emplace(err, "vis");
    q.vis.progress = [&](double fraction) {
        if (bar)
            bar->update(fraction);
        return !(cancel && cancel->load());
    };
    q.phs = phs_rule_of(o);
    q.phs_only = o.phs_only;
    const quake2::Quake2VisResult r = quake2::vis_quake2_map(bytes, map, prt ? &*prt : nullptr, prt_path, q);
    if (bar)
        bar->finish(r.cancelled ? "cancelled" : "done");
    if (r.cancelled) {
        std::fprintf(err, "pvscope: vis cancelled: %s left as it was\n", map.c_str());
        return kExitCancelled;
    }
    replace_atomically(map, r.map);
    std::fprintf(err, "%s: Quake 2 map, %u clusters: %s, mean %.1f visible, %.1f hearable (%s PHS)%s\n", map.c_str(),
                 r.clusters, o.phs_only ? "PVS kept" : "PVS baked", r.mean_visible, r.mean_hearable,
                 q.phs == quake2::PhsRule::Quake2 ? "Quake 2's" : "ericw-tools'",
                 o.phs_only ? "" : (", " + std::to_string(r.report.seconds) + " s").c_str());
    if (!o.report.empty())
        write_report(o.report, quake2_report(o, map, bytes, r));
    return 0;
}

} // namespace pvs::app
