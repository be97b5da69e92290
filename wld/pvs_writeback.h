// A PVS written back into the format its zone was read from, into a new file: what `pvscope
// bake -o` writes and what the inspector's "Save PVS" writes, through the same writers:
//   Quake BSP     -> the .bsp (29, BSP2 or 2PSB) with new visdata and, as Quake's vis does, the
//                   leaves' ambient sound levels computed from the new rows (unless
//                   PvsWriteOptions::quake_ambient is off: the file's levels stay); every other
//                   lump byte for byte (quake/bsp29_vis_writer.h, quake/ambient_sounds.h);
//   EverQuest S3D -> the zone written again with the rows as its VISLISTs (convert.h);
//   OBJ + .hepvs  -> a .hepvs of the zone's grid (hepvs/hepvs_zone.h);
//   Doom WAD      -> a copy of the file holding the map's GL nodes with GL_PVS set
//                    (doom/gl_pvs_writer.h);
//   Quake 2 map   -> the .bsp with a visibility lump over its clusters (the leaves' rows ORed
//                    per cluster) and the PHS made from it by PvsWriteOptions::phs (quake2/quake2_vis.h).
// The format is recognised from the zone's own file (zone.source.path, opened again with `load`
// for a Doom map). Throws FileError for a zone that has no file (a generated zone) or a file
// that changed since, std::invalid_argument for a PVS of the wrong size.
#pragma once

#include "visibility/methods/report_field.h"
#include "visibility/pvs.h"
#include "visibility/zone.h"
#include "wld/quake/ambient_sounds.h"
#include "wld/quake2/phs.h"
#include "wld/zone_file.h"

#include <string>
#include <vector>

namespace pvs {

struct PvsWriteOptions {
    bool quake_ambient = true;          // Quake: write ambient sound levels from the new rows
    quake::AmbientOptions ambient;      // which texture classes count (vis's -noambient* switches)
    quake2::PhsRule phs = quake2::PhsRule::Quake2; // Quake 2: which PHS is written (quake2/phs.h)
    // How the summary names the file written, when not out_path: a file written under a
    // temporary name and then renamed over the map (pvscope vis) is named by the map.
    std::string shown_path;
};

struct PvsWriteback {
    std::string summary;            // one line for the user: what was written
    std::vector<std::string> notes; // what the writer had to say (S3D)
    // What was written, for reports (report_field.h). A Quake 2 map: its rows are per cluster, so
    // quake2_written_fields: "clusters", "mean_visible" and "mean_hearable" per cluster row, and
    // "phs_rule".
    std::vector<ReportField> fields;
};

PvsWriteback write_pvs_in_zone_format(const Zone& zone, const ZoneLoadOptions& load, const Pvs& pvs,
                                      const std::string& out_path, const PvsWriteOptions& options = {});

} // namespace pvs
