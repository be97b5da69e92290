// EverQuest WLD files: the container and the visibility fragments, parsed into plain data close
// to the file, and written back (../shared/formats/eq-s3d-wld.md §2 container, §3 0x21 BSP tree,
// §4 0x22 region, §5 0x29 region flag, §7 ordering and counting rules, §8 known answers).
//
// This layer does not build a Zone; it exposes the file's own numbering, which the zone mapping
// translates:
//  - Fragments are numbered 1, 2, 3... in file order, as references use them:
//    WldFile::fragments[n - 1] is fragment n, and error messages say "fragment n".
//  - Regions are numbered by the order of the 0x22 fragments alone (§7.3): the k-th 0x22
//    (k from 1) is 0x21 leaf region k, 0x29 list value k - 1 and VISLIST position k - 1.
//    WldFile::region_fragments[k - 1] is its fragment number.
//
// Parsing is strict about structure and lenient about meaning (the decisions are listed in
// docs/formats-eq.md, "EverQuest WLD"):
//  - parse_wld checks the header (magic, a known version, a string hash inside the file), that
//    every fragment lies inside the file, every name_ref names a string, and that the header's
//    region_count equals the number of 0x22 fragments. The FF FF FF FF trailer is optional.
//  - The typed parsers read every counted part of their fragment, each count checked against the
//    bytes left in the fragment before anything is reserved, so a count of 2^31 fails cleanly.
//    Trailing bytes after the last field (padding) are ignored, as every reader does.
//  - Fragment references (ambient light, mesh, wall sprite) must be 0, a fragment number
//    BEFORE the referencing fragment (§7.2: every examined writer and ZU/WQ need that), or a
//    negative reference by name whose string exists. They are kept as stored; see
//    resolve_fragment_ref. Region numbers (0x21 region, 0x29 list) must name an existing 0x22;
//    0x21 child numbers an existing node, with no node reachable twice from the root.
// Every problem throws pvs::FileError(file name, absolute offset in the WLD bytes, reason); the
// reason starts with "fragment N (0xTT name): " when the problem is inside fragment N.
//
// Writing: write_bsp_tree / write_region / write_region_flag produce fragment bodies (from the
// name_ref on, zero-padded to a multiple of 4); write_wld assembles a whole file from the
// strings and bodies and fills in every header count itself. parse(write(x)) == x for any x the
// writers accept, placed in a file where its references and region numbers are valid (a body
// does not know its own fragment number); they throw std::invalid_argument for data the file
// cannot hold.
#pragma once

#include "visibility/codec/eq_vislist.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pvs::eq {

inline constexpr uint32_t kWldMagic = 0x54503D02;      // bytes 02 3D 50 54
inline constexpr uint32_t kWldVersionOld = 0x00015500; // 0x36 UVs are i16 / 256
inline constexpr uint32_t kWldVersionNew = 0x1000C800; // 0x36 UVs are f32
inline constexpr uint64_t kWldHeaderSize = 28;
inline constexpr uint64_t kWldFragmentHeaderSize = 8; // u32 size, u32 type

// Fragment types pvscope knows by name.
inline constexpr uint32_t kWldBitmapName = 0x03;
inline constexpr uint32_t kWldSpriteDef = 0x04;
inline constexpr uint32_t kWldSprite = 0x05;
inline constexpr uint32_t kWldBspTree = 0x21;
inline constexpr uint32_t kWldRegion = 0x22;
inline constexpr uint32_t kWldRegionFlag = 0x29;
inline constexpr uint32_t kWldLegacyMesh = 0x2C;
inline constexpr uint32_t kWldMaterial = 0x30;
inline constexpr uint32_t kWldMaterialPalette = 0x31;
inline constexpr uint32_t kWldAmbientLight = 0x35; // its name_ref slot holds a colour, not a string
inline constexpr uint32_t kWldMesh = 0x36;

// "region", "bsp tree", ... for error messages; "" for a type pvscope has no name for.
const char* wld_fragment_type_name(uint32_t type);

// ---- Container (§2) ----

struct WldHeader {
    uint32_t version = kWldVersionOld;
    uint32_t fragment_count = 0;
    uint32_t region_count = 0;     // must equal the number of 0x22 fragments (§7.3)
    uint32_t max_object_bytes = 0; // informational; QL alone checks it
    uint32_t string_hash_size = 0; // encoded bytes, padding included
    uint32_t string_count = 0;     // informational ([U], §2.1)
    bool operator==(const WldHeader&) const = default;
};

