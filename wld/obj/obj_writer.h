// Wavefront OBJ export of a zone: one object per region (its name where the zone has region names,
// as an OBJ zone does, else "region_<id>"; the region's faces, so
// per-object tools such as the HateEngine PVS baker see regions), `usemtl` per material, uvs,
// and a companion .mtl naming each material's texture (written as 24-bit BMP next to the OBJ when the
// material has pixels). A face listed by several regions is written in each of them.
//
// Axes: OBJ files are conventionally y-up; a zone is z-up. Positions are written as
// (x, z, -y), the usual map-editor export, which is also how the HateEngine E1M1 sample was made
// (../shared/formats/quake-doom-hepvs.md §5.5). Winding is kept counter-clockwise from the front.
#pragma once

#include "visibility/zone.h"

#include <string>

namespace pvs {

struct ObjExport {
    std::string obj;                                 // the .obj text
    std::string mtl;                                 // the .mtl text
    std::vector<std::pair<std::string, size_t>> textures; // (bmp file name, material index) to write
};

// `base_name` is the OBJ's file name without extension (used for the mtllib line and texture names).
ObjExport export_obj(const Zone& zone, const std::string& base_name);

// Writes the .obj, the .mtl beside it and the texture BMPs. Throws FileError when a file cannot be written.
void save_obj(const Zone& zone, const std::string& obj_path);

} // namespace pvs
