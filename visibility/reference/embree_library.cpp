// Embree 3 opened on first use (embree_library.h).
#include "visibility/reference/embree_library.h"

#include "visibility/shared_library.h"

#include <stdexcept>
#include <string>

#ifndef PVSCOPE_EMBREE_SONAME
#error "PVSCOPE_EMBREE_SONAME (the Embree library's soname) comes from visibility/CMakeLists.txt"
#endif

namespace pvs {
namespace {

constexpr const char* kWhat = "Embree 3";

struct LoadedEmbree {
    EmbreeApi api;
    std::string error; // empty when api is complete
};

LoadedEmbree load()
{
    LoadedEmbree loaded;
    void* library = open_shared_library(PVSCOPE_EMBREE_SONAME, kWhat, "libembree3-3", loaded.error);
    if (!library)
        return loaded;
#define PVSCOPE_EMBREE_RESOLVE(name)                                                                       \
    loaded.api.name = reinterpret_cast<decltype(loaded.api.name)>(                                         \
        shared_library_symbol(library, PVSCOPE_EMBREE_SONAME, kWhat, #name, loaded.error));                \
    if (!loaded.api.name)                                                                                  \
        return loaded;
    PVSCOPE_EMBREE_FUNCTIONS(PVSCOPE_EMBREE_RESOLVE)
#undef PVSCOPE_EMBREE_RESOLVE
    return loaded;
}

} // namespace

const EmbreeApi& embree_api()
{
    static const LoadedEmbree loaded = load(); // thread-safe initialisation, once
    if (!loaded.error.empty())
        throw std::runtime_error(loaded.error);
    return loaded.api;
}

} // namespace pvs
