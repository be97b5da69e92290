// Opening a zone file of any supported format: the format is recognised from the bytes, not
// from the file name. Sidecar files are picked up when present (a Quake map's .prt portal file
// next to the .bsp). Throws FileError for unreadable, unknown or bad files.
#pragma once

#include "visibility/zone.h"

#include <string>

namespace pvs {

Zone load_zone(const std::string& path);

} // namespace pvs
