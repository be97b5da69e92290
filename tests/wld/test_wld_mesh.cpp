// EverQuest WLD mesh 0x36 and the material chain 0x31 / 0x30 / 0x05 / 0x04 / 0x03
// (wld/eq/wld_mesh.h, wld/eq/wld_material.h) against ../shared/formats/eq-s3d-wld.md §6, §7, §8.3:
// the 0x03 name known answer; a WLD hand-assembled here from the spec's tables (§2.1, §2.3, §6.1,
// §6.3, §6.4, §6.6), in the old (i16 uv) and the new (f32 uv) version, with a material chain
// 0x03 -> 0x04 -> 0x05 -> 0x30 -> 0x31 and two 0x36 meshes using it, every field checked and
// every fragment written back byte for byte; writer-built files parsed back; bad input that must
// throw FileError naming the fragment and the problem; a truncation / random-change sweep (run
// under ASan + UBSan by tests/run-all.sh).
#include "tests/wld/wld_test_bytes.h"
#include "visibility/file_error.h"
#include "wld/eq/wld_file.h"
#include "wld/eq/wld_material.h"
#include "wld/eq/wld_mesh.h"
#include "wld/eq/wld_string_hash.h"

#include <gtest/gtest.h>

#include <cstdio>

#include <cmath>
#include <map>
#include <random>

namespace pvs::eq {
namespace {

using namespace wld_test;

constexpr uint32_t kOld = 0x00015500; // i16 / 256 uvs
constexpr uint32_t kNew = 0x1000C800; // f32 uvs
constexpr uint32_t kVersions[2] = {kOld, kNew};

// §8.3: "sgrass.bmp" + NUL.
const Bytes kSgrass = {0xE6, 0x5D, 0xB7, 0x4B, 0xE6, 0x09, 0xBB, 0x08, 0xF8, 0x4A, 0xC5};

// ---------------------------------------------------------------------------------------------
// The hand-assembled file:
//    1 0x03 SGRASS_BM         "sgrass.bmp" (count 0: one name)
//    2 0x03 WATER_BM          "water1.bmp", "WATER2.BMP" (count 1: two names, LQ/QL)
//    3 0x04 SGRASS_SPRITEDEF  flags 0x10, frames {1}
//    4 0x04 WATER_SPRITEDEF   flags 0x38 (current frame + sleep), frames {2, 1}
//    5 0x05 SGRASS_SPRITE     -> 3
//    6 0x05 WATER_SPRITE      -> 4
//    7 0x30 SGRASS_MDF        opaque diffuse 0x80000001, sprite 5
//    8 0x30 INVIS_MDF         render_method 0, sprite 0 (invisible), pair (7, 1.5)
//    9 0x30 WATER_MDF         two-sided, transparent 50 % 0x80000005, sprite 6
//   10 0x30 PACKED_MDF        flags 0x1 (no pair), packed render method 0x193, sprite 5
//   11 0x31 ZONE_MP           {7, 8, 9, 10}
//   12 0x36 R1_DMSPRITEDEF    zone mesh: 4 vertices, 3 faces (one passable), groups
//                             {1 x material 0, 2 x material 1 (invisible)}, scale 8
//   13 0x36 OBJ_DMSPRITEDEF   object mesh: normals > vertices, skin groups, mesh ops, scale 0

const char* const kNames[13] = {"SGRASS_BM",    "WATER_BM",      "SGRASS_SPRITEDEF", "WATER_SPRITEDEF",
                                "SGRASS_SPRITE", "WATER_SPRITE", "SGRASS_MDF",       "INVIS_MDF",
                                "WATER_MDF",     "PACKED_MDF",   "ZONE_MP",          "R1_DMSPRITEDEF",
                                "OBJ_DMSPRITEDEF"};

struct HandMade {
    uint32_t version = 0;
    Bytes file;
    std::string strings; // decoded
    std::map<std::string, int32_t> refs;
    std::vector<uint32_t> types;
    std::vector<Bytes> bodies; // as built, unpadded
    std::vector<uint64_t> body_at;
    std::map<std::string, std::pair<uint32_t, uint64_t>> marks; // fragment, body offset

