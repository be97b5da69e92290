#include "app/vis_quake2.h"

#include "app/cmd_bake.h"
#include "app/error_path.h"
#include "app/output_files.h"
#include "app/process_memory.h"
#include "report/pvs_diff_json.h"
#include "report/report_fields_json.h"
#include "wld/common/read_file.h"
#include "wld/quake2/ibsp38_zone.h"
#include "wld/quake2/quake2_vis.h"

#include <nlohmann/json.hpp>

namespace pvs::app {

namespace {

quake2::PhsRule phs_rule_of(const VisCommandOptions& o)
{
    return o.phs_rule == "ericw" ? quake2::PhsRule::EricwTools : quake2::PhsRule::Quake2;
}

// --report: what was written, and the PVS the map held before against the one written (the same
// rows: only the PHS is new).
nlohmann::json phs_only_report(const VisCommandOptions& o, const std::string& map, std::span<const uint8_t> before,
                               const quake2::Quake2ZonePvsResult& r)
{
    nlohmann::json j = {{"input", map},
                        {"output", map},
                        {"format", "Quake 2 BSP (IBSP 38)"},
                        {"method", "phs-only"},
                        {"peak_rss_bytes", peak_rss_bytes()}};
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

int quake2_phs_only(const VisCommandOptions& o, const std::string& map, std::span<const uint8_t> bytes, std::FILE* err)
{
    const quake2::PhsRule rule = phs_rule_of(o);
    const quake2::Quake2ZonePvsResult r = quake2::remake_quake2_phs(bytes, map, rule);
    replace_atomically(map, r.map);
    std::fprintf(err, "%s: Quake 2 map, %u clusters: PVS kept, mean %.1f visible, %.1f hearable (%s PHS)\n",
                 map.c_str(), r.clusters, r.mean_visible, r.mean_hearable,
                 rule == quake2::PhsRule::Quake2 ? "Quake 2's" : "ericw-tools'");
    if (!o.report.empty())
        write_report(o.report, phs_only_report(o, map, bytes, r));
    return 0;
}

} // namespace pvs::app
