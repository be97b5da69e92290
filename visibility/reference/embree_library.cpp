// Embree 3 opened on first use (embree_library.h).
#include "visibility/reference/embree_library.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>
#include <string>

#ifndef PVSCOPE_EMBREE_SONAME
#error "PVSCOPE_EMBREE_SONAME (the Embree library's soname) comes from visibility/CMakeLists.txt"
#endif

namespace pvs {
namespace {

struct LoadedEmbree {
    EmbreeApi api;
    std::string error; // empty when api is complete
};

template <class Pointer>
bool resolve(void* library, const char* name, Pointer& out, std::string& error)
{
    out = reinterpret_cast<Pointer>(dlsym(library, name));
    if (!out)
        error = std::string("Embree (" PVSCOPE_EMBREE_SONAME ") has no ") + name;
    return out != nullptr;
}

LoadedEmbree load()
{
    LoadedEmbree loaded;
    // RTLD_LOCAL: Embree's symbols (and TBB's, which it brings) stay out of the global namespace.
    void* library = dlopen(PVSCOPE_EMBREE_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        const char* why = dlerror();
        loaded.error = std::string("cannot open Embree 3 (" PVSCOPE_EMBREE_SONAME "; Debian package libembree3-3): ") +
                       (why ? why : "unknown error");
        return loaded;
    }
#define PVSCOPE_EMBREE_RESOLVE(name) \
    if (!resolve(library, #name, loaded.api.name, loaded.error)) \
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