    uint64_t field(uint32_t fragment, uint64_t body_offset) const { return body_at[fragment - 1] + body_offset; }
    uint64_t at(const std::string& key) const
    {
        const auto& [fragment, offset] = marks.at(key);
        return field(fragment, offset);
    }
};

HandMade build_hand_made(uint32_t version)
{
    const bool f32_uv = version == kNew;
    HandMade h;
    h.version = version;
    SpecStrings strings;
    for (const char* s : kNames)
        strings.add(s);
    h.strings = strings.decoded;
    h.refs = strings.refs;
    const auto add = [&](uint32_t type, const Builder& b) {
        h.types.push_back(type);
        h.bodies.push_back(b.out);
    };
    // Marks a field of the fragment being built.
    const auto mark = [&](const char* key, const Builder& b) {
        h.marks[key] = {uint32_t(h.bodies.size() + 1), b.size()};
    };

    {   // 1: §6.6 0x03, one name
        Builder b;
        b.i32(h.refs["SGRASS_BM"]);
        mark("bm1.count", b);
        b.u32(0);
        mark("bm1.length", b);
        b.u16(11).raw(kSgrass);
        add(kWldBitmapName, b);
    }
    {   // 2: two names, each encoded with the key restarting at 0
        Builder b;
        b.i32(h.refs["WATER_BM"]).u32(1);
        for (const std::string name : {"water1.bmp", "WATER2.BMP"})
            b.u16(uint16_t(name.size() + 1)).raw(spec_xor(name + std::string(1, '\0')));
        add(kWldBitmapName, b);
    }
    {   // 3: 0x04 flags 0x10, frame_count 1
        Builder b;
        b.i32(h.refs["SGRASS_SPRITEDEF"]).u32(0x10);
        mark("def3.count", b);
        b.u32(1);
        mark("def3.frame0", b);
        b.i32(1);
        add(kWldSpriteDef, b);
    }
    {   // 4: flags 0x38: current frame (0x20) and sleep (0x08 + 0x10), two frames
        Builder b;
        b.i32(h.refs["WATER_SPRITEDEF"]).u32(0x38).u32(2).u32(1).u32(250).i32(2).i32(1);
        add(kWldSpriteDef, b);
    }
    {   // 5, 6: 0x05
        Builder b;
        b.i32(h.refs["SGRASS_SPRITE"]);
        mark("sprite5.ref", b);
        b.i32(3).u32(0x50);
        add(kWldSprite, b);
        Builder c;
        c.i32(h.refs["WATER_SPRITE"]).i32(4).u32(0x50);
        add(kWldSprite, c);
    }
    {   // 7-10: §6.4 0x30
        Builder b;
        b.i32(h.refs["SGRASS_MDF"]).u32(0x2).u32(0x80000001u).u32(0x004E4E4E).f32(0.75f).f32(0.5f);
        mark("mdf7.sprite", b);
        b.i32(5).u32(0).f32(0.0f);
        add(kWldMaterial, b);
        Builder c;
        c.i32(h.refs["INVIS_MDF"]).u32(0x2).u32(0).u32(0).f32(0.0f).f32(0.0f).i32(0).u32(7).f32(1.5f);
        add(kWldMaterial, c);
        Builder d;
        d.i32(h.refs["WATER_MDF"]).u32(0x3).u32(0x80000005u).u32(0x00FFFFFF).f32(1.0f).f32(0.25f).i32(6);
        d.u32(0).f32(0.0f);
        add(kWldMaterial, d);
        Builder e;
        e.i32(h.refs["PACKED_MDF"]).u32(0x1).u32(0x193).u32(0x00808080).f32(0.5f).f32(0.0f).i32(5);
        add(kWldMaterial, e);
    }
    {   // 11: §6.3 0x31
        Builder b;
        b.i32(h.refs["ZONE_MP"]).u32(0);
        mark("mp.count", b);
        b.u32(4);
        mark("mp.entry0", b);
        b.i32(7);
        mark("mp.entry1", b);
        b.i32(8).i32(9).i32(10);
        add(kWldMaterialPalette, b);
    }
    {   // 12: §6.1 zone mesh
        Builder b;
        b.i32(h.refs["R1_DMSPRITEDEF"]).u32(0x00018003);
        mark("A.palette", b);
        b.i32(11);
        mark("A.animation", b);
        b.i32(0).i32(0).i32(1); // animation, fragment3, fragment4 (LQ: often the first 0x03)
        mark("A.center", b);
        b.f32(100).f32(200).f32(-50);
        b.u32(0).u32(0).u32(0).f32(150).f32(1).f32(2).f32(3).f32(4).f32(5).f32(6); // params2, max_distance, min, max
        mark("A.counts", b);
        b.u16(4).u16(4).u16(4).u16(4).u16(3).u16(0).u16(2).u16(2).u16(0); // V T Nn C F S G H M
        mark("A.scale", b);
        b.u16(8);
        mark("A.vertices", b);
        b.i16(0).i16(0).i16(0).i16(25600).i16(0).i16(128).i16(25600).i16(-12800).i16(-256);
        b.i16(-64).i16(32767).i16(1);
        if (f32_uv)
            b.f32(0).f32(0).f32(1).f32(0).f32(1).f32(-2.25f).f32(0.5f).f32(127.99609375f);
        else
            b.i16(0).i16(0).i16(256).i16(0).i16(256).i16(-576).i16(128).i16(32767);
        b.i8(0).i8(0).i8(127).i8(0).i8(0).i8(-127).i8(127).i8(0).i8(0).i8(-128).i8(64).i8(1);
        b.u32(0xFF00FF00u).u32(0x11223344u).u32(0).u32(0xFFFFFFFFu);
        mark("A.faces", b);
        b.u16(0).u16(0).u16(1).u16(2);
        b.u16(0).u16(0).u16(2);
        mark("A.face1.v2", b);
        b.u16(3);
        b.u16(0x10).u16(1).u16(2).u16(3);
        mark("A.group0.count", b);
        b.u16(1).u16(0);
        mark("A.group1.count", b);
        b.u16(2);
        mark("A.group1.material", b);
        b.u16(1);
        b.u16(3).u16(0).u16(1).u16(1); // vertex groups
        add(kWldMesh, b);
    }
    {   // 13: object mesh
        Builder b;
        b.i32(h.refs["OBJ_DMSPRITEDEF"]).u32(0x00014003).i32(11).i32(0).i32(0).i32(0);
        b.f32(-1000.5f).f32(0.25f).f32(3).u32(0).u32(0).u32(0).f32(20000);
        b.f32(0).f32(0).f32(0).f32(0).f32(0).f32(0);
        mark("B.counts", b);
        b.u16(3).u16(3).u16(5).u16(0).u16(1).u16(2).u16(1).u16(0).u16(2);
        b.u16(0);
        b.i16(20000).i16(-1).i16(0).i16(-20000).i16(5).i16(7).i16(0).i16(0).i16(-3);
        if (f32_uv)
            b.f32(0.25f).f32(-0.5f).f32(2).f32(3).f32(-128).f32(0);
        else
            b.i16(64).i16(-128).i16(512).i16(768).i16(-32768).i16(0);
        b.i8(1).i8(2).i8(3).i8(-1).i8(-2).i8(-3).i8(0).i8(0).i8(0).i8(127).i8(127).i8(127).i8(-127).i8(0).i8(0);
        b.u16(0x11).u16(2).u16(1).u16(0);
        b.u16(2).u16(0).u16(1).u16(1); // skin groups
        b.u16(1).u16(2);               // one face group: material 2
        b.u8(1).u8(0).u8(2).u8(0).u8(5).u8(1);
        b.f32(1.0f).u8(0).u8(4);
        add(kWldMesh, b);
    }

    SpecFile f = spec_wld(version, h.strings, h.types, h.bodies);
    h.file = std::move(f.file);
    h.body_at = std::move(f.body_at);
    return h;
}

const HandMade& hand_made(uint32_t version)
{
    static const HandMade old_form = build_hand_made(kOld);
    static const HandMade new_form = build_hand_made(kNew);
    return version == kOld ? old_form : new_form;
}

Bytes body_of(const HandMade& h, uint32_t number) { return padded(h.bodies[number - 1]); }

// ---------------------------------------------------------------------------------------------
// §8.3 0x03 name known answer

TEST(WldMaterialNames, SgrassKnownAnswer)
{
    EXPECT_EQ(spec_xor(std::string("sgrass.bmp\0", 11)), kSgrass);
    // name_ref 0, count 0, len 0B 00, the encoded name, 3 bytes of padding (21 -> 24)
    Bytes expected = {0, 0, 0, 0, 0, 0, 0, 0, 0x0B, 0x00};
    expected.insert(expected.end(), kSgrass.begin(), kSgrass.end());
    expected.insert(expected.end(), 3, 0);
    EXPECT_EQ(write_bitmap_name(WldBitmapName{0, {"sgrass.bmp"}}), expected);

    // The hand-made file holds the same 13 bytes (len + name), and they parse to the name.
    const HandMade& h = hand_made(kOld);
    const auto at = static_cast<std::ptrdiff_t>(h.at("bm1.length"));
    EXPECT_EQ(Bytes(h.file.begin() + at, h.file.begin() + at + 13), Bytes(expected.begin() + 8, expected.begin() + 21));
    const WldFile wld = parse_wld(h.file, "hand.wld");
    const WldBitmapName bitmap = parse_bitmap_name(wld, 1);
    EXPECT_EQ(bitmap.name_ref, h.refs.at("SGRASS_BM"));
    EXPECT_EQ(bitmap.files, (std::vector<std::string>{"sgrass.bmp"}));
}

// ---------------------------------------------------------------------------------------------
// The material chain, field by field

TEST(WldMaterialChain, HandMadeFragmentsParseAndWriteBack)
{
    for (const uint32_t version : kVersions) {
        SCOPED_TRACE(version);
        const HandMade& h = hand_made(version);
        const WldFile wld = parse_wld(h.file, "hand.wld");
        ASSERT_EQ(wld.fragments.size(), 13u);
        for (uint32_t n = 1; n <= 13; ++n) {
            EXPECT_EQ(wld.fragment(n).type, h.types[n - 1]);
            EXPECT_EQ(fragment_name(wld, wld.fragment(n)), kNames[n - 1]);
        }

        const WldBitmapName bm1 = parse_bitmap_name(wld, 1);
        EXPECT_EQ(bm1, (WldBitmapName{h.refs.at("SGRASS_BM"), {"sgrass.bmp"}}));
        EXPECT_EQ(write_bitmap_name(bm1), body_of(h, 1));
        const WldBitmapName bm2 = parse_bitmap_name(wld, 2);
        EXPECT_EQ(bm2, (WldBitmapName{h.refs.at("WATER_BM"), {"water1.bmp", "WATER2.BMP"}}));
        EXPECT_EQ(write_bitmap_name(bm2), body_of(h, 2));

        const WldSpriteDef def3 = parse_sprite_def(wld, 3);
        EXPECT_EQ(def3.name_ref, h.refs.at("SGRASS_SPRITEDEF"));
        EXPECT_EQ(def3.flags, 0x10u);
        EXPECT_EQ(def3.current_frame, 0u);
        EXPECT_EQ(def3.sleep, 0u);
        EXPECT_EQ(def3.frames, (std::vector<int32_t>{1}));
        EXPECT_EQ(write_sprite_def(def3), body_of(h, 3));
        const WldSpriteDef def4 = parse_sprite_def(wld, 4);
        EXPECT_EQ(def4, (WldSpriteDef{h.refs.at("WATER_SPRITEDEF"), 0x38, 1, 250, {2, 1}}));
        EXPECT_EQ(write_sprite_def(def4), body_of(h, 4));

        const WldSprite s5 = parse_sprite(wld, 5);
        EXPECT_EQ(s5, (WldSprite{h.refs.at("SGRASS_SPRITE"), 3, 0x50}));
        EXPECT_EQ(write_sprite(s5), body_of(h, 5));
        const WldSprite s6 = parse_sprite(wld, 6);
        EXPECT_EQ(s6, (WldSprite{h.refs.at("WATER_SPRITE"), 4, 0x50}));
        EXPECT_EQ(write_sprite(s6), body_of(h, 6));

        const WldMaterial m7 = parse_material(wld, 7);
        EXPECT_EQ(m7.name_ref, h.refs.at("SGRASS_MDF"));
        EXPECT_EQ(m7.flags, kWldMaterialPair);
        EXPECT_EQ(m7.render_method, 0x80000001u);
        EXPECT_EQ(m7.rgb_pen, 0x004E4E4Eu);
        EXPECT_EQ(m7.brightness, 0.75f);
        EXPECT_EQ(m7.scaled_ambient, 0.5f);
        EXPECT_EQ(m7.sprite_ref, 5);
        EXPECT_EQ(m7.pair_value, 0u);
        EXPECT_EQ(m7.pair_factor, 0.0f);
        EXPECT_EQ(write_material(m7), body_of(h, 7));
        const WldMaterial m8 = parse_material(wld, 8);
        EXPECT_EQ(m8, (WldMaterial{h.refs.at("INVIS_MDF"), 0x2, 0, 0, 0.0f, 0.0f, 0, 7, 1.5f}));
        EXPECT_EQ(write_material(m8), body_of(h, 8));
        const WldMaterial m9 = parse_material(wld, 9);
        EXPECT_EQ(m9, (WldMaterial{h.refs.at("WATER_MDF"), 0x3, 0x80000005u, 0x00FFFFFF, 1.0f, 0.25f, 6, 0, 0.0f}));
        EXPECT_EQ(m9.flags & kWldMaterialTwoSided, kWldMaterialTwoSided);
        EXPECT_EQ(write_material(m9), body_of(h, 9));
        const WldMaterial m10 = parse_material(wld, 10); // no pair: the body ends at sprite_ref
        EXPECT_EQ(m10, (WldMaterial{h.refs.at("PACKED_MDF"), 0x1, 0x193, 0x00808080, 0.5f, 0.0f, 5, 0, 0.0f}));
        EXPECT_EQ(body_of(h, 10).size(), 28u);
        EXPECT_EQ(write_material(m10), body_of(h, 10));

        const WldMaterialPalette mp = parse_material_palette(wld, 11);
        EXPECT_EQ(mp, (WldMaterialPalette{h.refs.at("ZONE_MP"), 0, {7, 8, 9, 10}}));
        EXPECT_EQ(write_material_palette(mp), body_of(h, 11));
    }
}

TEST(WldMaterialChain, ResolvesTexturesAndVisibility)
{
    const HandMade& h = hand_made(kOld);
    const WldFile wld = parse_wld(h.file, "hand.wld");
    EXPECT_EQ(material_fragment_of(wld, 11, 0), 7u);
    EXPECT_EQ(material_fragment_of(wld, 11, 3), 10u);
    EXPECT_EQ(texture_file_of(wld, 11, 0), "sgrass.bmp");
    EXPECT_EQ(texture_file_of(wld, 11, 1), "");           // sprite_ref 0
    EXPECT_EQ(texture_file_of(wld, 11, 2), "water1.bmp"); // first frame (0x03 #2), its first name
    EXPECT_EQ(texture_file_of(wld, 11, 3), "sgrass.bmp");
    EXPECT_TRUE(material_is_visible(wld, 11, 0));
    EXPECT_FALSE(material_is_visible(wld, 11, 1)); // render_method 0 and sprite_ref 0
    EXPECT_TRUE(material_is_visible(wld, 11, 2));  // drawn, though transparent
    EXPECT_TRUE(material_is_visible(wld, 11, 3));
    EXPECT_TRUE(decode_render_method(parse_material(wld, 9).render_method).transparent);

    EXPECT_THROW(texture_file_of(wld, 11, 4), std::out_of_range);
    EXPECT_THROW(material_is_visible(wld, 11, 4), std::out_of_range);
    EXPECT_THROW(texture_file_of(wld, 14, 0), std::out_of_range);
    try {
        (void)texture_file_of(wld, 12, 0);
        ADD_FAILURE() << "no FileError";
    } catch (const FileError& e) {
        EXPECT_EQ(e.offset(), h.field(12, 0) - 4);
        EXPECT_NE(e.reason().find("fragment 12 (0x36 mesh): expected a 0x31 material palette fragment"),
                  std::string::npos)
            << e.reason();
    }
}

TEST(WldMaterialChain, ByNameReferencesResolveLazily)
{
    // Built with the writers: every link of this chain is a reference by name.
    WldStringTable s;
    const int32_t bm = s.add("BM"), def = s.add("DEF"), spr = s.add("SPR"), mdf = s.add("MDF"), mdf2 = s.add("MDF2");
    const int32_t nobody = s.add("NOBODY"), mp = s.add("MP"), mesh_name = s.add("MESH");
    WldMesh mesh;
    mesh.name_ref = mesh_name;
    mesh.material_palette_ref = mp;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.faces = {WldMeshFace{0, {0, 1, 2}}};
    mesh.face_groups = {{1, 3}};
    const std::vector<WldFragmentBytes> fragments = {
        {kWldBitmapName, write_bitmap_name({bm, {"grass.dds"}})},
        {kWldSpriteDef, write_sprite_def({def, 0x10, 0, 0, {bm}})},
        {kWldSprite, write_sprite({spr, def, 0x50})},
        {kWldMaterial, write_material({mdf, 0x2, 0x80000001u, 0, 0, 0, spr, 0, 0})},
        {kWldMaterial, write_material({mdf2, 0x2, 0x80000001u, 0, 0, 0, nobody, 0, 0})},
        {kWldMaterialPalette, write_material_palette({mp, 0, {mdf, mdf2, 0, bm}})},
        {kWldMesh, write_mesh(mesh)},
    };
    const Bytes file = write_wld(kOld, s.data(), fragments);
    const WldFile wld = parse_wld(file, "byname.wld");
    EXPECT_EQ(texture_file_of(wld, 6, 0), "grass.dds");
    EXPECT_EQ(texture_file_of(wld, 6, 1), ""); // a name no fragment carries: the chain ends
    EXPECT_TRUE(material_is_visible(wld, 6, 1)); // drawn, sprite_ref not 0 (WQ/ZU rule)
    EXPECT_EQ(material_fragment_of(wld, 6, 2), 0u);
    EXPECT_EQ(texture_file_of(wld, 6, 2), "");
    EXPECT_FALSE(material_is_visible(wld, 6, 2));
    try { // entry 3 names the 0x03 by name: not a material
        (void)texture_file_of(wld, 6, 3);
        ADD_FAILURE() << "no FileError";
    } catch (const FileError& e) {
        EXPECT_NE(e.reason().find("fragment 1 (0x03 bitmap name): expected a 0x30 material fragment"),
                  std::string::npos)
            << e.reason();
    }
    // The mesh's palette by name is found and its indices checked (material 3 of 4).
    EXPECT_EQ(parse_mesh(wld, 7).face_groups, (std::vector<WldMeshGroup>{{1, 3}}));
}

TEST(WldMaterialRenderMethod, DecodesTheSpecTable)
{
    struct Case {
        uint32_t raw;
        WldMaterialType type;
        bool drawn, transparent;
        uint8_t opacity;
    };
    using T = WldMaterialType;
    const Case cases[] = {
        {0x80000000u, T::Boundary, false, false, 100},
        {0x80000001u, T::Diffuse, true, false, 100},
        {0x80000002u, T::Diffuse, true, false, 100},
        {0x80000012u, T::Diffuse, true, false, 100},
        {0x80000014u, T::Diffuse, true, false, 100},
        {0x80000015u, T::Diffuse, true, false, 100},
        {0x80000019u, T::Diffuse, true, false, 100},
        {0x80000031u, T::Diffuse, true, false, 100},
        {0x80000553u, T::Diffuse, true, false, 100},
        {0x80000005u, T::Transparent, true, true, 50},
        {0x80000009u, T::Transparent, true, true, 25},
        {0x8000000Au, T::Transparent, true, true, 75},
        {0x80000007u, T::TransparentMaskedPassable, true, true, 100},
        {0x80000013u, T::TransparentMasked, true, true, 100},
        {0x8000000Bu, T::TransparentAdditiveUnlit, true, true, 100},
        {0x80000017u, T::TransparentAdditive, true, true, 100},
        {0x8000000Du, T::SkyDome, true, false, 100},
        {0x8000000Fu, T::SkyDome, true, false, 100},
        {0x80000010u, T::SkyDome, true, false, 100},
        {0x80000003u, T::Invisible, false, false, 100},
        {0x8000004Bu, T::Invisible, false, false, 100},
        {0x80000053u, T::Invisible, false, false, 100},
        {0x80000006u, T::Unknown, true, false, 100},
        {0x8000001Au, T::Unknown, true, false, 100},
        {0x00000000u, T::Packed, false, false, 100}, // WQ and ZU: invisible
        {0x00000193u, T::Packed, true, false, 100},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.raw);
        const WldRenderMethod rm = decode_render_method(c.raw);
        EXPECT_EQ(rm.raw, c.raw);
        EXPECT_EQ(rm.user_defined, (c.raw & 0x80000000u) != 0);
        EXPECT_EQ(rm.material_type, rm.user_defined ? c.raw & 0x7FFFFFFFu : 0u);
        EXPECT_EQ(rm.type, c.type);
        EXPECT_EQ(rm.drawn, c.drawn);
        EXPECT_EQ(rm.transparent, c.transparent);
        EXPECT_EQ(rm.opacity_percent, c.opacity);
    }
    // Packed fields: draw style bits 0-1, lighting 2-4, shading 5-6, texture style 7-10.
    const WldRenderMethod packed = decode_render_method(0x193);
    EXPECT_EQ(packed.draw_style, 3);
    EXPECT_EQ(packed.lighting, 4);
    EXPECT_EQ(packed.shading, 0);
    EXPECT_EQ(packed.texture_style, 3);
    const WldRenderMethod all = decode_render_method(0x7FF);
    EXPECT_EQ(all.draw_style, 3);
    EXPECT_EQ(all.lighting, 7);
    EXPECT_EQ(all.shading, 3);
    EXPECT_EQ(all.texture_style, 15);
}

// ---------------------------------------------------------------------------------------------
// The meshes, field by field, in both uv forms

TEST(WldMesh, HandMadeZoneMesh)
{
    for (const uint32_t version : kVersions) {
        SCOPED_TRACE(version);
        const HandMade& h = hand_made(version);
        // The builder's offsets are the spec's (§6.1): counts at 0x4C, scale at 0x5E, vertices at 0x60.
        ASSERT_EQ(h.at("A.counts"), h.field(12, 0x4C));
        ASSERT_EQ(h.at("A.scale"), h.field(12, 0x5E));
        ASSERT_EQ(h.at("A.vertices"), h.field(12, kWldMeshHeaderSize));
        EXPECT_EQ(body_of(h, 12).size(), version == kOld ? 204u : 220u); // 4 B vs 8 B per uv

        const WldFile wld = parse_wld(h.file, "hand.wld");
        const WldMesh m = parse_mesh(wld, 12);
        EXPECT_EQ(m.name_ref, h.refs.at("R1_DMSPRITEDEF"));
        EXPECT_EQ(m.flags, kWldMeshZoneFlags);
        EXPECT_EQ(m.material_palette_ref, 11);
        EXPECT_EQ(m.animation_ref, 0);
        EXPECT_EQ(m.fragment3, 0);
        EXPECT_EQ(m.fragment4, 1);
        EXPECT_EQ(m.center, glm::vec3(100, 200, -50));
        EXPECT_EQ(m.params2, (std::array<uint32_t, 3>{0, 0, 0}));
        EXPECT_EQ(m.max_distance, 150.0f);
        EXPECT_EQ(m.min, glm::vec3(1, 2, 3)); // as stored
        EXPECT_EQ(m.max, glm::vec3(4, 5, 6));
        EXPECT_EQ(m.scale, 8);
        EXPECT_EQ(m.uv_form, version == kOld ? WldUvForm::I16 : WldUvForm::F32);
        // center + raw / 2^8
        EXPECT_EQ(m.positions, (std::vector<glm::vec3>{{100, 200, -50},
                                                        {200, 200, -49.5f},
                                                        {200, 150, -51},
                                                        {99.75f, 327.99609375f, -49.99609375f}}));
        EXPECT_EQ(m.uvs, (std::vector<glm::vec2>{{0, 0}, {1, 0}, {1, -2.25f}, {0.5f, 127.99609375f}}));
        EXPECT_EQ(m.normals, (std::vector<glm::vec3>{{0, 0, 1},
                                                      {0, 0, -1},
                                                      {1, 0, 0},
                                                      {-128.0f / 127.0f, 64.0f / 127.0f, 1.0f / 127.0f}}));
        EXPECT_EQ(m.colors, (std::vector<uint32_t>{0xFF00FF00u, 0x11223344u, 0, 0xFFFFFFFFu}));
        ASSERT_EQ(m.faces.size(), 3u);
        EXPECT_EQ(m.faces[0], (WldMeshFace{0, {0, 1, 2}})); // winding as stored
        EXPECT_EQ(m.faces[1], (WldMeshFace{0, {0, 2, 3}}));
        EXPECT_EQ(m.faces[2], (WldMeshFace{0x10, {1, 2, 3}}));
        EXPECT_FALSE(m.faces[0].passable());
        EXPECT_FALSE(m.faces[1].passable());
        EXPECT_TRUE(m.faces[2].passable());
        EXPECT_TRUE(m.skin_groups.empty());
        EXPECT_EQ(m.face_groups, (std::vector<WldMeshGroup>{{1, 0}, {2, 1}}));
        EXPECT_EQ(m.vertex_groups, (std::vector<WldMeshGroup>{{3, 0}, {1, 1}}));
        EXPECT_TRUE(m.mesh_ops.empty());

        // Per face: material, texture, visibility (faces 1 and 2 use the invisible material).
        EXPECT_EQ(face_materials(m), (std::vector<uint16_t>{0, 1, 1}));
        const uint32_t palette = resolve_fragment_ref(wld, m.material_palette_ref);
        EXPECT_EQ(texture_file_of(wld, palette, 0), "sgrass.bmp");
        EXPECT_TRUE(material_is_visible(wld, palette, 0));
        EXPECT_EQ(texture_file_of(wld, palette, 1), "");
        EXPECT_FALSE(material_is_visible(wld, palette, 1));

        const WldMeshBounds bounds = mesh_bounds(m);
        EXPECT_EQ(bounds.min, glm::vec3(99.75f, 150, -51));
        EXPECT_EQ(bounds.max, glm::vec3(200, 327.99609375f, -49.5f));
        EXPECT_NEAR(bounds.max_distance, std::sqrt(0.25 * 0.25 + 127.99609375 * 127.99609375 + 0.00390625 * 0.00390625),
                    1e-4);

        // The largest scale that fits is the stored one, so the body comes back byte for byte.
        EXPECT_EQ(mesh_scale_for(m), 8);
        EXPECT_EQ(write_mesh(m), body_of(h, 12));
    }
}

TEST(WldMesh, HandMadeObjectMesh)
{
    for (const uint32_t version : kVersions) {
        SCOPED_TRACE(version);
        const HandMade& h = hand_made(version);
        ASSERT_EQ(h.at("B.counts"), h.field(13, 0x4C));
        EXPECT_EQ(h.bodies[12].size(), version == kOld ? 173u : 185u); // written with 3 bytes of padding
        const WldFile wld = parse_wld(h.file, "hand.wld");
        const WldMesh m = parse_mesh(wld, 13);
        EXPECT_EQ(m.name_ref, h.refs.at("OBJ_DMSPRITEDEF"));
        EXPECT_EQ(m.flags, kWldMeshObjectFlags);
        EXPECT_EQ(m.material_palette_ref, 11);
        EXPECT_EQ(m.fragment4, 0);
        EXPECT_EQ(m.center, glm::vec3(-1000.5f, 0.25f, 3));
        EXPECT_EQ(m.max_distance, 20000.0f);
        EXPECT_EQ(m.min, glm::vec3(0.0f));
        EXPECT_EQ(m.max, glm::vec3(0.0f));
        EXPECT_EQ(m.scale, 0);
        EXPECT_EQ(m.positions,
                  (std::vector<glm::vec3>{{18999.5f, -0.75f, 3}, {-21000.5f, 5.25f, 10}, {-1000.5f, 0.25f, 0}}));
        EXPECT_EQ(m.uvs, (std::vector<glm::vec2>{{0.25f, -0.5f}, {2, 3}, {-128, 0}}));
        ASSERT_EQ(m.normals.size(), 5u); // more normals than vertices (§6.1, ssratemple)
        EXPECT_EQ(m.normals[0], glm::vec3(1, 2, 3) / 127.0f);
        EXPECT_EQ(m.normals[1], glm::vec3(-1, -2, -3) / 127.0f);
        EXPECT_EQ(m.normals[2], glm::vec3(0.0f));
        EXPECT_EQ(m.normals[3], glm::vec3(1.0f));
        EXPECT_EQ(m.normals[4], glm::vec3(-1, 0, 0));
        EXPECT_TRUE(m.colors.empty());
        EXPECT_EQ(m.faces, (std::vector<WldMeshFace>{{0x11, {2, 1, 0}}}));
        EXPECT_TRUE(m.faces[0].passable()); // bit 0x10, whatever else is set (LQ's test)
        EXPECT_EQ(m.skin_groups, (std::vector<WldSkinGroup>{{2, 0}, {1, 1}}));
        EXPECT_EQ(m.face_groups, (std::vector<WldMeshGroup>{{1, 2}}));
        EXPECT_TRUE(m.vertex_groups.empty());
        EXPECT_EQ(m.mesh_ops, (std::vector<WldMeshOp>{{{1, 0, 2, 0}, 5, 1}, {{0x00, 0x00, 0x80, 0x3F}, 0, 4}}));
        EXPECT_EQ(texture_file_of(wld, 11, face_materials(m)[0]), "water1.bmp");

        EXPECT_EQ(mesh_scale_for(m), 0); // 20000 units from the center: 40000 would not fit at scale 1
        EXPECT_EQ(write_mesh(m), body_of(h, 13));
    }
}

// ---------------------------------------------------------------------------------------------
// Writers: write -> parse round trips

WldMesh sample_mesh(WldUvForm form, int32_t name_ref, int32_t palette_ref)
{
    WldMesh m;
    m.name_ref = name_ref;
    m.material_palette_ref = palette_ref;
    m.center = {-512.0f, 64.0f, 8.5f};
    m.uv_form = form;
    m.positions = {{-512.0f, 64.0f, 8.5f}, {-600.25f, 64.125f, 9.0f}, {-500.0f, 100.0f, 8.5f}, {-511.0f, 90.0f, 0.0f}};
    m.uvs = {{0, 0}, {1, 0}, {0, 1}, {-3.5f, 0.00390625f}};
    m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, -1}};
    m.colors = {0x80808080u, 0x80808080u, 0x80808080u, 0x80808080u};
    m.faces = {{0, {0, 1, 2}}, {kWldFacePassable, {0, 2, 3}}, {0, {1, 2, 3}}};
    m.face_groups = {{2, 0}, {0, 1}, {1, 1}}; // an empty group is legal
    m.vertex_groups = {{4, 0}};
    m.min = {-600.25f, 64.0f, 0.0f};
    m.max = {-500.0f, 100.0f, 9.0f};
    m.max_distance = 88.5f;
    m.scale = mesh_scale_for(m); // what the writer will store
    return m;
}

