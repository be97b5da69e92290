// Quake 2 maps (IBSP 38) -> zone model. The lumps are those of ibsp38_file.h; record layouts
// as Quake 2's qfiles.h (planes 20 bytes, nodes 28, texinfo 76, faces 20, leaves 28, models 48).
//
// Mapping to the zone model:
//  - Regions are leaves, not clusters: region r is the r-th leaf, in file order, that the world
//    model's tree reaches, that has a cluster (cluster >= 0: the leaves vis works on) and whose
//    contents are not solid (ericw's qbsp gives detail solid leaves their cluster's number; they
//    still hide what is behind them). Leaves are convex, so every method (portals from the tree,
//    the reference, raster sampling) works on them as on any BSP leaf; a cluster is a set of
//    leaves, and the file's rows are over clusters: region r's row holds every region whose
//    cluster the row of r's cluster holds. Other leaves are kLeafSolid when their contents are
//    solid, kLeafOutside otherwise.
//  - Point lookup follows Quake 2's CM_PointLeafnum: a point on a plane goes to the front child
//    (TieRule::OnPlaneGoesFront, unlike Quake's back).
//  - Contents water / slime / lava become region flags, and every region carries its cluster's
//    contents (all its leaves' ORed, as qbsp compares clusters) for Quake 2's sight rule
//    (Region::vis_contents, visibility/portal/media.h): portals built from the tree and the
//    reference's lines cross between leaves as Quake 2's vis does between their clusters. Plain
//    water, lava and slime surfaces block sight; translucent ones (and glass: window +
//    translucent) do not.
//  - The mesh holds the world model's faces, fans counter-clockwise from the front; uv in
//    repeats of a 64-unit texture (the .wal files with the sizes are not in the map). Materials
//    are one per (texture name, surface kind): a flat colour made from the name (no pixels ship
//    in the map), kMaterialSky for SURF_SKY, kMaterialLiquid for SURF_WARP, kMaterialInvisible
//    for SURF_NODRAW, kMaterialTranslucent for SURF_TRANS33 / SURF_TRANS66 (+ kMaterialFaint for TRANS33) (glass and water
//    surfaces: drawn, but they hide nothing behind them).
//  - Region face lists come from the leaf-face lump; faces of brush models are dropped.
//  - trigger_changelevel entities become zone lines (wld/quake/changelevel_lines.h).
//  - The visibility lump becomes the baked PVS (expanded to leaves as above); an unvised map
//    (empty lump) has none. The PHS is not part of the zone (`pvscope vis` writes it).
//  - source.counts: leaves, clusters, areas and areaportals (Quake 2's door-closable links
//    between areas; vis sees through them), faces, texinfo.
// Every count, index and offset is checked; bad input throws FileError naming file and offset.
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <span>
#include <string>

namespace pvs::quake2 {

Zone load_ibsp38(std::span<const uint8_t> bytes, const std::string& file);

} // namespace pvs::quake2
