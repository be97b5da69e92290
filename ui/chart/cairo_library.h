// cairo, opened on first use instead of linked (as Irrlicht and Embree: visibility/shared_library.h).
//
// Why: cairo brings X11, xcb, fontconfig, freetype, pixman and libpng with it, 18 libraries and
// about 1.8 MB of every pvscope process before main, and only a chart (`compare --chart`, the
// inspector's chart export) draws with it. So it is not a link dependency: the first chart opens
// it with dlopen (by its soname) and reads the functions the chart calls.
//
// Contract: cairo_library() returns those functions, each the library's own; it throws
// std::runtime_error naming the library, its Debian package and what the dynamic loader said
// when the library or a function cannot be found (the same error on every call). Thread-safe;
// the library stays open for the life of the process.
#pragma once

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

namespace pvs::ui::chart {

// The cairo functions the chart calls: X(name) for cairo_name.
#define PVSCOPE_CAIRO_FUNCTIONS(X)                                                                                   \
    X(arc) X(create) X(destroy) X(fill) X(fill_preserve) X(font_extents) X(image_surface_create)                   \
    X(image_surface_get_data) X(image_surface_get_stride) X(line_to) X(move_to) X(new_path) X(new_sub_path)       \
    X(paint) X(pdf_surface_create) X(rectangle) X(select_font_face) X(set_font_size) X(set_line_width)            \
    X(set_source_rgb) X(set_source_rgba) X(show_text) X(status) X(status_to_string) X(stroke)                     \
    X(surface_destroy) X(surface_finish) X(surface_flush) X(surface_status) X(svg_surface_create) X(text_extents)

struct CairoLibrary {
#define PVSCOPE_CAIRO_POINTER(name) decltype(&::cairo_##name) name = nullptr;
    PVSCOPE_CAIRO_FUNCTIONS(PVSCOPE_CAIRO_POINTER)
#undef PVSCOPE_CAIRO_POINTER
};

const CairoLibrary& cairo_library();

} // namespace pvs::ui::chart
