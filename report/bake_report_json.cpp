#include "report/bake_report_json.h"

#include "report/pvs_diff_json.h"
#include "report/report_fields_json.h"
#include "visibility/eval/pvs_gap.h"

namespace pvs::report {

nlohmann::json bake_report_json(const BakeReportHeader& h, const MethodRun& run, const Pvs& written,
                                const Pvs* file_pvs)
{
    const uint32_t regions = written.region_count();
    const double mean_visible = pvs_gap(&written, written).mean_visible; // set bits per row
    nlohmann::json j = {{"input", h.input},
                        {"output", h.output},
                        {"format", h.format},
                        {"method", h.method},
                        {"params", h.params},
                        {"bound", bound_name(h.bound)},
                        {"summary", run.summary},
                        {"level", nullptr},
                        {"clusters", nullptr},
                        {"regions", regions},
                        {"time_seconds", run.seconds},
                        {"load_seconds", h.load_seconds},
                        {"write_seconds", h.write_seconds},
                        {"peak_memory_estimate_bytes", run.peak_bytes_estimate},
                        {"peak_rss_bytes", h.peak_rss_bytes},
                        {"mean_visible", mean_visible},
                        {"mean_visible_percent", regions ? 100.0 * mean_visible / regions : 0.0},
                        {"edits_applied", h.edits_applied}};
    add_report_fields(j, run.fields);
    add_report_fields(j, h.written);
    j["file_pvs"] = file_pvs ? pvs_diff_json(written, *file_pvs) : nlohmann::json(nullptr);
    return j;
}

} // namespace pvs::report
