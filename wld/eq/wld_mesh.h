// EverQuest WLD mesh fragment 0x36 (DmSpriteDef2): parsed into plain data with positions, uvs
// and normals decoded, and written back (../shared/formats/eq-s3d-wld.md §6.1, §6.2, §7.4).
// The material chain a mesh's faces name is in wld_material.h.
//
// Parsing follows wld_file.h (strict about structure, lenient about meaning):
//  - Every counted array (vertices, uvs, normals, colours, faces, skin groups, face and vertex
//    material groups, mesh ops) is checked against the bytes left in the fragment before
//    anything is reserved; the error names the count and sits at the count's offset.
//  - Face vertex indices must be < vertex_count. The face material groups must cover exactly
//    face_count faces (faces are sorted by material, §6.2), and each group's material index
//    must be inside the palette when material_palette_ref leads to one (a 0 reference, or a
//    by-name one that no fragment carries, leaves the indices unchecked).
//  - material_palette_ref must be 0, an EARLIER 0x31, or a name that exists; animation_ref 0,
//    an earlier fragment, or a name that exists. fragment3 / fragment4 are kept as stored and
//    not checked (every reader ignores them; LQ: fragment4 often names the first 0x03).
//  - scale must be <= 32767 (LQ/QL read a u16, ZU/WQ an i16: above that they disagree), and
//    the center finite (positions are center + raw / 2^scale).
//  - Face winding is kept as stored, (v0, v1, v2): LQ keeps it, ZU/WQ reverse it for their
//    renderers (§9.6). Use the triangles two-sided for visibility.
//  - min / max are kept as stored and not interpreted: LQ reads them as absolute, WQ as
//    relative to the center (§9.7), and zone meshes often store 0. mesh_bounds() computes
//    bounds from the vertices.
// Every problem throws pvs::FileError(file name, absolute offset, "fragment N (0x36 mesh): ...").
//
// Writing: write_mesh writes every array with counts from the vector sizes. It does not write
// the stored `scale`: it chooses mesh_scale_for(mesh), the largest scale <= 15 for which every
// |position - center| * 2^scale rounds to at most 32767, so each coordinate comes back within
// 2^-(scale + 1) of what was given (before the float rounding of center + offset); positions
// on that grid come back exactly. Everything else comes back exactly: parse(write(m)) == m with
// m.scale = mesh_scale_for(m), placed in a file of m.uv_form's version whose palette has the
// materials the groups name.
#pragma once

#include "wld/eq/wld_file.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace pvs::eq {

inline constexpr uint32_t kWldMeshZoneFlags = 0x00018003;   // zone meshes (LQ)
inline constexpr uint32_t kWldMeshObjectFlags = 0x00014003; // placeable objects (LQ)
inline constexpr uint16_t kWldFacePassable = 0x0010;        // face flag: passable / no collision
inline constexpr uint16_t kWldMeshMaxScale = 15;            // the largest scale write_mesh chooses
inline constexpr uint64_t kWldMeshHeaderSize = 0x60;        // name_ref .. scale

// How a file stores 0x36 texture coordinates (§6.2): decided by the WLD header version.
enum class WldUvForm : uint8_t {
    I16, // version 0x00015500 ("old"): i16 u, i16 v, in 1/256 (value = raw / 256)
    F32, // version 0x1000C800 ("new"): f32 u, f32 v as stored
};
WldUvForm wld_uv_form(uint32_t version);

struct WldMeshFace {
    uint16_t flags = 0;                // kWldFacePassable; other bits unknown (usually 0)
    std::array<uint16_t, 3> vertices{}; // indices into the mesh's vertices, winding as stored
    bool passable() const { return (flags & kWldFacePassable) != 0; }
    bool operator==(const WldMeshFace&) const = default;
};

// A run of consecutive faces (face material groups) or vertices (vertex material groups) that
// use palette entry `material` (0-based).
struct WldMeshGroup {
    uint16_t count = 0;
    uint16_t material = 0;
    bool operator==(const WldMeshGroup&) const = default;
};

