#include "ui/chart/chart_file.h"

#include "ui/chart/cairo_canvas.h"

#include "ui/chart/cairo_library.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>
#include <stdexcept>

namespace pvs::ui::chart {

namespace {

const CairoLibrary& cairo() { return cairo_library(); }

struct SurfaceDeleter {
    void operator()(cairo_surface_t* surface) const { cairo().surface_destroy(surface); }
};
struct ContextDeleter {
    void operator()(cairo_t* context) const { cairo().destroy(context); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using ContextPtr = std::unique_ptr<cairo_t, ContextDeleter>;

using Draw = std::function<void(Canvas& canvas, glm::vec2 size)>;

// Draws on a white page; the context is finished (every drawing error surfaces in its status)
// on return.
void draw_page(cairo_surface_t* surface, const Draw& draw, uint32_t width, uint32_t height, const std::string& what)
{
    ContextPtr context(cairo().create(surface));
    cairo().set_source_rgb(context.get(), 1, 1, 1);
    cairo().paint(context.get());
    CairoCanvas canvas(context.get());
    draw(canvas, {float(width), float(height)});
    if (const cairo_status_t status = cairo().status(context.get()); status != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(what + ": drawing the chart failed: " + cairo().status_to_string(status));
}

Draw speed_accuracy(std::span<const ChartPoint> points, const std::string& title)
{
    return [points, title](Canvas& canvas, glm::vec2 size) {
        draw_speed_accuracy_chart(points, title, canvas, {0, 0}, size);
    };
}


void check_surface(cairo_surface_t* surface, const std::string& path)
{
    if (const cairo_status_t status = cairo().surface_status(surface); status != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(path + ": cannot write the chart: " + cairo().status_to_string(status));
}

void check_size(uint32_t width, uint32_t height)
{
    constexpr uint32_t kMaxSide = 16384; // cairo's image surfaces stop at 32767; a chart needs far less
    if (width == 0 || height == 0 || width > kMaxSide || height > kMaxSide)
        throw std::invalid_argument("chart size " + std::to_string(width) + "x" + std::to_string(height) +
                                    " is outside 1..16384 pixels a side");
}

Image render_image(const Draw& draw, uint32_t width, uint32_t height)
{
    check_size(width, height);
    SurfacePtr surface(cairo().image_surface_create(CAIRO_FORMAT_RGB24, int(width), int(height)));
    check_surface(surface.get(), "chart image");
    draw_page(surface.get(), draw, width, height, "chart image");
    cairo().surface_flush(surface.get());
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.resize(size_t(width) * height * 4);
    const unsigned char* data = cairo().image_surface_get_data(surface.get());
    const size_t stride = size_t(cairo().image_surface_get_stride(surface.get()));
    for (uint32_t y = 0; y < height; ++y) {
        // RGB24 is one native-endian 32-bit word per pixel, 0xXXRRGGBB.
        const auto* row = reinterpret_cast<const uint32_t*>(data + y * stride);
        uint8_t* out = image.rgba.data() + size_t(y) * width * 4;
        for (uint32_t x = 0; x < width; ++x) {
            out[x * 4 + 0] = uint8_t(row[x] >> 16);
            out[x * 4 + 1] = uint8_t(row[x] >> 8);
            out[x * 4 + 2] = uint8_t(row[x]);
            out[x * 4 + 3] = 255;
        }
    }
    return image;
}

} // namespace

ChartFormat chart_format_for(const std::string& path)
{
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".png")
        return ChartFormat::Png;
    if (extension == ".svg")
        return ChartFormat::Svg;
    if (extension == ".pdf")
        return ChartFormat::Pdf;
    throw std::invalid_argument(path + ": a chart is written as .png, .svg or .pdf (chosen by the extension)");
}

Image render_chart_image(std::span<const ChartPoint> points, const std::string& title, uint32_t width, uint32_t height)
{
    return render_image(speed_accuracy(points, title), width, height);
}

void write_chart_file(std::span<const ChartPoint> points, const std::string& title, uint32_t width, uint32_t height,
                      const std::string& path)
{
    write_canvas_file(width, height, path, speed_accuracy(points, title));
}

void write_canvas_file(uint32_t width, uint32_t height, const std::string& path, const Draw& draw)
{
    const ChartFormat format = chart_format_for(path);
    switch (format) {
    case ChartFormat::Png:
        save_png(render_image(draw, width, height), path);
        return;
    case ChartFormat::Svg:
    case ChartFormat::Pdf: {
        check_size(width, height);
        SurfacePtr surface(format == ChartFormat::Svg ? cairo().svg_surface_create(path.c_str(), width, height)
                                                      : cairo().pdf_surface_create(path.c_str(), width, height));
        check_surface(surface.get(), path);
        draw_page(surface.get(), draw, width, height, path);
        cairo().surface_finish(surface.get()); // writes and closes the file: errors show up here
        check_surface(surface.get(), path);
        return;
    }
    }
}

} // namespace pvs::ui::chart
