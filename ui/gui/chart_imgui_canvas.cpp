#include "ui/gui/chart_imgui_canvas.h"

#include <cfloat>
#include <cmath>

namespace pvs::ui::chart {

namespace {
ImU32 packed(Color c) { return IM_COL32(c.r, c.g, c.b, c.a); }
ImVec2 im(glm::vec2 v) { return {v.x, v.y}; }
} // namespace

void ImguiCanvas::line(glm::vec2 a, glm::vec2 b, Color color, float thickness)
{
    list_->AddLine(im(a), im(b), packed(color), thickness);
}

void ImguiCanvas::rect(glm::vec2 min, glm::vec2 max, Color fill) { list_->AddRectFilled(im(min), im(max), packed(fill)); }

void ImguiCanvas::circle(glm::vec2 center, float radius, Color fill, Color outline)
{
    list_->AddCircleFilled(im(center), radius, packed(fill), 16);
    list_->AddCircle(im(center), radius, packed(outline), 16, 1.0f);
}

float ImguiCanvas::text_width(std::string_view text) const
{
    return font_->CalcTextSizeA(font_size_, FLT_MAX, 0.0f, text.data(), text.data() + text.size()).x;
}

void ImguiCanvas::text(glm::vec2 pos, std::string_view text, Color color, Align align)
{
    if (align != Align::Left)
        pos.x -= align == Align::Center ? text_width(text) * 0.5f : text_width(text);
    // Whole pixels: the font atlas is sampled texel for texel.
    list_->AddText(font_, font_size_, ImVec2(std::floor(pos.x), std::floor(pos.y)), packed(color), text.data(),
                   text.data() + text.size());
}

} // namespace pvs::ui::chart
