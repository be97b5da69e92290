// A Doom map as a zone (docs/architecture.md "Doom zones"; ../shared/formats/quake-doom-hepvs.md §4).
//
// Regions are the GL subsectors, region r = subsector r (so GL_PVS rows are region rows).
// The tree is the GL BSP with its partition lines as vertical planes (normal (dy, -dx, 0)
// normalised: the right side is the front, points on a line go left/back, as §4.4), and
// below each subsector:
//   - one node per wall seg (a seg with a linedef and no partner: a one-sided wall), its
//     right side (the subsector) in front, the back solid: so the tree's solid space is the
//     void behind the walls, as in a Quake map, and the reference and the popping check trace
//     through it. Its plane is the linedef's line (not the seg's, whose end may be a rounded GL
//     vertex), computed like every node's by vertical_line_plane (line_plane.h), so a wall on a
//     partition line is that partition's plane bit for bit and leaves no sliver of solid;
//   - then the sector's floor (front: above) and ceiling (front: below), each with a solid
//     back. These height nodes come after every other node (BspTree::first_height_node):
//     methods that follow glVIS and ignore heights walk past them (bsp_tree_edit.h), the
//     height-aware option keeps them. Heights are the map as built (doors closed, lifts up).
// The mesh: per subsector a floor and a ceiling polygon; per wall seg a wall from floor to
// ceiling; per two-sided seg the lower part (own floor up to the neighbour's floor) and the
// upper part (the neighbour's ceiling up to own ceiling; a sky wall when both ceilings are sky,
// which the engines fill with sky). Walls are made whatever their texture: a missing one ("-")
// still blocks sight (material "-", no pixels). Masked middle textures of two-sided lines are
// left out (sight goes through them). Faces face into their subsector and are listed by it. Materials are the
// flats and wall textures by name, with pixels when the WAD has them (doom_textures.h);
// F_SKY1 ceilings are sky materials.
// Flags: damaging floors by sector special — 7 (5%/nukage) slime; 5, 16, 4, 11 (10-20%) lava;
// Boom generalized damage bits (0x60) likewise (5 -> slime, 10 and 20 -> lava). Exit lines
// (specials 11, 51, 52, 124, 197, 198) make the subsectors along them zone lines whose target
// is the map the engines go to next (ExM(y+1), MAP(nn+1), the secret maps of §doom).
// The baked PVS is GL_PVS when the lump is present and not empty; an empty lump (glBSP's
// placeholder) means "everything visible", noted, and no PVS is attached.
#pragma once

#include "visibility/zone.h"
#include "wld/doom/doom_map.h"

namespace pvs::doom {

class DoomTextures;

// Builds the zone of `map`. `textures` may be null (materials without pixels). Throws
// FileError for a GL_PVS lump of the wrong size.
Zone build_doom_zone(const DoomMap& map, const DoomTextures* textures);

// Reads map `map_name` (empty = the first) of the WAD or .gwa at `path` and builds its zone:
// a .wad uses `gwa_path` (or, when that is empty, the .gwa beside it) when that has the map;
// a .gwa uses the .wad beside it.
Zone load_doom_zone(const std::string& path, const std::string& map_name, const std::string& gwa_path = {});

// The map the engines load after `name` by its normal or secret exit (E1M1 -> E1M2, MAP15
// secret -> MAP31); empty when unknown.
std::string next_map_name(const std::string& name, bool secret);

} // namespace pvs::doom
