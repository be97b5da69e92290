// A progress display for long commands (`pvscope bake`), written to one stream (stderr).
//
// On a terminal: one line redrawn in place with '\r' — "label [#####.....]  42%  3.1 s" — at
// most every 100 ms, ended with a newline by finish(). Not on a terminal (a log file, CI): plain
// lines "label: 40%" each time the fraction crosses another 10 %, so a log stays short and
// readable. update() is cheap to call often; only the caller's thread may use the object.
#pragma once

#include <atomic>
#include <chrono>
#include <memory>
#include <cstdio>
#include <string>

namespace pvs::app {

class ProgressBar {
public:
    enum class Style { Auto, Terminal, Lines };
    // Auto picks Terminal when `out` is a terminal (isatty), Lines otherwise.
    ProgressBar(std::FILE* out, std::string label, Style style = Style::Auto);
    // finish()es if not done yet: "done", or "stopped" when an exception is leaving the caller
    // (the error follows, so the bar must not say the work is done).
    ~ProgressBar();

    void update(double fraction); // fraction in [0, 1]; values outside are clamped
    // Prints one line of text above the bar (a terminal's bar is cleared, the line written, the
    // bar redrawn); as lines, just the line.
    void note(const std::string& line);
    // Ends the display: on a terminal, redraws the last value and ends the line with `suffix`
    // ("done", "cancelled"); as lines, prints "label: suffix". Further calls do nothing.
    void finish(const std::string& suffix = "done");

    bool terminal() const { return terminal_; }

private:
    void draw(double fraction);

    std::FILE* out_;
    std::string label_;
    bool terminal_;
    bool finished_ = false;
    int exceptions_at_start_; // std::uncaught_exceptions() when made
    double last_fraction_ = 0.0;
    int last_decile_ = -1;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point last_draw_;
};

// Progress of work in named stages (compare, stability): a bar per stage, drawn anew when the
// stage changes. As a progress callback it returns false once `cancel` is set (Ctrl-C).
class StagedProgress {
public:
    StagedProgress(std::FILE* out, const std::atomic<bool>* cancel) : out_(out), cancel_(cancel) {}
    bool operator()(const std::string& stage, double fraction);
    void finish() { bar_.reset(); }

private:
    std::FILE* out_;
    const std::atomic<bool>* cancel_;
    std::string stage_;
    std::unique_ptr<ProgressBar> bar_;
};

} // namespace pvs::app
