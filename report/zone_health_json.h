// A zone's health report (visibility/eval/zone_check.h) as JSON, the shape `pvscope check --json`
// prints. Field names are stable: scripts read them.
//   { "file", "format", "regions", "errors", "warnings", "healthy",
//     "checks": [ { "name", "severity", "applicable", "passed", "checked", "failed", "summary",
//                   "examples": [...], "places": [ { "region", "other", "point": [x,y,z] } ] } ],
//     (one place per example, each field null when the failure has none),
//     "crossings": { "tree": {"portals", "traced", "open", "blocked", "unplaced", "opaque"},
//                    "file": {...} | null },
//     "blocked_crossings": [ { "source": "tree"|"file", "portal", "regions": [front, back],
//                              "position": [x,y,z], "normal": [x,y,z], "blocked_at": [x,y,z] } ],
//     "leak_regions": [...] }
#pragma once

#include "visibility/eval/zone_check.h"
#include "visibility/zone.h"

#include <nlohmann/json.hpp>

namespace pvs {

nlohmann::json zone_health_json(const Zone& zone, const ZoneHealth& health);

} // namespace pvs