TEST(WldMesh, WrittenFileParsesBack)
{
    for (const uint32_t version : kVersions) {
        SCOPED_TRACE(version);
        WldStringTable s;
        const WldBitmapName bm{s.add("BM"), {"a.bmp", "b.bmp"}};
        const WldSpriteDef def{s.add("DEF"), 0x18 | kWldSpriteDefCurrentFrame, 1, 100, {1, 1}};
        const WldSprite spr{s.add("SPR"), 2, 0x50};
        const WldMaterial opaque{s.add("OPAQUE"), 0x2, 0x80000001u, 0x004E4E4E, 1.0f, 0.0f, 3, 0, 0.0f};
        const WldMaterial invisible{s.add("INVIS"), 0x0, 0, 0, 0.0f, 0.0f, 0, 0, 0.0f};
        const WldMaterialPalette palette{s.add("MP"), 0, {4, 5}};
        const WldMesh mesh = sample_mesh(wld_uv_form(version), s.add("MESH"), 6);
        EXPECT_EQ(mesh.scale, 8); // 88.25 units from the center: 88.25 * 2^8 = 22592, * 2^9 = 45184
        const std::vector<WldFragmentBytes> fragments = {
            {kWldBitmapName, write_bitmap_name(bm)}, {kWldSpriteDef, write_sprite_def(def)},
            {kWldSprite, write_sprite(spr)},         {kWldMaterial, write_material(opaque)},
            {kWldMaterial, write_material(invisible)}, {kWldMaterialPalette, write_material_palette(palette)},
            {kWldMesh, write_mesh(mesh)},
        };
        const Bytes file = write_wld(version, s.data(), fragments);
        const WldFile wld = parse_wld(file, "written.wld");
        EXPECT_EQ(parse_bitmap_name(wld, 1), bm);
        EXPECT_EQ(parse_sprite_def(wld, 2), def);
        EXPECT_EQ(parse_sprite(wld, 3), spr);
        EXPECT_EQ(parse_material(wld, 4), opaque);
        EXPECT_EQ(parse_material(wld, 5), invisible);
        EXPECT_EQ(parse_material_palette(wld, 6), palette);
        EXPECT_EQ(parse_mesh(wld, 7), mesh);
        EXPECT_EQ(face_materials(parse_mesh(wld, 7)), (std::vector<uint16_t>{0, 0, 1}));
        EXPECT_EQ(texture_file_of(wld, 6, 0), "a.bmp");
        EXPECT_TRUE(material_is_visible(wld, 6, 0));
        EXPECT_FALSE(material_is_visible(wld, 6, 1));
        // write(parse(write(x))) == write(x)
        EXPECT_EQ(write_mesh(parse_mesh(wld, 7)), fragments[6].body);
    }
}

