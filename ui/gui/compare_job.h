// `compare` on a background thread, for the inspector's Compare panel: ui::run_compare over the
// open zone as a BackgroundJob (background_job.h: its states, progress, the stage it is in,
// cancel and lifetime rules). Done when the compare ran to the end: result() holds the rows.
#pragma once

#include "ui/gui/background_job.h"
#include "render/method_compare.h"

#include <optional>
#include <string>

namespace pvs::gui {

class CompareJob {
public:
    // Starts comparing on `zone`; false (and nothing happens) while a compare is running.
    bool start(const Zone& zone, const ui::CompareOptions& options);
    void cancel() { job_.cancel(); }
    void stop() { job_.stop(); }
    JobStatus poll() { return job_.poll(); }

    JobStatus status() const { return job_.status(); }
    double progress() const { return job_.progress(); }
    std::string stage() const { return job_.stage(); }
    // The rows (Done only).
    const std::optional<ui::CompareResult>& result() const;
    const std::string& error() const { return job_.error(); }

private:
    BackgroundJob<ui::CompareResult> job_;
};

} // namespace pvs::gui
