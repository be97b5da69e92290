// A Wavefront OBJ level as a zone: Debian's tinyobjloader parses the text; each object
// (`o`, or `g` where the file groups that way) becomes one region, a drawable group whose bounds
// are its geometry's box and whose faces are its triangles, one Face per run of one material.
// An OBJ zone has no BSP tree: where the camera is comes from a view grid when a .hepvs is
// attached (wld/hepvs/hepvs_zone.h); without one the culler falls back to the frustum.
//
// Axes: OBJ files are y up, zones z up. File point (x, y, z) becomes zone point (x, -z, y), the
// inverse of obj_writer.h's (x, z, -y) and of the map-editor export that made the HateEngine
// E1M1 sample, so a level converted to OBJ comes back in its own coordinates.
//
// Materials: the .mtl named by `mtllib`, looked for next to the OBJ (its map_Kd textures are read
// when they are BMP files beside it); a `usemtl` name the .mtl does not define (or with no .mtl
// at all, as the E1M1 sample) gets a material of that name without pixels, and triangles with no
// material use a "default" one. UVs follow obj_writer.h (v flipped back).
//
// Bad input: text tinyobjloader refuses, a face naming a vertex or texture coordinate the file
// does not have, or a file with no faces throws FileError naming the file and the problem (the
// offset is that of the object's `o` line when it can be found, else 0).
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <span>
#include <string>

namespace pvs {

// Whether `path` names an OBJ file (by its extension, case-insensitive: OBJ has no magic).
bool is_obj_path(const std::string& path);
Zone read_obj_zone(std::span<const uint8_t> bytes, const std::string& path);

} // namespace pvs
