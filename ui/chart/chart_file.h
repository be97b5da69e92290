// The speed-vs-accuracy chart (speed_accuracy_chart.h) as a file or an image, drawn by cairo
// without a window or a GPU: PNG (antialiased, 8-bit RGBA), SVG and PDF (vector, text as the
// face's glyphs), chosen by the path's extension. One layout, the same as the inspector's panel.
#pragma once

#include "ui/chart/canvas.h"
#include "ui/chart/speed_accuracy_chart.h"
#include "render/software_renderer.h"

#include <functional>
#include <string>

namespace pvs::ui::chart {

enum class ChartFormat : uint8_t { Png, Svg, Pdf };

// .png, .svg or .pdf (any case); anything else throws std::invalid_argument naming the path and
// the formats.
ChartFormat chart_format_for(const std::string& path);

// The chart on a white background, width x height pixels.
Image render_chart_image(std::span<const ChartPoint> points, const std::string& title, uint32_t width, uint32_t height);

// Any drawing on a white page of width x height pixels, written in the format of `path`'s
// extension; throws as write_chart_file.
void write_canvas_file(uint32_t width, uint32_t height, const std::string& path,
                       const std::function<void(Canvas& canvas, glm::vec2 size)>& draw);

// Writes the chart in the format of `path`'s extension; throws std::runtime_error naming the path
// when it cannot be written (std::invalid_argument for an unknown extension).
void write_chart_file(std::span<const ChartPoint> points, const std::string& title, uint32_t width, uint32_t height,
                      const std::string& path);

} // namespace pvs::ui::chart
