// Re-cut a zone's mesh so that every face belongs to exactly one region and lies inside that
// region's BSP cell, as EverQuest zones store their geometry (one mesh per region holding exactly
// the polygons inside its volume).
//
// In a Quake BSP a face is stored once, at the node of its plane, and every leaf below that node
// that touches it lists it (marksurfaces): a face may span several leaves. Here each listed
// (region, face) pair becomes the part of the face inside the region's cell: each triangle of the
// face is clipped to the cell's bounding planes (with `epsilon`, so a face lying on a cell
// boundary stays whole) and the piece is kept as a new face of the same material, with uvs
// interpolated. On Quake maps the pieces of a face over its listing leaves add up to the face
// (tests/wld/test_bsp_volume.cpp), so the area per texture is preserved.
#pragma once

#include "visibility/geometry/winding.h"
#include "visibility/zone.h"

namespace pvs {

// The tree, regions, flags, PVS, materials, zone lines and portals are copied; the mesh and the
// region face lists are rebuilt. A region whose leaf the root does not reach keeps no face.
Zone clip_faces_to_region_cells(const Zone& zone, float epsilon = kWindingOnEpsilon);

} // namespace pvs
