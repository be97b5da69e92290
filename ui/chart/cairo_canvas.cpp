#include "ui/chart/cairo_canvas.h"

#include "ui/chart/cairo_library.h"

#include <string>

namespace pvs::ui::chart {

namespace {

const CairoLibrary& cairo() { return cairo_library(); }

void set_color(cairo_t* cr, Color c)
{
    cairo().set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, c.a / 255.0);
}

} // namespace

CairoCanvas::CairoCanvas(cairo_t* context, float font_size) : context_(context), font_size_(font_size)
{
    cairo().select_font_face(context_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo().set_font_size(context_, double(font_size_));
    cairo_font_extents_t extents;
    cairo().font_extents(context_, &extents);
    ascent_ = float(extents.ascent);
}

void CairoCanvas::line(glm::vec2 a, glm::vec2 b, Color color, float thickness)
{
    set_color(context_, color);
    cairo().set_line_width(context_, double(thickness));
    cairo().move_to(context_, double(a.x), double(a.y));
    cairo().line_to(context_, double(b.x), double(b.y));
    cairo().stroke(context_);
}

void CairoCanvas::rect(glm::vec2 min, glm::vec2 max, Color fill)
{
    set_color(context_, fill);
    cairo().rectangle(context_, double(min.x), double(min.y), double(max.x - min.x), double(max.y - min.y));
    cairo().fill(context_);
}

void CairoCanvas::circle(glm::vec2 center, float radius, Color fill, Color outline)
{
    cairo().new_sub_path(context_);
    cairo().arc(context_, double(center.x), double(center.y), double(radius), 0.0, 6.283185307179586);
    set_color(context_, fill);
    cairo().fill_preserve(context_);
    set_color(context_, outline);
    cairo().set_line_width(context_, 1.0);
    cairo().stroke(context_);
}

float CairoCanvas::text_width(std::string_view text) const
{
    const std::string terminated(text); // cairo takes NUL-terminated UTF-8
    cairo_text_extents_t extents;
    cairo().text_extents(context_, terminated.c_str(), &extents);
    return float(extents.x_advance);
}

void CairoCanvas::text(glm::vec2 pos, std::string_view text, Color color, Align align)
{
    if (align != Align::Left)
        pos.x -= align == Align::Center ? text_width(text) * 0.5f : text_width(text);
    const std::string terminated(text);
    set_color(context_, color);
    cairo().move_to(context_, double(pos.x), double(pos.y + ascent_));
    cairo().show_text(context_, terminated.c_str());
    cairo().new_path(context_); // show_text leaves the current point at the text's end
}

} // namespace pvs::ui::chart
