// A ratio per item as horizontal bars on a log axis, sorted: the peer benchmark's chart (pvscope's
// time over a peer's, one bar per map and mode). Reference lines mark targets (0.1x, 0.2x, ...) and
// parity (1x); bars are coloured by group (a corpus). Data in, drawing out (canvas.h).
#pragma once

#include "ui/chart/canvas.h"

#include <glm/vec2.hpp>

#include <span>
#include <string>
#include <vector>

namespace pvs::ui::chart {

struct RatioBar {
    std::string label; // e.g. "freedoom2:MAP10 full"
    std::string group; // colours: one per group
    double ratio = 0;  // > 0; bars at or below 0 are not drawn
};

struct RatioLine {
    double ratio = 1;
    std::string label; // e.g. "target 0.2x"
};

// Draws the bars sorted by ratio (smallest at the top) into the rectangle at origin of `size`.
void draw_ratio_chart(std::span<const RatioBar> bars, std::span<const RatioLine> lines, const std::string& title,
                      Canvas& canvas, glm::vec2 origin, glm::vec2 size);

// The height in pixels the chart needs to give every bar `bar_height`.
float ratio_chart_height(size_t bars, float bar_height = 14.0f);

} // namespace pvs::ui::chart
