// Where the fields of a Quake BSP's records lie, for each variant that shares BSP 29's lump table
// (../shared/formats/quake-doom-hepvs.md §1.12): version 29, BSP2 (tag "BSP2") and 2PSB (tag
// "2PSB", the older BSP2 of RMQ). The variants differ only in the widths of some records:
//
// | record      | BSP 29 | BSP2 | 2PSB | what widens                                       |
// |-------------|-------:|-----:|-----:|---------------------------------------------------|
// | node        | 24     | 44   | 32   | children i32; BSP2 also float bounds              |
// | leaf        | 28     | 44   | 32   | marksurface range u32; BSP2 also float bounds     |
// | face        | 20     | 28   | 28   | planenum, side, firstedge, numedges, texinfo: i32 |
// | clipnode    | 8      | 12   | 12   | children i32                                      |
// | edge        | 4      | 8    | 8    | vertex indices u32                                |
// | marksurface | 2      | 4    | 4    | face index u32                                    |
// Planes, vertices, texinfo, models, textures, visibility and entities are the same in all three.
// Code that reads or writes these records asks a BspLayout for sizes and offsets instead of
// assuming BSP 29's, so one reader and one writer serve every variant.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace pvs::quake {

enum class BspVariant : uint8_t { Bsp29, Bsp2, Bsp2Rmq };

// "BSP 29", "BSP2", "2PSB".
const char* bsp_variant_name(BspVariant variant);

struct BspLayout {
    BspVariant variant = BspVariant::Bsp29;
    uint32_t node_size = 24, leaf_size = 28, face_size = 20, clipnode_size = 8, edge_size = 4, marksurface_size = 2;
    bool wide = false;         // children, face fields, marksurfaces and edges are 32-bit
    bool float_bounds = false; // node and leaf bounds are f32[3] (BSP2), not i16[3]
    // leaf: contents@0, visofs@4, bounds@8, then these
    uint32_t leaf_first_marksurface = 20, leaf_marksurface_count = 22, leaf_ambient = 24;
    // node: planenum@0, children@4, bounds@8 (BSP 29) or @12, then these
    uint32_t node_bounds = 8, node_first_face = 20, node_face_count = 22;
    // face: planenum@0, then these
    uint32_t face_side = 2, face_first_edge = 4, face_edge_count = 8, face_texinfo = 10, face_styles = 12,
             face_light = 16;
};

BspLayout bsp_layout(BspVariant variant);

// The variant whose version field or tag the bytes start with; nullopt for anything else
// (including Quake 2's "IBSP" and Half-Life's 30, which are other formats).
std::optional<BspVariant> detect_bsp_variant(std::span<const uint8_t> bytes);

// What the first four bytes say, for errors about files that are not one of the variants:
// "Quake 2 IBSP version 38", "Quake 3 IBSP version 46", "Half-Life BSP 30", "version 17", ...
std::string describe_bsp_header(std::span<const uint8_t> bytes);

} // namespace pvs::quake
