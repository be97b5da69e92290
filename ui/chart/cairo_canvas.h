// A chart canvas (canvas.h) drawing with cairo onto any cairo surface: antialiased lines and
// circles, and real text in the system's sans-serif face (fontconfig), measured by cairo itself so
// that labels are laid out by their true widths. chart_file.h makes the surfaces (PNG, SVG, PDF).
#pragma once

#include "ui/chart/canvas.h"

typedef struct _cairo cairo_t;

namespace pvs::ui::chart {

class CairoCanvas final : public Canvas {
public:
    // `context` stays the caller's; the canvas sets its font and draws, nothing else.
    CairoCanvas(cairo_t* context, float font_size = 13.0f);
    void line(glm::vec2 a, glm::vec2 b, Color color, float thickness) override;
    void rect(glm::vec2 min, glm::vec2 max, Color fill) override;
    void circle(glm::vec2 center, float radius, Color fill, Color outline) override;
    void text(glm::vec2 pos, std::string_view text, Color color, Align align) override;
    float text_height() const override { return font_size_; }
    float text_width(std::string_view text) const override;

private:
    cairo_t* context_;
    float font_size_;
    float ascent_ = 0; // of the face at font_size_: where the baseline sits below a line's top
};

} // namespace pvs::ui::chart
