// The zone model: the one in-memory form every file format loads into and every later stage
// (lookup, culling, baking, rendering, inspection) reads.
//
// Conventions (see docs/architecture.md):
//  - z is up, units are the file's own.
//  - A region is a BSP leaf that can hold the camera (Quake empty/water/slime/lava/sky leaf,
//    EverQuest 0x22 region, ...). Region ids are 0-based and dense. Solid and outside leaves
//    are not regions. Each loader owns the mapping from its file's numbering to region ids
//    and records it in its header comment.
//  - A face is a convex polygon of the source file, triangulated into a contiguous range of
//    triangles. A face may be listed by several regions (Quake marksurfaces); a renderer draws
//    it once per frame if any of those regions is visible.
//  - Nothing here knows which file a zone came from, except the free-form ZoneSource notes.
#pragma once

#include "visibility/material_pixels.h"
#include "visibility/math/aabb.h"
#include "visibility/pvs.h"
#include "visibility/view_grid.h"

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace pvs {

// Region flags. A region may carry several (an EverQuest zone line under water).
enum RegionFlag : uint32_t {
    kRegionWater = 1u << 0,
    kRegionLava = 1u << 1,
    kRegionSlime = 1u << 2,
    kRegionIce = 1u << 3,
    kRegionVWater = 1u << 4, // EverQuest "vwater": water you see but do not swim in
    kRegionPvp = 1u << 5,
    kRegionZoneLine = 1u << 6,
    kRegionSky = 1u << 7,
};
inline constexpr uint32_t kRegionFlagCount = 8;
// Short lower-case name of one flag bit ("water", "zone_line", ...); "?" for an unknown bit.
const char* region_flag_name(uint32_t flag);

// Where a zone line leads (Quake trigger_changelevel, EverQuest zone-line region).
struct ZoneLine {
    std::string target; // map or zone name; empty when the file does not say
    Aabb bounds;        // the trigger volume, when known
};

// Region::vis_contents for formats whose vis does not follow the flags' rule (media.h).
inline constexpr uint16_t kNoVisContents = 0xFFFF;

struct Region {
    Aabb bounds;            // bounds of the region's volume (or of its geometry where the volume is unknown)
    uint32_t flags = 0;     // RegionFlag bits
    int32_t zone_line = -1; // index into Zone::zone_lines, or -1
    // Quake 2: the leaf's contents as its vis compares them (media.h, quake2_sight): the low
    // byte its visible contents, the high byte the same with translucent and detail contents
    // cleared. kNoVisContents for every other format.
    uint16_t vis_contents = kNoVisContents;
};

// How a point exactly on a split plane (signed distance == 0) is classified. Formats differ,
// and each loader sets its own engine's rule:
//  - Quake engines (Mod_PointInLeaf) send d == 0 to the back child: OnPlaneGoesBack.
//  - EverQuest readers send s >= 0 to the front child: OnPlaneGoesFront.
enum class TieRule : uint8_t { OnPlaneGoesBack, OnPlaneGoesFront };

// Leaf markers in BspTree::leaf_region for leaves that are not regions.
inline constexpr int32_t kLeafSolid = -1;   // inside a wall (Quake leaf 0, solid contents)
inline constexpr int32_t kLeafOutside = -2; // outside the world (EverQuest region-less leaf)

// A node child c >= 0 is a node index; c < 0 is the leaf ~c (so -1 is leaf 0).
struct BspNode {
    glm::vec3 normal; // split plane: dot(normal, p) - dist; positive = front = children[0]
    float dist;
    int32_t children[2];
};
static_assert(sizeof(BspNode) == 24, "BspNode is hot data for the point walk: keep it 24 bytes");

struct BspTree {
    std::vector<BspNode> nodes;
    std::vector<int32_t> leaf_region; // region id, or kLeafSolid / kLeafOutside
    int32_t root = -1;                // encoded like a child: a node index, or ~leaf for a one-leaf tree
    TieRule tie_rule = TieRule::OnPlaneGoesBack;
    // Trees extruded from a 2-D map (Doom): nodes[first_height_node..] are the regions' floors
    // and ceilings (horizontal planes with a solid child), placed after every other node.
    // Methods that ignore heights (2-D portal vis, as glVIS) walk past them:
    // without_height_nodes (bsp_tree_edit.h). nodes.size() when there are none.
    uint32_t first_height_node = UINT32_MAX;

    bool has_height_nodes() const { return first_height_node < nodes.size(); }
    static constexpr bool is_leaf(int32_t child) { return child < 0; }
    // False for zones without a tree (OBJ levels: no node and no leaf).
    bool exists() const { return !leaf_region.empty(); }
    static constexpr int32_t leaf_index(int32_t child) { return ~child; }
};

// The first node a walk down from the root reaches a second time (a cycle, or a subtree two
// parents share), or -1 when each is reached at most once. Loaders refuse such trees, so every
// walk of a loaded tree ends. Children must be in range (loaders check them first).
int32_t node_reached_twice(const BspTree& tree);

// Material flags.
enum MaterialFlag : uint32_t {
    kMaterialSky = 1u << 0,
    kMaterialLiquid = 1u << 1,    // warping water/slime/lava/teleport surface
    kMaterialInvisible = 1u << 2, // not drawn (EverQuest transparent / trigger surfaces)
    kMaterialTranslucent = 1u << 3, // drawn, but hides nothing behind it (Quake 2 glass: SURF_TRANS33/66)
    kMaterialFaint = 1u << 4,       // with kMaterialTranslucent: a third opaque (SURF_TRANS33), else two thirds
};

struct Material {
    std::string name;
    uint32_t width = 0, height = 0;
    MaterialPixels pixels; // width*height texels (palettized when they fit), or none when the file carries none
    uint32_t flags = 0;    // MaterialFlag bits

    bool has_pixels() const { return !pixels.empty(); }
};

// Sets the material's size and pixels from width*height*4 RGBA bytes (rows top to bottom);
// empty rgba with any size clears the pixels. Throws std::invalid_argument when the byte count
// does not match the size.
void set_material_rgba(Material& material, uint32_t width, uint32_t height, std::span<const uint8_t> rgba);
// The material's pixels as width*height*4 RGBA bytes; empty when it has none.
std::vector<uint8_t> material_rgba(const Material& material);

struct Face {
    uint32_t first_triangle = 0; // into Mesh::indices / 3
    uint32_t triangle_count = 0;
    uint32_t material = 0;       // index into Zone::materials
};

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec2> uvs;     // one per position, in texture repeats (1.0 = one texture width)
    std::vector<uint32_t> indices;  // three per triangle, counter-clockwise seen from the front
    std::vector<Face> faces;

    size_t triangle_count() const { return indices.size() / 3; }
};

