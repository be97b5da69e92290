// plot_vis_scaling CSV PNG [COLUMN]: a log-log plot of bake time (COLUMN, default cpu_seconds)
// against portals, one line per method, from the rows bench_vis --vis_csv writes (a header line
// naming the columns, among them method, portals and COLUMN). The legend gives each method's
// fitted growth exponent (least squares of log COLUMN on log portals). Methods whose name starts
// with "clustered" are drawn dashed (clustered-fast is then the colour of portal-fast). Written
// for docs/images/vis_scaling.png without a plotting library: lines and text (stb_easy_font)
// rasterised by hand, the PNG written by stb_image_write.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_easy_font.h>
#include <stb_image_write.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Rgb = std::array<unsigned char, 3>;

struct Image {
    int width, height;
    std::vector<unsigned char> pixels;
    Image(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h) * 3, 255) {}

    void set(int x, int y, Rgb c)
    {
        if (x < 0 || y < 0 || x >= width || y >= height)
            return;
        std::copy(c.begin(), c.end(), pixels.begin() + (ptrdiff_t(y) * width + x) * 3);
    }
    void dot(double x, double y, int r, Rgb c)
    {
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx)
                if (dx * dx + dy * dy <= r * r)
                    set(int(std::lround(x)) + dx, int(std::lround(y)) + dy, c);
    }
    void line(double x0, double y0, double x1, double y1, int thickness, Rgb c)
    {
        const int steps = int(std::max(std::abs(x1 - x0), std::abs(y1 - y0))) + 1;
        for (int i = 0; i <= steps; ++i) {
            const double t = double(i) / steps;
            dot(x0 + t * (x1 - x0), y0 + t * (y1 - y0), thickness / 2, c);
        }
    }
    // stb_easy_font quads (4 vertices of 16 bytes: x, y, z floats and a colour), scaled.
    void text(double x, double y, const std::string& s, int scale, Rgb c)
    {
        static char buffer[60000];
        const int quads = stb_easy_font_print(0, 0, const_cast<char*>(s.c_str()), nullptr, buffer, sizeof buffer);
        for (int q = 0; q < quads; ++q) {
            const float* v = reinterpret_cast<const float*>(buffer + q * 64);
            const float x0 = v[0], y0 = v[1], x1 = v[8], y1 = v[9];
            for (int py = int(y0 * scale); py < int(y1 * scale); ++py)
                for (int px = int(x0 * scale); px < int(x1 * scale); ++px)
                    set(int(x) + px, int(y) + py, c);
        }
    }
};

struct Point {
    double portals, seconds;
};

std::string format_value(double v)
{
    char buffer[32];
    if (v >= 1.0)
        std::snprintf(buffer, sizeof buffer, "%g", v);
    else
        std::snprintf(buffer, sizeof buffer, "%.3g", v);
    return buffer;
}