struct WldFragment {
    uint32_t type = 0;
    int32_t name_ref = 0;     // body offset 0
    uint64_t body_offset = 0; // absolute offset of the body (its name_ref) in the WLD bytes
    uint32_t body_size = 0;   // the header's size field: name_ref + fields + padding
    bool operator==(const WldFragment&) const = default;
};

struct WldFile {
    std::string name;               // the archive member, e.g. "gfaydark.wld"; names errors
    std::span<const uint8_t> bytes; // the whole file, NOT owned: keep it alive while parsing fragments
    WldHeader header;
    std::vector<char> strings;              // decoded string hash, cut after its last NUL
    std::vector<WldFragment> fragments;     // fragments[n - 1] is fragment n
    std::vector<uint32_t> region_fragments; // fragment numbers of the 0x22 fragments, in file order
    bool has_trailer = false;               // FF FF FF FF after the last fragment

    uint32_t region_count() const { return static_cast<uint32_t>(region_fragments.size()); }
    // Fragment `number` (1-based); std::out_of_range for a number outside the file.
    const WldFragment& fragment(uint32_t number) const;
};

// Parses the container: header, string hash, fragment table. `bytes` must outlive the result.
WldFile parse_wld(std::span<const uint8_t> bytes, const std::string& name);

// The fragment's name ("" when it has none, and for 0x35, whose name_ref slot is a colour).
std::string_view fragment_name(const WldFile& wld, const WldFragment& fragment);

// The fragment number a reference field names: itself when positive, 0 for none, and for a
// negative reference (by name) the first fragment carrying that name (LQ's rule), 0 if none.
// A linear search: writers never produce name references and real files are not known to.
uint32_t resolve_fragment_ref(const WldFile& wld, int32_t ref);

// ---- 0x21 BSP tree (§3) ----

struct WldBspNode {
    glm::vec3 normal{0.0f}; // plane: dot(normal, p) + d = 0, WLD coordinates (z up)
    float d = 0.0f;
    uint32_t region = 0; // leaf: 1-based region number (k-th 0x22); internal node: 0
    uint32_t front = 0;  // 1-based node number in this tree, 0 = none; s >= 0 goes here (§3.3)
    uint32_t back = 0;   // 1-based node number, 0 = none; s < 0
    bool operator==(const WldBspNode&) const = default;
};

struct WldBspTree {
    int32_t name_ref = 0;
    std::vector<WldBspNode> nodes; // nodes[0] is node 1, the root
    bool operator==(const WldBspTree&) const = default;
};

// Node planes must be finite; region numbers <= the file's region count; children <= node count;
// no node reachable twice from the root (so every walk ends). Both leaf rules readers use
// (region > 0; no children) are left to the caller.
WldBspTree parse_bsp_tree(const WldFile& wld, uint32_t number);
// Writes node_count = nodes.size(); the body is 8 + 28 * nodes bytes (always a multiple of 4).
std::vector<uint8_t> write_bsp_tree(const WldBspTree& tree);

// ---- 0x22 region (§4) ----

// Region flags (§4.2).
inline constexpr uint32_t kWldRegionSphere = 0x001;         // sphere present
inline constexpr uint32_t kWldRegionReverbVolume = 0x002;   // reverb_volume present
inline constexpr uint32_t kWldRegionReverbOffset = 0x004;   // reverb_offset present
inline constexpr uint32_t kWldRegionFog = 0x008;            // no data
inline constexpr uint32_t kWldRegionGouraud2 = 0x010;       // no data
inline constexpr uint32_t kWldRegionEncodedVis = 0x020;     // no data, meaning unknown
inline constexpr uint32_t kWldRegionLegacyMeshRef = 0x040;  // LX/QL: mesh_ref present (see WldRegion)
inline constexpr uint32_t kWldRegionVislistBytes = 0x080;   // set: byte-form lists; clear: word form
inline constexpr uint32_t kWldRegionMeshRef = 0x100;        // mesh_ref present

// Wall flags and render info flags (§4.3).
inline constexpr uint32_t kWldWallFloor = 0x1;
inline constexpr uint32_t kWldWallRenderData = 0x2; // render_method, render_info and normal present
inline constexpr uint32_t kWldRenderPen = 0x01;
inline constexpr uint32_t kWldRenderBrightness = 0x02;
inline constexpr uint32_t kWldRenderScaledAmbient = 0x04;
inline constexpr uint32_t kWldRenderSprite = 0x08;
inline constexpr uint32_t kWldRenderUvInfo = 0x10;
inline constexpr uint32_t kWldRenderUvMap = 0x20;
inline constexpr uint32_t kWldRenderTwoSided = 0x40; // no data

