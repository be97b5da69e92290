#include "ui/chart/speed_accuracy_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

namespace pvs::ui::chart {

namespace {

constexpr Color kBackground{255, 255, 255, 255};
constexpr Color kPlotBackground{248, 248, 250, 255};
constexpr Color kAxis{60, 60, 60, 255};
constexpr Color kGrid{220, 220, 226, 255};
constexpr Color kFront{150, 150, 150, 255};
constexpr Color kText{20, 20, 20, 255};
constexpr Color kZeroLine{40, 150, 60, 255};

// One colour per method, in order of first appearance (Tableau 10).
constexpr Color kPalette[] = {{31, 119, 180, 255}, {255, 127, 14, 255}, {44, 160, 44, 255}, {214, 39, 40, 255},
                              {148, 103, 189, 255}, {140, 86, 75, 255},  {227, 119, 194, 255}, {127, 127, 127, 255},
                              {188, 189, 34, 255},  {23, 190, 207, 255}};

double bits_axis(double bits) { return std::log10(1.0 + std::max(0.0, bits)); }

std::string bits_tick(double decade)
{
    const double v = std::pow(10.0, decade);
    if (decade < 0.5)
        return "0";
    char text[32];
    if (v >= 1e6)
        std::snprintf(text, sizeof text, "%gM", v / 1e6);
    else if (v >= 1e3)
        std::snprintf(text, sizeof text, "%gk", v / 1e3);
    else
        std::snprintf(text, sizeof text, "%g", v);
    return text;
}

std::string seconds_tick(double decade)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g s", std::pow(10.0, decade));
    return text;
}

struct Axes {
    double x_min, x_max; // log10 seconds; the "stored" column is left of x_min
    double y_max;        // log10(1 + bits)
};

// A panel's plot area and the mapping into it.
struct Panel {
    glm::vec2 min, max;
    float stored_width; // the column for points that baked nothing
    Axes axes;

    glm::vec2 place(double seconds, double bits) const
    {
        const float plot_left = min.x + stored_width;
        float x;
        if (seconds <= 0.0)
            x = min.x + stored_width * 0.5f;
        else
            x = plot_left + float((std::log10(seconds) - axes.x_min) / (axes.x_max - axes.x_min)) * (max.x - plot_left);
        const float y = max.y - float(bits_axis(bits) / axes.y_max) * (max.y - min.y);
        return {x, y};
    }
};

Axes fit_axes(std::span<const ChartPoint> points)
{
    double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest(), y = 1.0;
    for (const ChartPoint& p : points) {
        if (p.seconds > 0.0) {
            lo = std::min(lo, std::log10(p.seconds));
            hi = std::max(hi, std::log10(p.seconds));
        }
        y = std::max({y, bits_axis(p.missing_bits), bits_axis(p.excess_bits)});
    }
    if (lo > hi)
        lo = hi = 0.0;
    return {std::floor(lo), std::max(std::ceil(hi), std::floor(lo) + 1.0), std::ceil(y)};
}

void draw_frame(const Panel& panel, const std::string& title, Canvas& canvas)
{
    canvas.rect(panel.min, panel.max, kPlotBackground);
    const float th = canvas.text_height();
    for (double d = 0.0; d <= panel.axes.y_max + 1e-9; d += 1.0) {
        const float y = panel.place(1.0, std::pow(10.0, d) - 1.0).y;
        canvas.line({panel.min.x, y}, {panel.max.x, y}, d == 0.0 ? kZeroLine : kGrid, d == 0.0 ? 1.5f : 1.0f);
        canvas.text({panel.min.x - 6.0f, y - th * 0.5f}, bits_tick(d), kText, Align::Right);
    }
    for (double d = panel.axes.x_min; d <= panel.axes.x_max + 1e-9; d += 1.0) {
        const float x = panel.place(std::pow(10.0, d), 0.0).x;
        canvas.line({x, panel.min.y}, {x, panel.max.y}, kGrid, 1.0f);
        canvas.text({x, panel.max.y + 4.0f}, seconds_tick(d), kText, Align::Center);
    }
    const float stored_right = panel.min.x + panel.stored_width;
    canvas.line({stored_right, panel.min.y}, {stored_right, panel.max.y}, kAxis, 1.0f);
    canvas.text({panel.min.x + panel.stored_width * 0.5f, panel.min.y + 4.0f}, "stored", kText, Align::Center);
    canvas.line(panel.min, {panel.min.x, panel.max.y}, kAxis, 1.0f);
    canvas.line({panel.min.x, panel.max.y}, panel.max, kAxis, 1.0f);
    canvas.text({(panel.min.x + panel.max.x) * 0.5f, panel.min.y - th - 6.0f}, title, kText, Align::Center);
    canvas.text({(panel.min.x + panel.max.x) * 0.5f, panel.max.y + th + 8.0f}, "bake time (log)", kText, Align::Center);
}

void draw_front(const Panel& panel, std::span<const ChartPoint> points, std::span<const double> values, Canvas& canvas)
{
    std::vector<double> seconds;
    for (const ChartPoint& p : points)
        seconds.push_back(p.seconds);
    const std::vector<size_t> front = pareto_front(seconds, values);
    for (size_t k = 1; k < front.size(); ++k) {
        const glm::vec2 a = panel.place(points[front[k - 1]].seconds, values[front[k - 1]]);
        const glm::vec2 b = panel.place(points[front[k]].seconds, values[front[k]]);
        canvas.line(a, {b.x, a.y}, kFront, 2.0f);
        canvas.line({b.x, a.y}, b, kFront, 2.0f);
    }
}

} // namespace

