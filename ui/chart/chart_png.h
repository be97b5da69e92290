// The speed-vs-accuracy chart as an image, without a window or a GPU: the chart is drawn into a
// Dear ImGui draw list of a private, headless ImGui context (its default font), exactly as the
// inspector's panel draws it, and the list's triangles are rasterised here on the CPU (texture =
// the font atlas, colours per vertex, alpha blended). The caller's ImGui context, if any, is
// current again on return.
#pragma once

#include "ui/chart/speed_accuracy_chart.h"
#include "ui/software_renderer.h"

#include <string>

namespace pvs::ui::chart {

Image render_chart_image(std::span<const ChartPoint> points, const std::string& title, uint32_t width, uint32_t height);

// Writes the chart as PNG; throws std::runtime_error naming the path when it cannot.
void write_chart_png(std::span<const ChartPoint> points, const std::string& title, uint32_t width, uint32_t height,
                     const std::string& path);

} // namespace pvs::ui::chart