TEST(WldMesh, ScaleChoiceAndPositionPrecision)
{
    WldMesh m;
    EXPECT_EQ(mesh_scale_for(m), kWldMeshMaxScale); // no vertices
    m.center = {10, 20, 30};
    m.positions = {{10.5f, 20, 30}};
    EXPECT_EQ(mesh_scale_for(m), 15); // 0.5 * 2^15 = 16384
    m.positions = {{10, 19, 30}};
    EXPECT_EQ(mesh_scale_for(m), 14); // 1 * 2^15 = 32768 does not fit
    m.positions = {{10, 20, 30 + 32767}};
    EXPECT_EQ(mesh_scale_for(m), 0);
    m.positions = {{10, 20, 30 - 32767.4f}};
    EXPECT_EQ(mesh_scale_for(m), 0); // rounds to 32767
    m.positions = {{10, 20, 30 + 32768}};
    EXPECT_THROW(mesh_scale_for(m), std::invalid_argument);
    EXPECT_THROW(write_mesh(m), std::invalid_argument);
    m.positions = {{NAN, 20, 30}};
    EXPECT_THROW(mesh_scale_for(m), std::invalid_argument);
    m.positions = {};
    m.center = {INFINITY, 0, 0};
    EXPECT_THROW(write_mesh(m), std::invalid_argument);

    // Arbitrary positions come back within half a step of the chosen scale (plus float rounding).
    std::mt19937 rng(36);
    for (const float extent : {0.3f, 7.0f, 100.0f, 3000.0f, 32000.0f}) {
        SCOPED_TRACE(extent);
        std::uniform_real_distribution<float> offset(-extent, extent);
        WldMesh mesh;
        mesh.center = {1234.5f, -77.25f, 10.0f};
        for (int i = 0; i < 200; ++i)
            mesh.positions.push_back(mesh.center + glm::vec3(offset(rng), offset(rng), offset(rng)));
        const uint16_t scale = mesh_scale_for(mesh);
        const Bytes file = write_wld(kOld, {}, std::vector<WldFragmentBytes>{{kWldMesh, write_mesh(mesh)}});
        const WldMesh back = parse_mesh(parse_wld(file, "precision.wld"), 1);
        EXPECT_EQ(back.scale, scale);
        ASSERT_EQ(back.positions.size(), mesh.positions.size());
        for (size_t i = 0; i < mesh.positions.size(); ++i)
            for (int k = 0; k < 3; ++k) {
                const double given = mesh.positions[i][k];
                EXPECT_LE(std::abs(double{back.positions[i][k]} - given),
                          std::ldexp(1.0, -(scale + 1)) + std::abs(given) * 0x1p-23)
                    << "scale " << scale;
            }
    }
}

