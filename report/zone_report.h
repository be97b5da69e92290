// A zone's statistics as JSON, the shape `pvscope info --json` prints and the inspector's
// statistics export writes. Field names are stable: scripts read them.
#pragma once

#include "visibility/zone.h"
#include "visibility/zone_stats.h"

#include <nlohmann/json.hpp>

namespace pvs {

nlohmann::json zone_report_json(const Zone& zone, const ZoneStats& stats, double load_ms);

} // namespace pvs
