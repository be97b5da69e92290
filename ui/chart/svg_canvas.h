// A chart canvas (canvas.h) that writes SVG 1.1: text stays text (searchable, scalable). Text
// widths are estimated (0.6 em per character of a sans-serif face), enough for layout.
#pragma once

#include "ui/chart/canvas.h"

#include <string>

namespace pvs::ui::chart {

class SvgCanvas final : public Canvas {
public:
    SvgCanvas(float width, float height, float font_size = 13.0f);
    void line(glm::vec2 a, glm::vec2 b, Color color, float thickness) override;
    void rect(glm::vec2 min, glm::vec2 max, Color fill) override;
    void circle(glm::vec2 center, float radius, Color fill, Color outline) override;
    void text(glm::vec2 pos, std::string_view text, Color color, Align align) override;
    float text_height() const override { return font_size_; }
    float text_width(std::string_view text) const override { return 0.6f * font_size_ * float(text.size()); }
    // The document so far, closed.
    std::string svg() const { return body_ + "</svg>\n"; }

private:
    float font_size_;
    std::string body_;
};

} // namespace pvs::ui::chart