TEST(WldMesh, WritersRefuseWhatTheFileCannotHold)
{
    const WldMesh good = sample_mesh(WldUvForm::I16, 0, 0);
    EXPECT_NO_THROW(write_mesh(good));
    WldMesh m = good;
    m.faces[1].vertices[2] = 4; // 4 vertices
    EXPECT_THROW(write_mesh(m), std::invalid_argument);
    m = good;
    m.face_groups.back().count = 2; // covers 4 of 3 faces
    EXPECT_THROW(write_mesh(m), std::invalid_argument);
    m = good;
    m.uvs[0] = {128.0f, 0.0f}; // 32768 does not fit an i16...
    EXPECT_THROW(write_mesh(m), std::invalid_argument);
    m.uv_form = WldUvForm::F32; // ... but a float does
    EXPECT_NO_THROW(write_mesh(m));
    m = good;
    m.uvs[0] = {NAN, 0.0f};
    EXPECT_THROW(write_mesh(m), std::invalid_argument);
    m = good;
    m.normals[0] = {0, 0, 1.01f}; // 128.27
    EXPECT_THROW(write_mesh(m), std::invalid_argument);
    m.normals[0] = {0, 0, -128.0f / 127.0f}; // -128 fits
    EXPECT_NO_THROW(write_mesh(m));
    m = good;
    m.positions.assign(65536, m.center);
    EXPECT_THROW(write_mesh(m), std::invalid_argument);
    m = good;
    m.mesh_ops.resize(65536);
    EXPECT_THROW(write_mesh(m), std::invalid_argument);

    EXPECT_THROW(write_bitmap_name(WldBitmapName{0, {}}), std::invalid_argument);
    EXPECT_THROW(write_bitmap_name(WldBitmapName{0, {std::string("a\0b", 3)}}), std::invalid_argument);
    EXPECT_THROW(write_bitmap_name(WldBitmapName{0, {std::string(65535, 'a')}}), std::invalid_argument);
    EXPECT_NO_THROW(write_bitmap_name(WldBitmapName{0, {std::string(65534, 'a')}}));
}

