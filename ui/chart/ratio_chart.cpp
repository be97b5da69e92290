#include "ui/chart/ratio_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pvs::ui::chart {

namespace {

constexpr float kTop = 52, kBottom = 40, kRight = 24, kBar = 14;

Color group_color(const std::string& group, std::span<const RatioBar> bars)
{
    static const Color palette[] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}, {148, 103, 189}, {255, 127, 14}};
    std::vector<std::string> groups;
    for (const RatioBar& b : bars)
        if (std::find(groups.begin(), groups.end(), b.group) == groups.end())
            groups.push_back(b.group);
    const size_t i = size_t(std::find(groups.begin(), groups.end(), group) - groups.begin());
    return palette[i % (sizeof palette / sizeof palette[0])];
}

std::string ratio_text(double r)
{
    char text[32];
    std::snprintf(text, sizeof text, r >= 0.1 ? "%.2fx" : "%.3fx", r);
    return text;
}

} // namespace

float ratio_chart_height(size_t bars, float bar_height) { return kTop + kBottom + float(bars) * bar_height; }

void draw_ratio_chart(std::span<const RatioBar> bars, std::span<const RatioLine> lines, const std::string& title,
                      Canvas& canvas, glm::vec2 origin, glm::vec2 size)
{
    std::vector<RatioBar> sorted;
    for (const RatioBar& b : bars)
        if (b.ratio > 0 && std::isfinite(b.ratio))
            sorted.push_back(b);
    std::stable_sort(sorted.begin(), sorted.end(), [](const RatioBar& a, const RatioBar& b) { return a.ratio < b.ratio; });
    const Color ink{40, 40, 40}, grid{200, 200, 200};
    canvas.text(origin + glm::vec2(size.x / 2, 6), title, ink, Align::Center);
    if (sorted.empty())
        return;

    float label_width = 0;
    for (const RatioBar& b : sorted)
        label_width = std::max(label_width, canvas.text_width(b.label));
    const float left = origin.x + label_width + 12, right = origin.x + size.x - kRight;
    const float top = origin.y + kTop;
    const float bar = std::min(kBar, (size.y - kTop - kBottom) / float(sorted.size()));
    const float bottom = top + bar * float(sorted.size());

    // A log axis over whole decades that hold every bar and line.
    double lo = sorted.front().ratio, hi = sorted.back().ratio;
    for (const RatioLine& l : lines)
        lo = std::min(lo, l.ratio), hi = std::max(hi, l.ratio);
    const double d0 = std::floor(std::log10(lo)), d1 = std::max(d0 + 1, std::ceil(std::log10(hi)));
    const auto x_of = [&](double r) { return left + float((std::log10(r) - d0) / (d1 - d0)) * (right - left); };

    for (double d = d0; d <= d1; ++d) {
        const float x = x_of(std::pow(10.0, d));
        canvas.line({x, top}, {x, bottom}, grid, 1);
        canvas.text({x, bottom + 4}, ratio_text(std::pow(10.0, d)), ink, Align::Center);
    }
    for (size_t i = 0; i < sorted.size(); ++i) {
        const float y = top + bar * float(i);
        const Color c = group_color(sorted[i].group, bars);
        canvas.rect({left, y + 1}, {x_of(sorted[i].ratio), y + bar - 1}, c);
        canvas.text({left - 6, y + (bar - canvas.text_height()) / 2}, sorted[i].label, ink, Align::Right);
    }
    for (const RatioLine& l : lines) {
        const float x = x_of(l.ratio);
        canvas.line({x, top - 4}, {x, bottom}, {0, 0, 0}, 1.5f);
        canvas.text({x, top - 6 - canvas.text_height()}, l.label, ink, Align::Center);
    }
    // The legend: one swatch per group, under the axis labels.
    float x = left;
    std::vector<std::string> seen;
    for (const RatioBar& b : bars) {
        if (std::find(seen.begin(), seen.end(), b.group) != seen.end())
            continue;
        seen.push_back(b.group);
        const float y = bottom + 6 + canvas.text_height();
        canvas.rect({x, y + 2}, {x + 10, y + 12}, group_color(b.group, bars));
        canvas.text({x + 14, y}, b.group, ink);
        x += 24 + canvas.text_width(b.group);
    }
}

} // namespace pvs::ui::chart
