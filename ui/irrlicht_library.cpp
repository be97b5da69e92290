// Irrlicht opened on first use (irrlicht_library.h).
#include "ui/irrlicht_library.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

#ifndef PVSCOPE_IRRLICHT_SONAME
#error "PVSCOPE_IRRLICHT_SONAME (the Irrlicht library's soname) comes from ui/CMakeLists.txt"
#endif

namespace pvs::ui {
namespace {

// createDeviceEx as irrlicht.h declares it (extern "C", so dlsym finds it by this name).
using CreateDeviceEx = irr::IrrlichtDevice*(IRRCALLCONV*)(const irr::SIrrlichtCreationParameters&);

struct LoadedIrrlicht {
    CreateDeviceEx create = nullptr;
    std::string error; // empty when create is set
};

LoadedIrrlicht load()
{
    LoadedIrrlicht loaded;
    void* library = dlopen(PVSCOPE_IRRLICHT_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        const char* why = dlerror();
        loaded.error = std::string("cannot open Irrlicht (" PVSCOPE_IRRLICHT_SONAME "; Debian package libirrlicht1.8): ") +
                       (why ? why : "unknown error");
        return loaded;
    }
    loaded.create = reinterpret_cast<CreateDeviceEx>(dlsym(library, "createDeviceEx"));
    if (!loaded.create)
        loaded.error = "Irrlicht (" PVSCOPE_IRRLICHT_SONAME ") has no createDeviceEx";
    return loaded;
}

} // namespace

irr::IrrlichtDevice* create_irrlicht_device(const irr::SIrrlichtCreationParameters& parameters)
{
    static const LoadedIrrlicht loaded = load(); // thread-safe initialisation, once
    if (!loaded.create)
        throw std::runtime_error(loaded.error);
    return loaded.create(parameters);
}

} // namespace pvs::ui
