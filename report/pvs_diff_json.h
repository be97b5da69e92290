// A baked PVS against the one a file held before, for `bake --report` and `vis --report`
// ("file_pvs"): mean visible of each, the bits only each holds, the rows that differ and the rows
// with bits only the bake holds, and the file's missing rows (read as all visible, as engines do).
// Built on pvs_gap (visibility/eval/pvs_gap.h) with the file's PVS as the reference.
#pragma once

#include "visibility/pvs.h"

#include <nlohmann/json.hpp>

namespace pvs::report {

nlohmann::json pvs_diff_json(const Pvs& baked, const Pvs& file);

} // namespace pvs::report
