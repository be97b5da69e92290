// Irrlicht 1.8, opened on first use instead of linked.
//
// Why: Irrlicht brings X11, OpenGL, libpng and libjpeg with it, about 6 MB of a process's memory
// before main, and most pvscope runs (bake, info, stats, convert) render nothing. Everything the
// renderer calls on Irrlicht goes through the device's and driver's virtual functions; the one
// entry point the dynamic linker would resolve is createDeviceEx. So the library is not a link
// dependency: the first device opens it with dlopen (by its soname) and reads that one symbol.
//
// Contract: create_irrlicht_device() returns createDeviceEx(parameters) (null when Irrlicht
// cannot make the device), or throws std::runtime_error naming the library and what the dynamic
// loader said when the library cannot be opened -- the same error on every call. Thread-safe;
// the library stays open for the life of the process.
#pragma once

#include <IrrlichtDevice.h>
#include <SIrrCreationParameters.h>

namespace pvs::ui {

irr::IrrlichtDevice* create_irrlicht_device(const irr::SIrrlichtCreationParameters& parameters);

} // namespace pvs::ui
