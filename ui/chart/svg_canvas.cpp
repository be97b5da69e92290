#include "ui/chart/svg_canvas.h"

#include <cstdio>

namespace pvs::ui::chart {

namespace {

std::string rgb(Color c)
{
    char text[48];
    std::snprintf(text, sizeof text, "rgb(%d,%d,%d)", c.r, c.g, c.b);
    return text;
}

std::string escaped(std::string_view text)
{
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string format(const char* fmt, auto... args)
{
    char text[512];
    std::snprintf(text, sizeof text, fmt, args...);
    return text;
}

} // namespace

SvgCanvas::SvgCanvas(float width, float height, float font_size) : font_size_(font_size)
{
    body_ = format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%g\" height=\"%g\" viewBox=\"0 0 %g %g\" "
                   "font-family=\"DejaVu Sans, Arial, sans-serif\" font-size=\"%g\">\n",
                   double(width), double(height), double(width), double(height), double(font_size));
}

void SvgCanvas::line(glm::vec2 a, glm::vec2 b, Color color, float thickness)
{
    body_ += format("<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"%g\"/>\n",
                    double(a.x), double(a.y), double(b.x), double(b.y), rgb(color).c_str(), double(thickness));
}

void SvgCanvas::rect(glm::vec2 min, glm::vec2 max, Color fill)
{
    body_ += format("<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"%s\"/>\n", double(min.x),
                    double(min.y), double(max.x - min.x), double(max.y - min.y), rgb(fill).c_str());
}

void SvgCanvas::circle(glm::vec2 center, float radius, Color fill, Color outline)
{
    body_ += format("<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%g\" fill=\"%s\" stroke=\"%s\"/>\n", double(center.x),
                    double(center.y), double(radius), rgb(fill).c_str(), rgb(outline).c_str());
}

void SvgCanvas::text(glm::vec2 pos, std::string_view text, Color color, Align align)
{
    const char* anchor = align == Align::Left ? "start" : align == Align::Center ? "middle" : "end";
    // SVG places text by its baseline: about 0.8 em below the top of the line.
    body_ += format("<text x=\"%.1f\" y=\"%.1f\" fill=\"%s\" text-anchor=\"%s\">", double(pos.x),
                    double(pos.y + 0.8f * font_size_), rgb(color).c_str(), anchor);
    body_ += escaped(text) + "</text>\n";
}

} // namespace pvs::ui::chart
