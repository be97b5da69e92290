#include "app/pvs_source.h"

#include "visibility/portal/portal_vis.h"
#include "visibility/portal/portalize.h"

#include <cstdio>
#include <stdexcept>

namespace pvs::app {

const std::vector<std::string>& pvs_source_names()
{
    static const std::vector<std::string> names{"baked", "none", "portal-fast", "portal-full"};
    return names;
}

namespace {

PvsSource bake_now(const Zone& zone, VisParams::Method method, const std::string& name)
{
    PvsSource source;
    VisParams params;
    params.method = method;
    VisReport report;
    source.baked_now = bake_portal_vis(build_zone_portals(zone), uint32_t(zone.region_count()), params, &report);
    source.pvs = &*source.baked_now;
    char note[160];
    std::snprintf(note, sizeof note, "%s: %zu portals, mean %.1f visible of %zu regions, %.2f s on %u threads",
                  name.c_str(), report.portals, report.mean_visible, zone.region_count(), report.seconds,
                  report.threads);
    source.note = note;
    return source;
}

} // namespace

PvsSource make_pvs_source(const Zone& zone, const std::string& name)
{
    if (name == "baked") {
        PvsSource source;
        source.pvs = zone.baked_pvs ? &*zone.baked_pvs : nullptr;
        source.note = zone.baked_pvs ? "baked: the file's PVS" : "baked: the file has no PVS; culling with the frustum only";
        return source;
    }
    if (name == "none")
        return {std::nullopt, nullptr, "none: culling with the frustum only"};
    if (name == "portal-fast")
        return bake_now(zone, VisParams::Method::Fast, name);
    if (name == "portal-full")
        return bake_now(zone, VisParams::Method::Full, name);
    throw std::invalid_argument("unknown PVS source '" + name + "' (baked, none, portal-fast, portal-full)");
}

} // namespace pvs::app
