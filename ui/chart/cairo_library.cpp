// cairo opened on first use (cairo_library.h).
#include "ui/chart/cairo_library.h"

#include "visibility/shared_library.h"

#include <stdexcept>
#include <string>

#ifndef PVSCOPE_CAIRO_SONAME
#error "PVSCOPE_CAIRO_SONAME (cairo's soname) comes from ui/CMakeLists.txt"
#endif

namespace pvs::ui::chart {
namespace {

struct LoadedCairo {
    CairoLibrary functions;
    std::string error; // empty when every function is set
};

LoadedCairo load()
{
    constexpr const char* kWhat = "cairo (the chart renderer)";
    LoadedCairo loaded;
    void* library = open_shared_library(PVSCOPE_CAIRO_SONAME, kWhat, "libcairo2", loaded.error);
    if (!library)
        return loaded;
#define PVSCOPE_CAIRO_LOAD(name)                                                                                     \
    if (loaded.error.empty())                                                                                        \
        loaded.functions.name = reinterpret_cast<decltype(loaded.functions.name)>(                                 \
            shared_library_symbol(library, PVSCOPE_CAIRO_SONAME, kWhat, "cairo_" #name, loaded.error));
    PVSCOPE_CAIRO_FUNCTIONS(PVSCOPE_CAIRO_LOAD)
#undef PVSCOPE_CAIRO_LOAD
    return loaded;
}

} // namespace

const CairoLibrary& cairo_library()
{
    static const LoadedCairo loaded = load(); // thread-safe initialisation, once
    if (!loaded.error.empty())
        throw std::runtime_error(loaded.error);
    return loaded.functions;
}

} // namespace pvs::ui::chart
