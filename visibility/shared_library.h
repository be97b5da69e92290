// A shared library opened at run time (dlopen) instead of linked: for the heavy dependencies
// most runs never call (Embree: reference/embree_library.h; Irrlicht: ui/irrlicht_library.h),
// so that a process maps them only when it uses them.
//
// Contract: open_shared_library(soname, what, package) returns the handle of the library opened
// with RTLD_NOW | RTLD_LOCAL (its symbols, and those of the libraries it brings, stay out of the
// global namespace), or null with `error` set to a sentence naming `what`, the soname, the
// Debian package that holds it and what the dynamic loader said. The library stays open for the
// life of the process. shared_library_symbol() returns the symbol's address, or null with
// `error` set.
#pragma once

#include <string>

namespace pvs {

void* open_shared_library(const char* soname, const char* what, const char* package, std::string& error);
void* shared_library_symbol(void* library, const char* soname, const char* what, const char* name, std::string& error);

} // namespace pvs
