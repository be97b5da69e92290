// Shared libraries opened at run time (shared_library.h).
#include "visibility/shared_library.h"

#include <dlfcn.h>

namespace pvs {

void* open_shared_library(const char* soname, const char* what, const char* package, std::string& error)
{
    void* library = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        const char* why = dlerror();
        error = std::string("cannot open ") + what + " (" + soname + "; Debian package " + package +
                "): " + (why ? why : "unknown error");
    }
    return library;
}

void* shared_library_symbol(void* library, const char* soname, const char* what, const char* name, std::string& error)
{
    void* symbol = dlsym(library, name);
    if (!symbol)
        error = std::string(what) + " (" + soname + ") has no " + name;
    return symbol;
}

} // namespace pvs
