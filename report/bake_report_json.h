// The JSON report of a bake (`bake --report`, `vis --report`): what was read and written, the
// method's run (its summary, its report fields and work counters), the rows written and how they
// differ from the rows the file held. Fields are documented in docs/baking.md.
#pragma once

#include "visibility/methods/vis_method.h"
#include "visibility/pvs.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace pvs::report {

struct BakeReportHeader {
    std::string input;
    std::string output;
    std::string format; // the input's format as a user names it ("Quake BSP 29", "EverQuest S3D")
    std::string method; // the registry's name
    std::string params; // the method's label of its settings (VisMethod::label)
    Bound bound = Bound::Unknown;
    double load_seconds = 0.0;
    double write_seconds = 0.0;
    size_t edits_applied = 0; // a PVS edit list applied before writing
    size_t peak_rss_bytes = 0;
    std::vector<ReportField> written; // what the writer reports of the file it wrote (PvsWriteback::fields)
};

// `written` is the PVS written (after any edits); `file_pvs` the one the input held, or nullptr.
// "level" and "clusters" are null unless the method reports them; the run's fields and then the
// writer's come last and may nest ("clusters.clusters" is "clusters" in "clusters"). A writer's
// field replaces the bake's of the same name: a Quake 2 map's "clusters" and "mean_visible" are
// those of the rows written, per cluster (quake2_written_fields).
nlohmann::json bake_report_json(const BakeReportHeader& header, const MethodRun& run, const Pvs& written,
                                const Pvs* file_pvs);

} // namespace pvs::report
