#include "report/zone_report.h"

namespace pvs {

namespace {
nlohmann::json vec3_json(const glm::vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }
} // namespace

nlohmann::json zone_report_json(const Zone& zone, const ZoneStats& s, double load_ms)
{
    using nlohmann::json;
    json flags = json::object();
    for (uint32_t bit = 0; bit < kRegionFlagCount; ++bit)
        flags[region_flag_name(1u << bit)] = s.flag_counts[bit];

    json pvs = {{"present", s.pvs.present}};
    if (s.pvs.present) {
        pvs["rows"] = s.pvs.rows;
        pvs["missing_rows"] = s.pvs.missing_rows;
        pvs["mean_visible"] = s.pvs.mean_visible;
        pvs["min_visible"] = s.pvs.min_visible;
        pvs["max_visible"] = s.pvs.max_visible;
        pvs["p50_visible"] = s.pvs.p50_visible;
        pvs["p90_visible"] = s.pvs.p90_visible;
        pvs["p99_visible"] = s.pvs.p99_visible;
        pvs["mean_visible_percent"] = s.pvs.mean_percent;
        pvs["storage"] = s.pvs.dense ? "dense" : "compressed";
        pvs["memory_bytes"] = s.pvs.memory_bytes;
    }

    json zone_lines = json::array();
    for (const ZoneLine& line : zone.zone_lines)
        zone_lines.push_back({{"target", line.target}, {"min", vec3_json(line.bounds.min)},
                              {"max", vec3_json(line.bounds.max)}});

    json source_counts = json::object();
    for (const auto& [key, value] : zone.source.counts)
        source_counts[key] = value;

    json report = {
        {"file", zone.source.path},
        {"format", zone.source.format},
        {"version", zone.source.version},
        {"load_ms", load_ms},
        {"memory_bytes", s.memory_bytes},
        {"counts",
         {{"nodes", s.tree.nodes},
          {"regions", s.regions},
          {"solid_leaves", s.tree.solid_leaves},
          {"outside_leaves", s.tree.outside_leaves},
          {"faces", s.faces},
          {"triangles", s.triangles},
          {"vertices", s.vertices},
          {"materials", s.materials},
          {"materials_with_pixels", s.materials_with_pixels},
          {"region_face_refs", s.region_face_refs},
          {"portals", s.portals},
          {"zone_lines", s.zone_lines}}},
        {"region_flags", flags},
        {"pvs", pvs},
        {"tree", {{"max_depth", s.tree.max_depth}, {"mean_depth", s.tree.mean_depth}, {"leaves", s.tree.leaves}}},
        {"zone_lines", zone_lines},
        {"source_counts", source_counts},
        {"view_grid", zone.view_grid ? json{{"min", vec3_json(zone.view_grid->min)},
                                            {"cell_size", zone.view_grid->cell_size},
                                            {"counts", {zone.view_grid->counts.x, zone.view_grid->counts.y,
                                                        zone.view_grid->counts.z}},
                                            {"cells", zone.view_grid->cell_count()},
                                            {"grid_size", zone.view_grid->grid_size}}
                                     : json(nullptr)},
        {"notes", zone.source.notes},
    };
    if (!s.bounds.empty())
        report["bounds"] = {{"min", vec3_json(s.bounds.min)}, {"max", vec3_json(s.bounds.max)}};
    return report;
}

} // namespace pvs