std::vector<size_t> pareto_front(std::span<const double> seconds, std::span<const double> values)
{
    std::vector<size_t> order(seconds.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return seconds[a] != seconds[b] ? seconds[a] < seconds[b] : values[a] < values[b];
    });
    std::vector<size_t> front;
    double best = std::numeric_limits<double>::infinity();
    for (size_t i : order)
        if (values[i] < best) {
            best = values[i];
            front.push_back(i);
        }
    return front;
}

PointPositions draw_speed_accuracy_chart(std::span<const ChartPoint> points, const std::string& title, Canvas& canvas,
                                         glm::vec2 origin, glm::vec2 size)
{
    canvas.rect(origin, origin + size, kBackground);
    const float th = canvas.text_height();
    canvas.text({origin.x + size.x * 0.5f, origin.y + 6.0f}, title, kText, Align::Center);
    const Axes axes = fit_axes(points);
    const float margin_left = canvas.text_width("100k") + 14.0f, gap = margin_left + 10.0f;
    const float top = origin.y + 3.0f * th + 12.0f, bottom = origin.y + size.y - 2.0f * th - 16.0f;
    const float panel_width = (size.x - margin_left - gap - 10.0f) * 0.5f;
    const float stored = std::min(60.0f, panel_width * 0.15f);
    const Panel panels[2] = {
        {{origin.x + margin_left, top}, {origin.x + margin_left + panel_width, bottom}, stored, axes},
        {{origin.x + margin_left + panel_width + gap, top},
         {origin.x + margin_left + 2.0f * panel_width + gap, bottom}, stored, axes}};
    std::vector<double> missing, excess;
    for (const ChartPoint& p : points) {
        missing.push_back(p.missing_bits);
        excess.push_back(p.excess_bits);
    }
    draw_frame(panels[0], "missing bits (would pop; 0 = conservative)", canvas);
    draw_frame(panels[1], "excess bits (would overdraw)", canvas);
    draw_front(panels[0], points, missing, canvas);
    draw_front(panels[1], points, excess, canvas);

    std::vector<std::string> methods;
    std::vector<Color> colors;
    PointPositions positions(points.size());
    // Every point first (their circles are taken space), then a label beside each where it
    // overlaps no circle and no label drawn before it: right of the point, else left, above, below,
    // else none.
    std::vector<std::array<glm::vec2, 2>> taken[2];
    for (size_t i = 0; i < points.size(); ++i) {
        const ChartPoint& p = points[i];
        auto known = std::find(methods.begin(), methods.end(), p.method);
        if (known == methods.end())
            known = methods.insert(methods.end(), p.method);
        colors.push_back(kPalette[size_t(known - methods.begin()) % std::size(kPalette)]);
        for (int side = 0; side < 2; ++side) {
            const glm::vec2 at = panels[side].place(p.seconds, side == 0 ? p.missing_bits : p.excess_bits);
            positions[i][size_t(side)] = at;
            canvas.circle(at, 4.5f, colors.back(), kAxis);
            taken[side].push_back({at - glm::vec2(5.0f), at + glm::vec2(5.0f)});
        }
    }
    auto try_label = [&](int side, glm::vec2 min, glm::vec2 max) {
        if (min.x < panels[side].min.x || max.x > panels[side].max.x)
            return false;
        for (const auto& r : taken[side])
            if (min.x < r[1].x && r[0].x < max.x && min.y < r[1].y && r[0].y < max.y)
                return false;
        taken[side].push_back({min, max});
        return true;
    };
    for (size_t i = 0; i < points.size(); ++i)
        for (int side = 0; side < 2; ++side) {
            const glm::vec2 at = positions[i][size_t(side)];
            const glm::vec2 extent(canvas.text_width(points[i].label), th);
            const glm::vec2 places[] = {{at.x + 7.0f, at.y - th * 0.5f},
                                        {at.x - 7.0f - extent.x, at.y - th * 0.5f},
                                        {at.x - extent.x * 0.5f, at.y - 6.0f - th},
                                        {at.x - extent.x * 0.5f, at.y + 6.0f}};
            for (const glm::vec2& place : places)
                if (try_label(side, place, place + extent)) {
                    canvas.text(place, points[i].label, colors[i]);
                    break;
                }
        }
    return positions;
}

int point_near(const PointPositions& positions, glm::vec2 at, float radius)
{
    int best = -1;
    float best_d2 = radius * radius;
    for (size_t i = 0; i < positions.size(); ++i)
        for (const glm::vec2& p : positions[i]) {
            const glm::vec2 d = p - at;
            const float d2 = d.x * d.x + d.y * d.y;
            if (d2 <= best_d2) {
                best_d2 = d2;
                best = int(i);
            }
        }
    return best;
}

} // namespace pvs::ui::chart