// Obstacle flags and the obstacle types that carry data (§4.3).
inline constexpr uint32_t kWldObstacleFloor = 0x1;
inline constexpr uint32_t kWldObstacleCutting = 0x2;
inline constexpr uint32_t kWldObstacleUserData = 0x4;
inline constexpr int32_t kWldObstacleEdgePolygon = 14;        // vertex list
inline constexpr int32_t kWldObstacleEdgePolygonNormal = -15; // vertex list + normal
inline constexpr int32_t kWldObstacleEdgeWall = 18;           // wall index
// Types 8..13 (XY_VERTEX .. PLANE) carry nothing; any other type is rejected (its size is unknown).

struct WldRenderInfo {
    uint32_t flags = 0;          // kWldRender*: which of the fields below are present
    uint32_t pen = 0;            // kWldRenderPen
    float brightness = 0.0f;     // kWldRenderBrightness
    float scaled_ambient = 0.0f; // kWldRenderScaledAmbient
    int32_t sprite_ref = 0;      // kWldRenderSprite: fragment reference (0x05)
    glm::vec3 uv_origin{0.0f}, u_axis{0.0f}, v_axis{0.0f}; // kWldRenderUvInfo
    std::vector<glm::vec2> uv_map;                         // kWldRenderUvMap (u32 count + pairs)
    bool operator==(const WldRenderInfo&) const = default;
};

struct WldWall {
    uint32_t flags = 0;             // kWldWall*
    std::vector<uint32_t> vertices; // vertex indices, kept as stored (not checked: see docs)
    uint32_t render_method = 0;     // kWldWallRenderData
    WldRenderInfo render_info;      // kWldWallRenderData
    glm::vec4 normal{0.0f};         // kWldWallRenderData: a, b, c, d
    bool operator==(const WldWall&) const = default;
};

struct WldObstacle {
    uint32_t flags = 0;             // kWldObstacle*
    int32_t next_region = 0;        // kept as stored: numbering not established
    int32_t type = 0;               // 8..14, -15, 18
    std::vector<uint32_t> vertices; // EDGEPOLYGON, EDGEPOLYGON+NORMALABCD
    glm::vec4 normal{0.0f};         // EDGEPOLYGON+NORMALABCD
    uint32_t edge_wall = 0;         // EDGEWALL: 0-based index into the region's walls
    std::vector<uint8_t> user_data; // kWldObstacleUserData: raw bytes
    bool operator==(const WldObstacle&) const = default;
};

struct WldProximalRegion {
    uint32_t region = 0; // kept as stored: base not established
    float distance = 0.0f;
    bool operator==(const WldProximalRegion&) const = default;
};

struct WldVisNode {
    glm::vec4 normal{0.0f};
    uint32_t vis_list_index = 0; // 1-based into the region's lists, 0 = none
    uint32_t front = 0;          // 1-based vis node numbers, 0 = none
    uint32_t back = 0;
    bool operator==(const WldVisNode&) const = default;
};

struct WldVisList {
    bool byte_form = true;     // the region's flag bit 7 (the same for all its lists)
    std::vector<uint8_t> data; // the raw elements: range_count bytes, or range_count u16 LE words
    uint32_t range_count() const { return static_cast<uint32_t>(byte_form ? data.size() : data.size() / 2); }
    bool operator==(const WldVisList&) const = default;
};

struct WldRegion {
    int32_t name_ref = 0;
    uint32_t flags = 0;        // kWldRegion*: which optional parts are present
    int32_t ambient_light = 0; // fragment reference, normally 0
    std::vector<glm::vec3> vertices;
    std::vector<WldProximalRegion> proximal_regions;
    std::vector<glm::vec3> render_vertices; // always read (LX/QL), see docs
    std::vector<WldWall> walls;
    std::vector<WldObstacle> obstacles;
    uint32_t cutting_obstacle_count = 0; // no payload layout is known; none is read
    std::vector<WldVisNode> vis_nodes;
    std::vector<WldVisList> vis_lists;
    glm::vec4 sphere{0.0f};      // kWldRegionSphere: centre x, y, z and radius
    float reverb_volume = 0.0f;  // kWldRegionReverbVolume
    int32_t reverb_offset = 0;   // kWldRegionReverbOffset
    std::vector<uint8_t> user_data; // raw bytes (u32 size always present)
    // Present when flags has kWldRegionMeshRef, or kWldRegionLegacyMeshRef and 4 more bytes are
    // left (LX/QL read it for bit 6, LQ/WQ do not). 0 = none; a positive value must name an
    // earlier 0x36 (or legacy 0x2C) fragment.
    int32_t mesh_ref = 0;
    bool operator==(const WldRegion&) const = default;
};