// Least-squares slope of log(seconds) on log(portals).
double growth_exponent(const std::vector<Point>& points)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const Point& p : points) {
        const double lx = std::log(p.portals), ly = std::log(p.seconds);
        sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    }
    const double n = double(points.size()), denominator = n * sxx - sx * sx;
    return points.size() < 2 || denominator == 0.0 ? 0.0 : (n * sxy - sx * sy) / denominator;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 3 && argc != 4) {
        std::fprintf(stderr, "usage: plot_vis_scaling ROWS.csv OUT.png [COLUMN]\n");
        return 2;
    }
    const std::string column = argc == 4 ? argv[3] : "cpu_seconds";
    std::ifstream csv(argv[1]);
    if (!csv) {
        std::fprintf(stderr, "plot_vis_scaling: cannot read %s\n", argv[1]);
        return 1;
    }
    auto split = [](const std::string& line) {
        std::vector<std::string> fields;
        std::stringstream in(line);
        std::string field;
        while (std::getline(in, field, ','))
            fields.push_back(field);
        return fields;
    };
    std::string line;
    std::getline(csv, line);
    const std::vector<std::string> header = split(line);
    auto index_of = [&](const std::string& name) {
        const auto it = std::find(header.begin(), header.end(), name);
        return it == header.end() ? size_t(-1) : size_t(it - header.begin());
    };
    const size_t method_at = index_of("method"), portals_at = index_of("portals"), time_at = index_of(column);
    if (method_at == size_t(-1) || portals_at == size_t(-1) || time_at == size_t(-1)) {
        std::fprintf(stderr, "plot_vis_scaling: %s lacks a method, portals or %s column\n", argv[1], column.c_str());
        return 1;
    }
    std::map<std::string, std::vector<Point>> series;
    while (std::getline(csv, line)) {
        const std::vector<std::string> fields = split(line);
        if (fields.size() > std::max({method_at, portals_at, time_at}))
            series[fields[method_at]].push_back(
                {std::stod(fields[portals_at]), std::max(std::stod(fields[time_at]), 1e-6)});
    }
    if (series.empty()) {
        std::fprintf(stderr, "plot_vis_scaling: no rows in %s\n", argv[1]);
        return 1;
    }

    double x_lo = 1e300, x_hi = 0, y_lo = 1e300, y_hi = 0;
    for (const auto& [method, points] : series)
        for (const Point& p : points) {
            x_lo = std::min(x_lo, p.portals), x_hi = std::max(x_hi, p.portals);
            y_lo = std::min(y_lo, p.seconds), y_hi = std::max(y_hi, p.seconds);
        }
    const double lx0 = std::floor(std::log10(x_lo)), lx1 = std::ceil(std::log10(x_hi));
    const double ly0 = std::floor(std::log10(y_lo)), ly1 = std::ceil(std::log10(y_hi));

    Image img(900, 600);
    const double left = 110, right = 820, top = 80, bottom = 520;
    auto px = [&](double x) { return left + (std::log10(x) - lx0) / std::max(lx1 - lx0, 1.0) * (right - left); };
    auto py = [&](double y) { return bottom - (std::log10(y) - ly0) / std::max(ly1 - ly0, 1.0) * (bottom - top); };
    const Rgb grid{220, 220, 220}, axis{0, 0, 0};
    for (double e = lx0; e <= lx1; ++e) {
        const double v = std::pow(10.0, e);
        img.line(px(v), top, px(v), bottom, 1, grid);
        img.text(px(v) - 30, bottom + 10, format_value(v), 2, axis);
    }
    for (double e = ly0; e <= ly1; ++e) {
        const double v = std::pow(10.0, e);
        img.line(left, py(v), right, py(v), 1, grid);
        img.text(left - 80, py(v) - 7, format_value(v), 2, axis);
    }
    img.line(left, bottom, right, bottom, 2, axis);
    img.line(left, top, left, bottom, 2, axis);
    img.text(left, 18, "Portal vis bake on generated zones, 2 threads, log-log: " + column, 2, axis);
    img.text((left + right) / 2 - 200, bottom + 40, "portals of the zone (before clustering)", 2, axis);
    img.text(10, top - 30, column, 2, axis);

    // fast: blue, full: red; a method named otherwise takes green, then purple.
    const auto colour_of = [](const std::string& method) -> Rgb {
        if (method.find("fast") != std::string::npos)
            return {31, 119, 180};
        if (method.find("full") != std::string::npos)
            return {214, 39, 40};
        return method.size() % 2 ? Rgb{44, 160, 44} : Rgb{148, 103, 189};
    };
    int index = 0;
    for (const auto& [method, points] : series) {
        const Rgb c = colour_of(method);
        const bool dashed = method.rfind("clustered", 0) == 0;
        for (size_t i = 0; i + 1 < points.size(); ++i) {
            const double x0 = px(points[i].portals), y0 = py(points[i].seconds);
            const double x1 = px(points[i + 1].portals), y1 = py(points[i + 1].seconds);
            const int dashes = dashed ? std::max(1, int(std::hypot(x1 - x0, y1 - y0) / 24.0)) : 1;
            for (int d = 0; d < dashes; ++d) {
                const double t0 = double(d) / dashes, t1 = dashed ? (d + 0.6) / dashes : 1.0;
                img.line(x0 + t0 * (x1 - x0), y0 + t0 * (y1 - y0), x0 + t1 * (x1 - x0), y0 + t1 * (y1 - y0), 3, c);
            }
        }
        for (const Point& p : points)
            img.dot(px(p.portals), py(p.seconds), 5, c);
        const double legend_y = top + 20 + 25 * index;
        img.line(left + 20, legend_y, left + 36, legend_y, 3, c);
        img.line(left + (dashed ? 44 : 36), legend_y, left + 60, legend_y, 3, c);
        char exponent[32];
        std::snprintf(exponent, sizeof exponent, " ~ portals^%.2f", growth_exponent(points));
        img.text(left + 70, legend_y - 7, method + exponent, 2, axis);
        ++index;
    }
    if (!stbi_write_png(argv[2], img.width, img.height, 3, img.pixels.data(), img.width * 3)) {
        std::fprintf(stderr, "plot_vis_scaling: cannot write %s\n", argv[2]);
        return 1;
    }
    return 0;
}