// ---------------------------------------------------------------------------------------------
// Bad input: FileError naming the file, the absolute offset, the fragment and the problem

TEST(WldMeshBadInput, CountsThatDoNotFit)
{
    const HandMade& h = hand_made(kOld);
    const auto mesh12 = parse_fragment<parse_mesh>(12);
    const auto mesh13 = parse_fragment<parse_mesh>(13);
    Bytes bad = h.file;
    put_u16(bad, h.field(12, 0x4C), 0xFFFF);
    expect_error(bad, mesh12, h.field(12, 0x4C),
                 {"fragment 12 (0x36 mesh)", "vertex_count 65535 does not fit in the fragment",
                  "at least 6 per element"});
    bad = h.file;
    put_u16(bad, h.field(12, 0x4E), 0xFFFF);
    expect_error(bad, mesh12, h.field(12, 0x4E), {"uv_count 65535 does not fit", "at least 4 per element"});
    bad = hand_made(kNew).file; // 8 bytes per uv in the new form
    put_u16(bad, hand_made(kNew).field(12, 0x4E), 14);
    expect_error(bad, mesh12, hand_made(kNew).field(12, 0x4E), {"uv_count 14 does not fit", "at least 8 per"});
    bad = h.file;
    put_u16(bad, h.field(12, 0x54), 0xFFFF);
    expect_error(bad, mesh12, h.field(12, 0x54), {"face_count 65535 does not fit"});
    bad = h.file;
    put_u16(bad, h.field(13, 0x5C), 0xFFFF);
    expect_error(bad, mesh13, h.field(13, 0x5C), {"fragment 13 (0x36 mesh)", "meshop_count 65535 does not fit"});
    bad = h.file;
    put_u16(bad, h.field(13, 0x56), 400);
    expect_error(bad, mesh13, h.field(13, 0x56), {"skin_group_count 400 does not fit"});

    // A body cut short: the last fragment's size shrunk (the file is still whole).
    bad = h.file;
    put_u32(bad, h.field(13, 0) - 8, 0x60);
    expect_error(bad, mesh13, h.field(13, 0x4C), {"vertex_count 3 does not fit", "(0 bytes left"});
    put_u32(bad, h.field(13, 0) - 8, 0x40);
    expect_error(bad, mesh13, h.field(13, 0x40), {"max runs past the end of the fragment (4 bytes needed, 0 left)"});
}

