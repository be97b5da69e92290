// One Doom map read from a WAD and its GL nodes (../shared/formats/quake-doom-hepvs.md §4.2-§4.5):
// the classic lumps (VERTEXES, LINEDEFS in Doom or Hexen layout, SIDEDEFS, SECTORS, REJECT) and
// glBSP's GL lumps (GL_VERT, GL_SEGS, GL_SSECT, GL_NODES, GL_PVS) in versions V2, V3 and V5 (V1
// is read too: no magic, 4-byte vertices), from the WAD itself or from the .gwa beside it.
//
// Finding things. A map is a marker lump (ExMy, MAPxx, or any name) followed by THINGS and
// LINEDEFS. Its GL group is the lump GL_<name> (names of at most 5 characters) or a GL_LEVEL lump
// whose text holds LEVEL=<name>, followed by GL_VERT, GL_SEGS, GL_SSECT, GL_NODES and, when
// present, GL_PVS at marker + 5. The .gwa is preferred when it has the map (as glVIS and the
// engines do), else the WAD. A missing GL group is an error that says how to make one (glbsp).
//
// Contract. Every index is checked here, once: seg vertices (with the version's GL-vertex flag)
// against VERTEXES / GL_VERT, seg linedefs, sides and partners, subsector seg ranges, node
// children, linedef vertices and sidedefs, sidedef sectors. Violations throw FileError naming the
// file, the lump and the byte offset of the bad record. A subsector whose segs are all minisegs
// has no sector (glVIS and Vavoom refuse it): an error too. Afterwards every index in DoomMap
// is in range, so the zone builder reads it without checks.
#pragma once

#include "wld/doom/wad_file.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pvs::doom {

struct MapVertex {
    double x = 0, y = 0; // map units (GL vertices are 16.16 fixed point in the file)
};

struct Linedef {
    uint32_t v1 = 0, v2 = 0;
    uint16_t flags = 0;
    uint16_t special = 0; // Doom: the special; Hexen: the u8 special
    int16_t tag = 0;
    int32_t side[2] = {-1, -1}; // sidedef index, -1 = none
};

struct Sidedef {
    int16_t x_offset = 0, y_offset = 0;
    std::string upper, lower, middle; // texture names, upper case, "-" = none
    uint32_t sector = 0;
};

struct Sector {
    int16_t floor_height = 0, ceiling_height = 0;
    std::string floor_flat, ceiling_flat;
    int16_t light = 0, special = 0, tag = 0;
};

inline constexpr uint32_t kNoLinedef = 0xFFFFFFFFu;
inline constexpr uint32_t kNoPartner = 0xFFFFFFFFu;

struct GlSeg {
    uint32_t v1 = 0, v2 = 0;    // into DoomMap::vertices (GL vertices follow the map's)
    uint32_t linedef = kNoLinedef; // kNoLinedef for a miniseg
    uint8_t side = 0;           // 0 = front (right) side of the linedef, 1 = back
    uint32_t partner = kNoPartner;
};

struct GlSubsector {
    uint32_t first_seg = 0, seg_count = 0;
    uint32_t sector = 0; // from its first seg with a linedef
};

struct GlNode {
    double x = 0, y = 0, dx = 0, dy = 0;
    // child >= 0: a node; child < 0: subsector ~child.
    int32_t children[2] = {0, 0}; // [0] right (front), [1] left (back)
};

// Where the map and its GL data were found, for writing GL_PVS and REJECT back.
struct MapSource {
    std::string wad_path;       // the WAD holding the map lumps
    size_t map_marker = 0;      // lump index of the map marker in the WAD
    std::string gl_path;        // the file holding the GL group (the WAD or the .gwa)
    size_t gl_marker = 0;       // lump index of GL_<name> / GL_LEVEL in that file
    bool gl_pvs_present = false; // a lump named GL_PVS at gl_marker + 5
};

struct DoomMap {
    std::string name; // upper case: E1M1, MAP10, ...
    bool hexen = false;
    int gl_version = 2; // 1, 2, 3 or 5
    std::string gl_builder; // BUILDER= of the GL marker when present (glBSP, ZDBSP, ...)
    std::vector<MapVertex> vertices; // VERTEXES, then GL_VERT
    uint32_t map_vertex_count = 0;   // how many of `vertices` are VERTEXES
    std::vector<Linedef> linedefs;
    std::vector<Sidedef> sidedefs;
    std::vector<Sector> sectors;
    std::vector<GlSeg> segs;
    std::vector<GlSubsector> subsectors;
    std::vector<GlNode> nodes; // the root is the last node; none = one subsector
    std::vector<uint8_t> reject;
    std::vector<uint8_t> gl_pvs; // GL_PVS as stored (may be empty: everything visible)
    MapSource source;
};

// Names of the maps in a WAD (markers followed by THINGS and LINEDEFS), in directory order.
std::vector<std::string> map_names(const WadFile& wad);

// The .gwa beside a WAD path (same stem, extension .gwa), whether or not it exists.
std::string gwa_path_for(const std::string& wad_path);

// Reads map `name` (case-insensitive; empty = the first map) from `wad`, with the GL group from
// `gwa` when it has one for the map, else from `wad`. Throws FileError.
DoomMap read_doom_map(const WadFile& wad, const WadFile* gwa, const std::string& name);

// A map opened from a path as the engines find it: `path` a .wad (its GL nodes from `gwa_path`
// when given, else from the .gwa beside it when there is one, else its own) or a .gwa (its map
// lumps from the .wad beside it). The one place that resolves the files (load, bake, write-back).
struct OpenedMap {
    WadFile wad;
    std::optional<WadFile> gwa;
    DoomMap map;
};
OpenedMap open_doom_map(const std::string& path, const std::string& name, const std::string& gwa_path = {});

// The subsector holding point (x, y), by the GL nodes (§4.4: c = (px - x)*dy - (py - y)*dx,
// right child when c > 0, points on the line go left).
uint32_t locate_subsector(const DoomMap& map, double x, double y);

} // namespace pvs::doom
