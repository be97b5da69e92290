#include "report/zone_health_json.h"

namespace pvs {

namespace {

nlohmann::json vec(const glm::dvec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json crossing_counts(const CrossingReport& r)
{
    return {{"portals", r.portals}, {"traced", r.traced},   {"open", r.open()},
            {"blocked", r.blocked.size()}, {"unplaced", r.unplaced}, {"opaque", r.opaque}};
}

void add_blocked(const char* source, const CrossingReport& r, nlohmann::json& out)
{
    for (const BlockedCrossing& c : r.blocked)
        out.push_back({{"source", source},
                       {"portal", c.portal},
                       {"regions", {c.regions[0], c.regions[1]}},
                       {"position", vec(c.centre)},
                       {"normal", vec(c.normal)},
                       {"blocked_at", vec(c.blocked_at)}});
}

// Where each example is: its region, the other region of a pair, its point (null when none).
nlohmann::json places_json(const CheckItem& item)
{
    nlohmann::json places = nlohmann::json::array();
    for (const CheckPlace& p : item.places)
        places.push_back({{"region", p.region >= 0 ? nlohmann::json(p.region) : nlohmann::json(nullptr)},
                          {"other", p.other >= 0 ? nlohmann::json(p.other) : nlohmann::json(nullptr)},
                          {"point", p.has_point ? nlohmann::json::array({p.point.x, p.point.y, p.point.z})
                                                : nlohmann::json(nullptr)}});
    return places;
}

} // namespace

nlohmann::json zone_health_json(const Zone& zone, const ZoneHealth& health)
{
    nlohmann::json checks = nlohmann::json::array();
    for (const CheckItem& item : health.items)
        checks.push_back({{"name", item.name},
                          {"severity", check_severity_name(item.severity)},
                          {"applicable", item.applicable},
                          {"passed", item.passed()},
                          {"checked", item.checked},
                          {"failed", item.failed},
                          {"summary", item.summary},
                          {"examples", item.examples},
                          {"places", places_json(item)}});
    nlohmann::json blocked = nlohmann::json::array();
    add_blocked("tree", health.tree_crossings, blocked);
    add_blocked("file", health.file_crossings, blocked);
    const bool has_file_portals = zone.portals.has_value();
    return {{"file", zone.source.path},
            {"format", zone.source.format},
            {"regions", zone.regions.size()},
            {"errors", health.errors()},
            {"warnings", health.warnings()},
            {"healthy", health.errors() == 0},
            {"checks", checks},
            {"crossings",
             {{"tree", crossing_counts(health.tree_crossings)},
              {"file", has_file_portals ? crossing_counts(health.file_crossings) : nlohmann::json()}}},
            {"blocked_crossings", blocked},
            {"leak_regions", health.leak_regions}};
}

} // namespace pvs