struct WldSkinGroup {
    uint16_t vertex_count = 0;
    uint16_t bone = 0;
    bool operator==(const WldSkinGroup&) const = default;
};

// 6 bytes per LQ and QL [U]: 4 bytes of indices or an f32, a u8 parameter and a u8 type; kept raw.
struct WldMeshOp {
    std::array<uint8_t, 4> data{};
    uint8_t param = 0;
    uint8_t type = 0;
    bool operator==(const WldMeshOp&) const = default;
};

struct WldMesh {
    int32_t name_ref = 0;
    uint32_t flags = kWldMeshZoneFlags;
    int32_t material_palette_ref = 0; // reference to a 0x31
    int32_t animation_ref = 0;        // reference to a 0x2F (animated vertices); 0 for static meshes
    int32_t fragment3 = 0;            // unknown, usually 0; not checked
    int32_t fragment4 = 0;            // unknown; not checked
    glm::vec3 center{0.0f};           // vertices are stored relative to it
    std::array<uint32_t, 3> params2{}; // usually 0
    float max_distance = 0.0f;        // radius around the center enclosing the vertices, as stored
    glm::vec3 min{0.0f};              // as stored, not interpreted (absolute or center-relative [D])
    glm::vec3 max{0.0f};
    uint16_t scale = 0;               // as stored; write_mesh writes mesh_scale_for(*this)
    WldUvForm uv_form = WldUvForm::I16; // the file's form (parse_mesh); what write_mesh writes
    std::vector<glm::vec3> positions; // decoded: center + raw / 2^scale (WLD coordinates, z up)
    std::vector<glm::vec2> uvs;       // decoded per uv_form (normally as many as positions, or none)
    std::vector<glm::vec3> normals;   // decoded: i8 / 127 per axis (may outnumber positions, §6.1)
    std::vector<uint32_t> colors;     // 4 bytes per vertex as stored (byte 0 first), normally V or 0
    std::vector<WldMeshFace> faces;
    std::vector<WldSkinGroup> skin_groups;  // 0 for zone meshes
    std::vector<WldMeshGroup> face_groups;  // cover faces in order; counts sum to faces.size()
    std::vector<WldMeshGroup> vertex_groups; // kept as stored (no total is required)
    std::vector<WldMeshOp> mesh_ops;        // 0 for zone meshes
    bool operator==(const WldMesh&) const = default;
};

WldMesh parse_mesh(const WldFile& wld, uint32_t fragment_number);

// The scale write_mesh uses: the largest s in [0, kWldMeshMaxScale] with every
// round(|position - center| * 2^s) <= 32767 (§7.4). Throws std::invalid_argument when a
// position or the center is not finite, or a position is more than 32767 units from the center
// on some axis (move the center).
uint16_t mesh_scale_for(const WldMesh& mesh);

// Writes the body (zero-padded to 4). Throws std::invalid_argument for what the fragment cannot
// hold or parse_mesh would refuse: more than 65535 elements in an array, positions
// mesh_scale_for refuses, a uv component that does not round to an i16 after * 256 in the I16
// form (about [-128, 128), NaN refused), a normal component that does not round to an i8 after
// * 127, a face vertex index >= the vertex count, face groups that do not cover exactly the
// faces. uvs (I16 form) come back to the nearest 1/256, normals to the nearest 1/127.
std::vector<uint8_t> write_mesh(const WldMesh& mesh);

// The 0-based palette index of each face, from the face groups.
std::vector<uint16_t> face_materials(const WldMesh& mesh);

// Bounds recomputed from the decoded positions (absolute WLD coordinates): min, max, and the
// largest distance of a position from the center. All zero for a mesh without vertices.
struct WldMeshBounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    float max_distance = 0.0f;
    bool operator==(const WldMeshBounds&) const = default;
};
WldMeshBounds mesh_bounds(const WldMesh& mesh);

} // namespace pvs::eq
