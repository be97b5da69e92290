// What `bake` reads: the zone in one of the formats it writes back (Quake BSP 29 / BSP2 / 2PSB,
// Quake 2 IBSP 38, EverQuest S3D, a Doom map with its GL nodes, an OBJ level with its .hepvs),
// what it is called and where a Doom map's lumps are, and a portal file read for that zone.
// Throws FileError naming the file for what cannot be read.
#pragma once

#include "app/bake_options.h"
#include "visibility/methods/portal_input.h"
#include "visibility/zone.h"
#include "wld/doom/doom_map.h"
#include "wld/zone_file.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace pvs::app {

struct BakeInput {
    ZoneFormat format; // as load_zone tells it (zone_file.h)
    Zone zone;
    // Doom: where the map and its GL group are, and each subsector's sector (for REJECT).
    doom::MapSource doom_source;
    std::vector<uint32_t> sector_of_subsector;
    uint32_t sector_count = 0;

    bool drawing_dropped = false; // mesh and pixels freed for the bake (drop_drawing)

    BakeInput(ZoneFormat f, Zone z) : format(f), zone(std::move(z)) {}
};

// Reads options.input (a Doom map: options.map, options.gwa; an OBJ level: its grid options).
// A Doom map with --heights whose sectors move gets a warning on `err`.
BakeInput load_bake_input(const BakeOptions& options, std::FILE* err);

// "Quake BSP 29", "Quake BSP2", "Quake 2 BSP (IBSP 38)", "EverQuest S3D", ... as `info` says.
std::string format_name(const BakeInput& in);
// The output's extension: the input's format, and for a Doom map the file holding its GL nodes.
std::string format_extension(const BakeInput& in);
std::string lowercase_extension(const std::string& path);

// The argument errors that need the input's format (the output's extension, options for another
// format); empty when there are none.
std::string check_output_against_input(const BakeOptions& options, const BakeInput& in);

// Frees the mesh and textures of a Quake map or an EverQuest zone, for a method that reads
// neither (VisMethod::reads_drawing); the writer reads what it needs again.
void drop_drawing(BakeInput& in);

// --prt: the portals of a PRT1 / PRT2 / PRT1-AM file for this zone (leaf k = region k; a file
// with clusters, or a Quake 2 map's qbsp PRT1 naming its clusters: baked over the clusters).
// Throws FileError when the file names another count of leaves.
PortalInput portal_input_from_file(const std::string& prt_path, const BakeInput& in);

} // namespace pvs::app
