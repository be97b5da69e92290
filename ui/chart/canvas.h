// What the chart draws on: lines, filled circles, rectangles and text in pixel coordinates
// (y down). Two implementations: cairo (cairo_canvas.h: the command line's PNG, SVG and PDF) and
// an ImGui draw list (ui/gui/chart_imgui_canvas.h: the inspector's Compare panel).
#pragma once

#include <glm/vec2.hpp>

#include <cstdint>
#include <string_view>

namespace pvs::ui::chart {

struct Color {
    uint8_t r = 0, g = 0, b = 0, a = 255;
};

enum class Align : uint8_t { Left, Center, Right };

class Canvas {
public:
    virtual ~Canvas() = default;
    virtual void line(glm::vec2 a, glm::vec2 b, Color color, float thickness) = 0;
    virtual void rect(glm::vec2 min, glm::vec2 max, Color fill) = 0;
    virtual void circle(glm::vec2 center, float radius, Color fill, Color outline) = 0;
    // `pos` is the top of the text line, on its left edge, centre or right edge as aligned.
    virtual void text(glm::vec2 pos, std::string_view text, Color color, Align align = Align::Left) = 0;
    virtual float text_height() const = 0;
    virtual float text_width(std::string_view text) const = 0;
};

} // namespace pvs::ui::chart
