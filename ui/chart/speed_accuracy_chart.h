// The speed-vs-accuracy chart of `pvscope compare` and the inspector's Compare panel: one
// labelled point per method and parameter, time on a log axis against accuracy, in two panels
// side by side — missing bits (sight lines the method would pop: a conservative method sits on
// the 0 line) and excess bits (pairs beyond the reference: what it would overdraw). The Pareto
// front of each panel (no other point is both faster and closer) is drawn as a step line.
//
// Axes: x is log10 of the bake's seconds (methods that bake nothing, the file's PVS and none,
// sit in a column at the left marked "stored"); y is log10(1 + bits), with ticks at 0, 1, 10,
// 100 ..., so 0 is a line and every decade is visible. Data in, drawing out (canvas.h): the
// layout does not know where it is drawn.
#pragma once

#include "ui/chart/canvas.h"

#include <glm/vec2.hpp>

#include <array>
#include <span>
#include <string>
#include <vector>

namespace pvs::ui::chart {

struct ChartPoint {
    std::string label;   // shown beside the point, e.g. "portal-full L2"
    std::string method;  // colours: one per method name
    double seconds = 0;  // bake wall clock; 0 = nothing baked (stored)
    double missing_bits = 0;
    double excess_bits = 0;
};

// Where each point was drawn, in each panel (missing, excess): for hit tests.
using PointPositions = std::vector<std::array<glm::vec2, 2>>;

PointPositions draw_speed_accuracy_chart(std::span<const ChartPoint> points, const std::string& title, Canvas& canvas,
                                         glm::vec2 origin, glm::vec2 size);

// The index of the point drawn nearest `at` within `radius` pixels, or -1.
int point_near(const PointPositions& positions, glm::vec2 at, float radius);

// Indices of the Pareto front of (seconds, value), fastest first: each is strictly better in
// value than every faster point. Exposed for tests.
std::vector<size_t> pareto_front(std::span<const double> seconds, std::span<const double> values);

} // namespace pvs::ui::chart
