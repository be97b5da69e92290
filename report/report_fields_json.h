// Report fields (visibility/methods/report_field.h) into a JSON object: a dotted name nests
// ("work.flow_frames" becomes {"work": {"flow_frames": ...}}), a name already present is replaced.
#pragma once

#include "visibility/methods/report_field.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace pvs::report {

void add_report_fields(nlohmann::json& object, const std::vector<ReportField>& fields);

} // namespace pvs::report