TEST(WldMaterialBadInput, CountsThatOverflow)
{
    const HandMade& h = hand_made(kOld);
    Bytes bad = h.file;
    put_u32(bad, h.at("bm1.count"), 0xFFFFFFFFu); // names = count + 1 = 2^32: no wrap to 0
    expect_error(bad, parse_fragment<parse_bitmap_name>(1), h.at("bm1.count"),
                 {"fragment 1 (0x03 bitmap name)", "name count 4294967295 (4294967296 names) does not fit"});
    bad = h.file;
    put_u16(bad, h.at("bm1.length"), 0xFFFF);
    expect_error(bad, parse_fragment<parse_bitmap_name>(1), h.at("bm1.length") + 2,
                 {"name 0 runs past the end of the fragment (65535 bytes needed"});
    bad = h.file;
    put_u32(bad, h.at("def3.count"), 0x40000000u); // 4 * 2^30 = 2^32
    expect_error(bad, parse_fragment<parse_sprite_def>(3), h.at("def3.count"),
                 {"fragment 3 (0x04 sprite definition)", "frame_count 1073741824 does not fit"});
    bad = h.file;
    put_u32(bad, h.at("mp.count"), 0x40000000u);
    expect_error(bad, parse_fragment<parse_material_palette>(11), h.at("mp.count"),
                 {"fragment 11 (0x31 material palette)", "material count 1073741824 does not fit"});
    bad = h.file;
    put_u32(bad, h.at("mp.count"), 5);
    expect_error(bad, parse_fragment<parse_material_palette>(11), h.at("mp.count"),
                 {"material count 5 does not fit in the fragment (16 bytes left"});
    // 0x04 with the sleep flag but no room for it
    bad = h.file;
    put_u32(bad, h.at("def3.count") - 4, 0x38);
    expect_error(bad, parse_fragment<parse_sprite_def>(3), h.at("def3.count") + 8,
                 {"sleep runs past the end of the fragment"});
}

TEST(WldMeshBadInput, FacesAndMaterialGroups)
{
    const HandMade& h = hand_made(kOld);
    const auto mesh12 = parse_fragment<parse_mesh>(12);
    Bytes bad = h.file;
    put_u16(bad, h.at("A.face1.v2"), 4);
    expect_error(bad, mesh12, h.at("A.face1.v2"),
                 {"fragment 12 (0x36 mesh)", "face 1 vertex 2 is 4 but the mesh has 4 vertices"});
    try { // the whole message, as docs/formats-eq.md quotes it
        mesh12(bad);
    } catch (const FileError& e) {
        const uint64_t at = h.at("A.face1.v2");
        char where[64];
        std::snprintf(where, sizeof where, "offset %llu (0x%llx)", static_cast<unsigned long long>(at),
                      static_cast<unsigned long long>(at));
        EXPECT_EQ(std::string(e.what()), std::string("bad.wld: ") + where +
                                             ": fragment 12 (0x36 mesh): face 1 vertex 2 is 4 but the mesh has 4 vertices");
    }
    bad = h.file;
    put_u16(bad, h.at("A.group1.count"), 3);
    expect_error(bad, mesh12, h.field(12, 0x58), {"the face material groups cover 4 faces but face_count is 3"});
    bad = h.file;
    put_u16(bad, h.at("A.group0.count"), 0);
    expect_error(bad, mesh12, h.field(12, 0x58), {"cover 2 faces but face_count is 3"});
    bad = h.file;
    put_u16(bad, h.field(12, 0x58), 0); // no groups at all
    expect_error(bad, mesh12, h.field(12, 0x58), {"cover 0 faces but face_count is 3"});
    bad = h.file;
    put_u16(bad, h.at("A.group1.material"), 4);
    expect_error(bad, mesh12, h.at("A.group1.material"),
                 {"face material group 1 names material 4 but the palette (fragment 11) has 4 materials"});
    // Without a palette the indices cannot be checked: the mesh parses.
    put_u32(bad, h.at("A.palette"), 0);
    const WldMesh unchecked = parse_mesh(parse_wld(bad, "bad.wld"), 12);
    EXPECT_EQ(unchecked.face_groups[1].material, 4);
    EXPECT_EQ(unchecked.material_palette_ref, 0);

    bad = h.file;
    put_u16(bad, h.at("A.scale"), 0x8000);
    expect_error(bad, mesh12, h.at("A.scale"), {"scale 32768 is above 32767", "they disagree"});
    bad = h.file;
    put_f32(bad, h.at("A.center") + 4, NAN);
    expect_error(bad, mesh12, h.at("A.center"), {"center is not a finite number"});

    expect_error(h.file, parse_fragment<parse_mesh>(11), h.field(11, 0) - 4,
                 {"fragment 11 (0x31 material palette)", "expected a 0x36 mesh fragment"});
    expect_error(h.file, parse_fragment<parse_material>(12), h.field(12, 0) - 4,
                 {"fragment 12 (0x36 mesh)", "expected a 0x30 material fragment"});
}