// A portal between two regions: a convex planar polygon.
struct Portal {
    int32_t regions[2] = {-1, -1};
    uint32_t first_point = 0; // into PortalSet::points
    uint32_t point_count = 0;
};
struct PortalSet {
    std::vector<Portal> portals;
    std::vector<glm::vec3> points;
};

// Free-form notes from the loader, for `pvscope info` and the inspector's zone panel.
struct ZoneSource {
    std::string path;
    std::string format;  // "Quake BSP", "EverQuest S3D/WLD", ...
    std::string version; // "29", ...
    // Format-specific counts a user wants to see, in display order ("leaves.empty" = 1407).
    std::vector<std::pair<std::string, uint64_t>> counts;
    std::vector<std::string> notes;
};

// Quake 2: a func_areaportal, the door-closable link between two areas. Vis sees through it; the
// engine draws nothing of an area that no open areaportal links to the camera's (area_flood.h).
struct AreaPortal {
    Aabb bounds;                // the areaportal brush
    int32_t areas[2] = {-1, -1};
    uint32_t number = 0;        // the portal number (the entity's "style")
};

struct Zone {
    ZoneSource source;
    std::vector<Region> regions;
    BspTree tree;
    Mesh mesh;
    std::vector<Material> materials;
    // Faces listed by each region, as compressed rows: region r lists
    // region_faces[region_face_offsets[r] .. region_face_offsets[r+1]).
    std::vector<uint32_t> region_face_offsets; // regions.size() + 1 entries
    std::vector<uint32_t> region_faces;
    std::vector<ZoneLine> zone_lines;
    // Names of the regions where the format has them (an OBJ's objects, which a .hepvs names);
    // empty otherwise.
    std::vector<std::string> region_names;
    std::optional<Pvs> baked_pvs;        // the PVS stored in the file, if any
    std::optional<PortalSet> portals;    // portals read from a file or built from the tree, if any
    // Grid zones only (OBJ + .hepvs, view_grid.h): the camera's cell comes from this grid, and
    // baked_pvs has one row per cell over the regions (the OBJ's objects). Absent for BSP zones.
    std::optional<ViewGrid> view_grid;
    // Quake 2 only (empty elsewhere): each region's area, and the areaportals between areas.
    std::vector<int32_t> region_areas;
    std::vector<AreaPortal> area_portals;

    size_t region_count() const { return regions.size(); }
    std::span<const uint32_t> faces_of_region(uint32_t region) const
    {
        return std::span<const uint32_t>(region_faces)
            .subspan(region_face_offsets[region], region_face_offsets[region + 1] - region_face_offsets[region]);
    }
    Aabb bounds() const;
    // Bytes of heap memory held by the model (vectors' capacity, strings, PVS storage).
    size_t memory_bytes() const;
    // Releases the spare capacity loaders leave behind while growing their vectors.
    void shrink_to_fit();
};

// Per mesh face, 1 where the face's material is kMaterialTranslucent (drawn, but hiding nothing
// behind it: Quake 2's SURF_TRANS33/66 glass and water); empty when no face is, so a zone
// without glass pays nothing. Sight methods that draw pictures (the raster baker) let such a face
// through and still count it as seen. A face naming no material is opaque.
std::vector<uint8_t> translucent_face_mask(const Zone& zone);

} // namespace pvs
