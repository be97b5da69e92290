#include "ui/gui/compare_job.h"

namespace pvs::gui {

bool CompareJob::start(const Zone& zone, const ui::CompareOptions& options)
{
    return job_.start(
        [&zone, options](JobControl& control) {
            ui::CompareOptions run_options = options;
            run_options.progress = [&control](const std::string& stage, double fraction) {
                control.set_stage(stage);
                control.set_progress(fraction);
                return !control.cancel_requested();
            };
            return ui::run_compare(zone, run_options);
        },
        [](const ui::CompareResult& result) { return !result.cancelled; });
}

const std::optional<ui::CompareResult>& CompareJob::result() const
{
    static const std::optional<ui::CompareResult> kNone;
    return job_.status() == JobStatus::Done ? job_.output() : kNone;
}

} // namespace pvs::gui