TEST(WldMeshBadInput, ForwardAndOutOfRangeReferences)
{
    const HandMade& h = hand_made(kOld);
    const auto mesh12 = parse_fragment<parse_mesh>(12);
    Bytes bad = h.file;
    put_u32(bad, h.at("A.palette"), 12); // itself
    expect_error(bad, mesh12, h.at("A.palette"),
                 {"fragment 12 (0x36 mesh)", "material_palette_ref 12 is a forward reference"});
    put_u32(bad, h.at("A.palette"), 13);
    expect_error(bad, mesh12, h.at("A.palette"), {"material_palette_ref 13 is a forward reference"});
    put_u32(bad, h.at("A.palette"), 99);
    expect_error(bad, mesh12, h.at("A.palette"),
                 {"material_palette_ref 99 is out of range (the file has 13 fragments)"});
    put_u32(bad, h.at("A.palette"), 7);
    expect_error(bad, mesh12, h.at("A.palette"),
                 {"material_palette_ref 7 names fragment 7 (0x30 material), not a 0x31 material palette"});
    put_u32(bad, h.at("A.palette"), uint32_t(h.refs.at("SGRASS_MDF"))); // by name, the wrong type
    expect_error(bad, mesh12, h.at("A.palette"),
                 {"names fragment 7 (0x30 material), not a 0x31 material palette"});
    put_u32(bad, h.at("A.palette"), uint32_t(-5000));
    expect_error(bad, mesh12, h.at("A.palette"),
                 {"material_palette_ref -5000 names a string outside the string hash"});
    put_u32(bad, h.at("A.palette"), uint32_t(h.refs.at("ZONE_MP"))); // by name, right: parses
    EXPECT_EQ(parse_mesh(parse_wld(bad, "bad.wld"), 12).material_palette_ref, h.refs.at("ZONE_MP"));
    bad = h.file;
    put_u32(bad, h.at("A.animation"), 13);
    expect_error(bad, mesh12, h.at("A.animation"), {"animation_ref 13 is a forward reference"});

    bad = h.file;
    put_u32(bad, h.at("mp.entry1"), 11);
    expect_error(bad, parse_fragment<parse_material_palette>(11), h.at("mp.entry1"),
                 {"fragment 11 (0x31 material palette)", "material reference 1 11 is a forward reference"});
    put_u32(bad, h.at("mp.entry1"), 5);
    expect_error(bad, parse_fragment<parse_material_palette>(11), h.at("mp.entry1"),
                 {"material reference 1 5 names fragment 5 (0x05 sprite), not a 0x30 material"});
    // A broken palette is reported when a mesh needs it for its material indices.
    expect_error(bad, mesh12, h.at("mp.entry1"), {"fragment 11 (0x31 material palette)"});

    bad = h.file;
    put_u32(bad, h.at("mdf7.sprite"), 3);
    expect_error(bad, parse_fragment<parse_material>(7), h.at("mdf7.sprite"),
                 {"fragment 7 (0x30 material)",
                  "sprite_ref 3 names fragment 3 (0x04 sprite definition), not a 0x05 sprite"});
    put_u32(bad, h.at("mdf7.sprite"), 7);
    expect_error(bad, parse_fragment<parse_material>(7), h.at("mdf7.sprite"), {"sprite_ref 7 is a forward reference"});

    bad = h.file;
    put_u32(bad, h.at("sprite5.ref"), 1);
    expect_error(bad, parse_fragment<parse_sprite>(5), h.at("sprite5.ref"),
                 {"fragment 5 (0x05 sprite)", "sprite_def_ref 1 names fragment 1 (0x03 bitmap name), not a 0x04"});
    put_u32(bad, h.at("sprite5.ref"), 0x7FFFFFFF);
    expect_error(bad, parse_fragment<parse_sprite>(5), h.at("sprite5.ref"),
                 {"sprite_def_ref 2147483647 is out of range"});

    bad = h.file;
    put_u32(bad, h.at("def3.frame0"), 3);
    expect_error(bad, parse_fragment<parse_sprite_def>(3), h.at("def3.frame0"),
                 {"fragment 3 (0x04 sprite definition)", "frame reference 0 3 is a forward reference"});
    put_u32(bad, h.at("def3.frame0"), 0);
    EXPECT_EQ(parse_sprite_def(parse_wld(bad, "bad.wld"), 3).frames, (std::vector<int32_t>{0}));
    EXPECT_EQ(texture_file_of(parse_wld(bad, "bad.wld"), 11, 0), ""); // the chain ends at frame 0
}

// ---------------------------------------------------------------------------------------------
// Sweep: every truncation and 300 random changes parse or throw FileError, nothing else.

// Parses the container, every fragment of the chain and every mesh, and resolves every palette
// entry; FileError escapes to the caller.
void parse_everything(const Bytes& bytes)
{
    const WldFile wld = parse_wld(bytes, "sweep.wld");
    for (uint32_t n = 1; n <= wld.fragments.size(); ++n) {
        switch (wld.fragment(n).type) {
        case kWldBitmapName: (void)parse_bitmap_name(wld, n); break;
        case kWldSpriteDef: (void)parse_sprite_def(wld, n); break;
        case kWldSprite: (void)parse_sprite(wld, n); break;
        case kWldMaterial: (void)decode_render_method(parse_material(wld, n).render_method); break;
        case kWldMaterialPalette: {
            const auto count = uint32_t(parse_material_palette(wld, n).materials.size());
            for (uint32_t i = 0; i < count; ++i) {
                (void)texture_file_of(wld, n, i);
                (void)material_is_visible(wld, n, i);
            }
            break;
        }
        case kWldMesh: {
            const WldMesh mesh = parse_mesh(wld, n);
            (void)face_materials(mesh);
            (void)mesh_bounds(mesh);
            break;
        }
        default: break;
        }
    }
}

TEST(WldMeshSweep, EveryTruncationParsesOrThrowsFileError)
{
    for (const uint32_t version : kVersions) {
        SCOPED_TRACE(version);
        const Bytes& good = hand_made(version).file;
        ASSERT_TRUE(parses(good, parse_everything));
        // Only cuts inside the optional trailer keep every fragment.
        EXPECT_EQ(prefixes_that_parse(good, parse_everything), 4u);
    }
}

TEST(WldMeshSweep, RandomByteChangesParseOrThrowFileError)
{
    for (const uint32_t version : kVersions) {
        SCOPED_TRACE(version);
        // Many changes hit a count, a reference, a size or a face index.
        EXPECT_GT(random_changes_that_fail(hand_made(version).file, version, parse_everything), 30u);
    }
}

} // namespace
} // namespace pvs::eq
