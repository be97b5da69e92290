// A portal bake's report (VisReport, portal_vis.h) as named report fields (report_field.h): the
// names `bake --report` and `vis --report` have always written, and the flow's work counters under
// "work." (frames entered, windings or segments clipped, separators used, target checks, dominated
// windows, passage pairs; in 2-D also the separator candidates tried).
#pragma once

#include "visibility/methods/report_field.h"
#include "visibility/portal/portal_vis.h"

#include <vector>

namespace pvs {

std::vector<ReportField> vis_report_fields(const VisReport& report, bool full, bool flow_2d);

} // namespace pvs
