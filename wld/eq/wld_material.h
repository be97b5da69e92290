// EverQuest WLD material chain: 0x31 material palette, 0x30 material, 0x05 sprite, 0x04 sprite
// definition, 0x03 bitmap name (../shared/formats/eq-s3d-wld.md §6.3-§6.6, §7.2, §7.4, §8.3),
// parsed into plain data close to the file, written back, and resolved from a mesh face's
// material index to a texture file name.
//
// A face's texture: material_index -> 0x31.materials[material_index] -> 0x30 -> sprite_ref ->
// 0x05 -> sprite_def_ref -> 0x04 -> frames[0] -> 0x03 -> files[0], a file in the same .s3d.
//
// Parsing follows wld_file.h: strict about structure, lenient about meaning.
//  - Every counted part is checked against the bytes left in the fragment before anything is
//    reserved (0x03's stored count is names - 1, so 0xFFFFFFFF asks for 2^32 names and fails).
//  - Fragment references must be 0, a fragment number BEFORE the referencing fragment (§7.2),
//    or a negative reference by name whose string exists. A positive reference must also name
//    a fragment of the type the chain expects (0x31 -> 0x30 -> 0x05 -> 0x04 -> 0x03). They are
//    kept as stored; zero entries are kept too (WQ drops them, shifting later indices; pvscope
//    keeps the file's indices).
//  - Where readers disagree on a layout the LQ/QL reading is followed (they are the two
//    readers that also write, and LQ round-trips original files): 0x03 count = names - 1;
//    0x04 "current frame" present on flag 0x20 and "sleep" on 0x08 together with 0x10; 0x30
//    sprite_ref always at body offset 0x18 (ZU moves it 8 bytes on for flags == 0).
// Every problem throws pvs::FileError(file name, absolute offset, "fragment N (0xTT name): ...").
//
// Writing: each write_* is the exact inverse of its parse_* (parse(write(x)) == x, placed in a
// file where its references are valid). They throw std::invalid_argument only for what the
// format cannot hold. The interoperable subset (§7.4) is the caller's choice: one name per
// 0x03, 0x04 flags 0x10 with one frame, 0x05 flags 0x50, 0x30 flags 0x2 with the pair (0, 0.0),
// no zero or negative 0x31 entries, every reference positive and backward.
#pragma once

#include "wld/eq/wld_file.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pvs::eq {

// ---- 0x03 bitmap name (BmInfo, §6.6) ----

struct WldBitmapName {
    int32_t name_ref = 0;
    // Decoded file names (each up to its first NUL, case as stored; WQ lowercases). The stored
    // count is files.size() - 1 (LQ/QL); more than one name is an animation's frames [D].
    std::vector<std::string> files;
    bool operator==(const WldBitmapName&) const = default;
};

WldBitmapName parse_bitmap_name(const WldFile& wld, uint32_t number);
// Each name is written as u16 length (NUL included) + the encoded name + encoded NUL (§8.3:
// "sgrass.bmp" -> 0B 00 E6 5D B7 4B E6 09 BB 08 F8 4A C5). Throws std::invalid_argument for no
// names, a name with a NUL inside, or a name longer than 65534 bytes.
std::vector<uint8_t> write_bitmap_name(const WldBitmapName& bitmap);

// ---- 0x04 sprite definition (SimpleSpriteDef, §6.6) ----

inline constexpr uint32_t kWldSpriteDefAnimated = 0x08;     // with kWldSpriteDefBit4: sleep present
inline constexpr uint32_t kWldSpriteDefBit4 = 0x10;         // set in practice (LQ), meaning unknown
inline constexpr uint32_t kWldSpriteDefCurrentFrame = 0x20; // current frame present

struct WldSpriteDef {
    int32_t name_ref = 0;
    uint32_t flags = kWldSpriteDefBit4;
    uint32_t current_frame = 0;  // flags & kWldSpriteDefCurrentFrame
    uint32_t sleep = 0;          // flags has kWldSpriteDefAnimated and kWldSpriteDefBit4 (ms)
    std::vector<int32_t> frames; // references to 0x03, one per frame (frame_count = size)
    bool operator==(const WldSpriteDef&) const = default;
};

WldSpriteDef parse_sprite_def(const WldFile& wld, uint32_t number);
std::vector<uint8_t> write_sprite_def(const WldSpriteDef& sprite_def);

// ---- 0x05 sprite (SimpleSprite, §6.6) ----

struct WldSprite {
    int32_t name_ref = 0;
    int32_t sprite_def_ref = 0; // reference to 0x04, 0 = none
    uint32_t flags = 0x50;      // typically 0x50; nobody interprets it
    bool operator==(const WldSprite&) const = default;
};

WldSprite parse_sprite(const WldFile& wld, uint32_t number);
std::vector<uint8_t> write_sprite(const WldSprite& sprite);

