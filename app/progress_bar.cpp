#include "app/progress_bar.h"

#include <algorithm>
#include <exception>
#include <unistd.h>

namespace pvs::app {

namespace {
constexpr int kBarWidth = 30;
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);
} // namespace

ProgressBar::ProgressBar(std::FILE* out, std::string label, Style style)
    : out_(out), label_(std::move(label)),
      terminal_(style == Style::Terminal || (style == Style::Auto && isatty(fileno(out)) == 1)),
      exceptions_at_start_(std::uncaught_exceptions()), start_(std::chrono::steady_clock::now()),
      last_draw_(start_ - kRedrawInterval)
{
}

ProgressBar::~ProgressBar() { finish(std::uncaught_exceptions() > exceptions_at_start_ ? "stopped" : "done"); }

void ProgressBar::note(const std::string& line)
{
    if (terminal_ && !finished_)
        std::fputs("\r\033[K", out_);
    std::fprintf(out_, "%s\n", line.c_str());
    if (terminal_ && !finished_)
        draw(last_fraction_);
    std::fflush(out_);
}

void ProgressBar::update(double fraction)
{
    if (finished_)
        return;
    fraction = std::clamp(fraction, 0.0, 1.0);
    last_fraction_ = fraction;
    if (!terminal_) {
        const int decile = int(fraction * 10.0);
        if (decile > last_decile_) {
            last_decile_ = decile;
            std::fprintf(out_, "%s: %d%%\n", label_.c_str(), decile * 10);
            std::fflush(out_);
        }
        return;
    }
    const auto now = std::chrono::steady_clock::now();
    if (now - last_draw_ < kRedrawInterval)
        return;
    last_draw_ = now;
    draw(fraction);
}

void ProgressBar::draw(double fraction)
{
    const int filled = int(fraction * kBarWidth);
    std::string bar(size_t(filled), '#');
    bar.append(size_t(kBarWidth - filled), '.');
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(out_, "\r%s [%s] %3d%%  %.1f s", label_.c_str(), bar.c_str(), int(fraction * 100.0), seconds);
    std::fflush(out_);
}

void ProgressBar::finish(const std::string& suffix)
{
    if (finished_)
        return;
    finished_ = true;
    if (terminal_) {
        draw(last_fraction_);
        std::fprintf(out_, "  %s\n", suffix.c_str());
    } else {
        std::fprintf(out_, "%s: %s\n", label_.c_str(), suffix.c_str());
    }
    std::fflush(out_);
}

bool StagedProgress::operator()(const std::string& stage, double fraction)
{
    if (!bar_ || stage != stage_) {
        bar_ = std::make_unique<ProgressBar>(out_, stage);
        stage_ = stage;
    }
    bar_->update(fraction);
    return !(cancel_ && cancel_->load());
}

} // namespace pvs::app
