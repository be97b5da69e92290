// A PVS written back into the format its zone was read from, into a new file: what `pvscope
// bake -o` writes and what the inspector's "Save PVS" writes, through the same writers:
//   Quake BSP 29 -> the .bsp with new visdata, every other lump byte for byte
//                   (quake/bsp29_vis_writer.h);
//   EverQuest S3D -> the zone written again with the rows as its VISLISTs (convert.h);
//   OBJ + .hepvs  -> a .hepvs of the zone's grid (hepvs/hepvs_zone.h);
//   Doom WAD      -> a copy of the file holding the map's GL nodes with GL_PVS set
//                    (doom/gl_pvs_writer.h).
// The format is recognised from the zone's own file (zone.source.path, opened again with `load`
// for a Doom map). Throws FileError for a zone that has no file (a generated zone) or a file
// that changed since, std::invalid_argument for a PVS of the wrong size.
#pragma once

#include "visibility/pvs.h"
#include "visibility/zone.h"
#include "wld/zone_file.h"

#include <string>
#include <vector>

namespace pvs {

struct PvsWriteback {
    std::string summary;            // one line for the user: what was written
    std::vector<std::string> notes; // what the writer had to say (S3D)
};

PvsWriteback write_pvs_in_zone_format(const Zone& zone, const ZoneLoadOptions& load, const Pvs& pvs,
                                      const std::string& out_path);

} // namespace pvs