WldRegion parse_region(const WldFile& wld, uint32_t number);
// Writes every part; counts come from the vector sizes. Throws std::invalid_argument when a
// list's form differs from flags bit 7, a list holds more than 65535 elements, a word list has
// an odd byte count, or an obstacle type is not one parse_region accepts.
std::vector<uint8_t> write_region(const WldRegion& region);

// The §4.7 interoperable subset, which every examined reader parses the same way:
// flags 0x181 (mesh_ref > 0) or 0x81; ambient 0; no vertices, proximal regions, render
// vertices, walls or obstacles; one all-zero VisNode naming list 1; one byte-form list; the
// sphere; no reverb; no user data; the mesh reference.
WldRegion make_interoperable_region(int32_t name_ref, std::vector<uint8_t> vislist_bytes, glm::vec4 sphere,
                                    int32_t mesh_ref);
bool is_interoperable_region(const WldRegion& region);

// Decodes one list into a bit row of region_count bits with the visibility/codec decoders
// (byte form §4.4, word form §4.5). `out` needs bits::words_for(region_count) words.
EqVislistResult decode_vis_list(const WldVisList& list, size_t region_count, std::span<uint64_t> out);

// ---- 0x29 region flag (§5) ----

// A zone line's destination as encoded in a DRNTP/WTNTP/LANTP string (§5.2).
struct WldZoneLineTarget {
    uint32_t zone_id = 255;   // 255: the target is a zone point of the current zone's list
    uint32_t zone_point = 0;  // zone_id == 255
    int32_t x = 0, y = 0, z = 0; // zone_id != 255: destination position (whole units)
    int32_t heading = 0;
    bool operator==(const WldZoneLineTarget&) const = default;
};

enum class WldTypeSource : uint8_t { None, Name, UserData };

// The region type one string encodes: pvs::RegionFlag bits (visibility/zone.h: kRegionWater,
// kRegionLava, kRegionSlime, kRegionIce, kRegionVWater, kRegionPvp, kRegionZoneLine), 0 when the
// string names no type, plus the zone-line target when the string encodes one.
struct WldRegionType {
    uint32_t flags = 0;
    std::optional<WldZoneLineTarget> zone_line;
    bool operator==(const WldRegionType&) const = default;
};
WldRegionType classify_region_type(std::string_view text);

struct WldRegionFlag {
    int32_t name_ref = 0;
    uint32_t flags = 0;           // "usually 0", meaning unknown
    std::vector<uint32_t> regions; // 0-based region numbers (the k-th 0x22 is k - 1)
    std::string user_data;        // decoded, up to the first NUL
    // Derived, not stored: from the name, else from the user data (ZU's order, §5.2).
    WldRegionType type;
    WldTypeSource type_source = WldTypeSource::None;
    bool operator==(const WldRegionFlag&) const = default;
};

WldRegionFlag parse_region_flag(const WldFile& wld, uint32_t number);
// Writes name_ref, flags, the list and the user data (encoded, with its NUL counted, §5.1);
// empty user data is written as size 0. The derived type is not written (it lives in the name).
std::vector<uint8_t> write_region_flag(const WldRegionFlag& flag);

// ---- Assembling a file (§7.4) ----

struct WldFragmentBytes {
    uint32_t type = 0;
    std::vector<uint8_t> body; // from the name_ref on; padded with zeros to 4 when written
};

// A complete WLD: header (fragment_count, region_count = number of 0x22, max_object_bytes =
// largest size + 8, string_hash_size, string_count = strings after the leading empty one), the
// encoded string hash, every fragment, and the FF FF FF FF trailer.
// `strings` is the decoded hash (WldStringTable::data()): empty, or starting and ending with a NUL.
// Throws std::invalid_argument for an unknown version, a body shorter than its name_ref, a
// name_ref that is positive or outside `strings`, a second 0x21, or an order readers cannot
// follow (§7.2): a 0x22 before the 0x21, a 0x29 before the 0x21 or before the last 0x22.
std::vector<uint8_t> write_wld(uint32_t version, std::span<const char> strings,
                               std::span<const WldFragmentBytes> fragments);

} // namespace pvs::eq
