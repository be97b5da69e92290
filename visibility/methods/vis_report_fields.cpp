#include "visibility/methods/vis_report_fields.h"

namespace pvs {

std::vector<ReportField> vis_report_fields(const VisReport& r, bool full, bool flow_2d)
{
    const auto count = [](size_t v) { return uint64_t(v); };
    std::vector<ReportField> f = {
        {"threads", uint64_t(r.threads)},
        {"portals", count(r.portals)},
        {"portals_skipped", count(r.portals_skipped)},
        {"base_seconds", r.base_seconds},
        {"passage_pairs", count(r.passage_pairs)},
        {"passage_seconds", r.passage_seconds},
        {"target_checks", count(r.target_checks)},
        {"target_check_prunes", count(r.target_check_prunes)},
        {"dominated_windows", count(r.dominated_windows)},
        {"saw_into_own_region", count(r.saw_into_own_region)},
        {"leaf_recursions", count(r.leaf_recursions)},
        {"flow_frames", count(r.frames)},
        {"flow_frames_floor", count(r.portal_visible)},
    };
    if (!full || r.cancelled)
        return f;
    const auto work = [&](const char* name, size_t v) { f.push_back({std::string(kWorkPrefix) + name, uint64_t(v)}); };
    work("flow_frames", r.frames);
    work("flow_clips", r.clips);
    work("flow_separators", r.separators);
    work("target_checks", r.target_checks);
    if (flow_2d)
        work("flow_separator_candidates", r.separator_candidates);
    else
        work("passage_pairs", r.passage_pairs);
    work("dominated_windows", r.dominated_windows);
    return f;
}

} // namespace pvs
