// InspectorState's statistics export: the zone report `pvscope info --json` prints
// (report/zone_report.h) plus the culling stats gathered since the zone was opened.
#include "ui/gui/inspector_state.h"

#include "report/json_csv.h"
#include "report/zone_report.h"

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace pvs::gui {

namespace {

const char* camera_place_name(CameraPlace place)
{
    switch (place) {
    case CameraPlace::InRegion: return "in_region";
    case CameraPlace::InSolid: return "in_solid";
    case CameraPlace::Outside: return "outside";
    }
    return "?";
}

nlohmann::json culling_json(const InspectorState& state)
{
    const CullTotals& t = state.totals();
    const double n = t.frames ? double(t.frames) : 1.0;
    const CullStats& s = state.last_cull();
    return {
        {"frames", t.frames},
        {"frames_in_region", t.frames_in_region},
        {"frames_pvs_used", t.frames_pvs_used},
        {"mean_lookup_us", t.lookup_us / n},
        {"mean_pvs_us", t.pvs_us / n},
        {"mean_distance_us", t.distance_us / n},
        {"mean_frustum_us", t.frustum_us / n},
        {"max_cull_us", t.max_cull_us},
        {"mean_render_ms", t.render_ms / n},
        {"max_render_ms", t.max_render_ms},
        {"mean_regions_after_pvs", double(t.regions_after_pvs) / n},
        {"mean_regions_drawn", double(t.regions_drawn) / n},
        {"mean_triangles_after_pvs", double(t.triangles_after_pvs) / n},
        {"mean_triangles_drawn", double(t.triangles_drawn) / n},
        {"last_frame",
         {{"mode", cull_mode_name(state.cull_mode)},
          {"camera", camera_place_name(s.camera)},
          {"region", s.region},
          {"pvs_used", s.pvs_used},
          {"regions_total", s.regions_total},
          {"regions_after_pvs", s.regions_after_pvs},
          {"far_clip", state.far_clip},
          {"regions_after_distance", s.regions_after_distance},
          {"regions_drawn", s.regions_after_frustum},
          {"triangles_total", s.triangles_total},
          {"triangles_after_pvs", s.triangles_after_pvs},
          {"triangles_drawn", s.triangles_after_frustum},
          {"lookup_us", s.lookup_us},
          {"pvs_us", s.pvs_us},
          {"distance_us", s.distance_us},
          {"frustum_us", s.frustum_us},
          {"render_ms", state.last_render().draw_ms}}},
    };
}

nlohmann::json stats_json(const InspectorState& state)
{
    if (!state.has_zone())
        return nlohmann::json::object();
    nlohmann::json report = zone_report_json(state.zone(), state.zone_stats(), state.load_ms());
    report["culling"] = culling_json(state);
    return report;
}

} // namespace

std::string InspectorState::export_stats_json() const { return stats_json(*this).dump(2) + "\n"; }

std::string InspectorState::export_stats_csv() const
{
    CsvFields fields;
    flatten_json(stats_json(*this), "", fields);
    return csv_table({fields});
}

} // namespace pvs::gui