// ---- 0x30 material (MaterialDef, §6.4, §6.5) ----

inline constexpr uint32_t kWldMaterialTwoSided = 0x1;
inline constexpr uint32_t kWldMaterialPair = 0x2; // the (u32, f32) pair is present

struct WldMaterial {
    int32_t name_ref = 0;
    uint32_t flags = kWldMaterialPair;
    uint32_t render_method = 0; // §6.5, see decode_render_method
    uint32_t rgb_pen = 0;       // 4 bytes as stored (typically 0x004E4E4E)
    float brightness = 0.0f;
    float scaled_ambient = 0.0f;
    int32_t sprite_ref = 0;    // reference to 0x05; 0 = no texture
    uint32_t pair_value = 0;   // flags & kWldMaterialPair; meaning unknown, usually 0
    float pair_factor = 0.0f;  // flags & kWldMaterialPair; usually 0.0
    bool operator==(const WldMaterial&) const = default;
};

WldMaterial parse_material(const WldFile& wld, uint32_t number);
std::vector<uint8_t> write_material(const WldMaterial& material);

// What a render_method says (§6.5, LQ's table). Bit 31 set: "user defined", the low 31 bits are
// a material type from a known list; bit 31 clear: packed fields.
enum class WldMaterialType : uint8_t {
    Packed,                    // bit 31 clear: see the packed fields
    Boundary,                  // user defined 0x00: not rendered
    Diffuse,                   // 0x01 0x02 0x12 0x14 0x15 0x19 0x31 0x553
    Transparent,               // 0x05 / 0x09 / 0x0A: 50 / 25 / 75 % (opacity_percent)
    TransparentMasked,         // 0x13
    TransparentMaskedPassable, // 0x07
    TransparentAdditive,       // 0x17
    TransparentAdditiveUnlit,  // 0x0B
    SkyDome,                   // 0x0D 0x0F 0x10
    Invisible,                 // 0x03 0x4B 0x53 ("invisible (unknown)")
    Unknown,                   // any other user-defined value (0x06, 0x1A, ...)
};

struct WldRenderMethod {
    uint32_t raw = 0;
    bool user_defined = false;    // bit 31
    uint32_t material_type = 0;   // user defined: raw & 0x7FFFFFFF
    WldMaterialType type = WldMaterialType::Packed;
    uint8_t opacity_percent = 100; // Transparent: 50, 25 or 75
    // Packed fields (bit 31 clear): draw style bits 0-1, lighting 2-4, shading 5-6, texture
    // style 7-10. Decoded for both forms (they are just bit fields of raw).
    uint8_t draw_style = 0, lighting = 0, shading = 0, texture_style = 0;
    // false when (raw & 0x7FFFFFFF) == 0 (WQ; ZU: raw == 0), or the type is Boundary or
    // Invisible. A drawn material can still be see-through: see `transparent`.
    bool drawn = false;
    // A known transparent, masked or additive type. Unknown and packed values count as opaque.
    bool transparent = false;
    bool operator==(const WldRenderMethod&) const = default;
};

WldRenderMethod decode_render_method(uint32_t raw);

// ---- 0x31 material palette (MaterialPalette, §6.3) ----

struct WldMaterialPalette {
    int32_t name_ref = 0;
    uint32_t flags = 0;              // 0 per LQ; kept as stored
    std::vector<int32_t> materials;  // references to 0x30; a mesh's material_index indexes this
    bool operator==(const WldMaterialPalette&) const = default;
};

WldMaterialPalette parse_material_palette(const WldFile& wld, uint32_t number);
std::vector<uint8_t> write_material_palette(const WldMaterialPalette& palette);

// ---- Resolving a mesh face's material (§6.6) ----

// The 0x30 fragment number of palette entry `material_index` (resolve_fragment_ref: by-name
// entries are looked up), 0 when the entry is 0 or names no fragment. Throws FileError when a
// fragment on the way is not of the expected type or does not parse, std::out_of_range when
// material_index is past the palette.
uint32_t material_fragment_of(const WldFile& wld, uint32_t palette_fragment, uint32_t material_index);

// The texture file the material shows: the first name of the first frame's 0x03. Empty when
// the chain ends before a bitmap (no material, sprite_ref 0, no sprite definition, no frames,
// a by-name reference nothing carries). Same exceptions as material_fragment_of.
std::string texture_file_of(const WldFile& wld, uint32_t palette_fragment, uint32_t material_index);

// Whether faces with this material are drawn: there is a material, its render method is drawn
// (decode_render_method) and its sprite_ref is not 0 (WQ and ZU: invisible otherwise). Same
// exceptions as material_fragment_of.
bool material_is_visible(const WldFile& wld, uint32_t palette_fragment, uint32_t material_index);

} // namespace pvs::eq
