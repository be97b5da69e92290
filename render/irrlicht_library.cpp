// Irrlicht opened on first use (irrlicht_library.h).
#include "render/irrlicht_library.h"

#include "visibility/shared_library.h"

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
    constexpr const char* kWhat = "Irrlicht";
    LoadedIrrlicht loaded;
    if (void* library = open_shared_library(PVSCOPE_IRRLICHT_SONAME, kWhat, "libirrlicht1.8", loaded.error))
        loaded.create = reinterpret_cast<CreateDeviceEx>(
            shared_library_symbol(library, PVSCOPE_IRRLICHT_SONAME, kWhat, "createDeviceEx", loaded.error));
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
