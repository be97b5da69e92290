// EverQuest WLD container and visibility fragments (wld/eq/wld_file.h, wld/eq/wld_string_hash.h)
// against ../shared/formats/eq-s3d-wld.md: the §8.3 string vectors, the §3.4 tree and the §4.7
// region byte for byte (parsed and written), a hand-assembled WLD built here from the spec's
// tables (§2.1, §2.3, §3.1, §4.1, §4.3, §5.1) with every field checked, bad input that must
// throw FileError naming the fragment and the problem, and a truncation / random-change sweep
// (run under ASan + UBSan by tests/run-all.sh).
#include "tests/wld/wld_test_bytes.h"
#include "visibility/bit_row.h"
#include "visibility/file_error.h"
#include "visibility/zone.h"
#include "wld/eq/wld_file.h"
#include "wld/eq/wld_string_hash.h"

#include <gtest/gtest.h>

#include <map>

namespace pvs::eq {
namespace {

using namespace wld_test;

std::vector<uint32_t> set_bits(std::span<const uint64_t> row)
{
    std::vector<uint32_t> out;
    bits::for_each_set(row, [&](size_t i) { out.push_back(uint32_t(i)); });
    return out;
}

// ---------------------------------------------------------------------------------------------
// §2.2 / §8.3 string hash

TEST(WldStringHash, FooBarKnownAnswer)
{
    const std::string decoded("\0FOO\0BAR\0", 9);
    const Bytes expected = {0x95, 0x7C, 0x8A, 0x65, 0x95, 0x38, 0xD4, 0x38, 0x95, 0x00, 0x00, 0x00};
    EXPECT_EQ(encode_string_hash(std::span<const char>(decoded.data(), decoded.size())), expected);

    const std::vector<char> back = decode_string_hash(expected);
    EXPECT_EQ(std::string(back.begin(), back.end()), decoded); // the padding is dropped
    EXPECT_EQ(wld_string_at(back, -1), "FOO");
    EXPECT_EQ(wld_string_at(back, -5), "BAR");
    EXPECT_EQ(wld_string_at(back, -2), "OO");
    EXPECT_EQ(wld_string_at(back, 0), "");
    EXPECT_EQ(wld_string_at(back, 7), ""); // positive: "no name"
    EXPECT_EQ(wld_string_at(back, -9), std::nullopt);
    EXPECT_EQ(wld_string_at(back, std::numeric_limits<int32_t>::min()), std::nullopt);

    WldStringTable table;
    EXPECT_EQ(table.add("FOO"), -1);
    EXPECT_EQ(table.add("BAR"), -5);
    EXPECT_EQ(table.add("FOO"), -1);
    EXPECT_EQ(table.add(""), 0);
    EXPECT_EQ(std::string(table.data().begin(), table.data().end()), decoded);
    EXPECT_THROW(table.add(std::string("A\0B", 3)), std::invalid_argument);
}

TEST(WldStringHash, FragmentStringKnownAnswers)
{
    const Bytes sgrass = {0xE6, 0x5D, 0xB7, 0x4B, 0xE6, 0x09, 0xBB, 0x08, 0xF8, 0x4A, 0xC5};
    EXPECT_EQ(encode_wld_string("sgrass.bmp"), sgrass);
    EXPECT_EQ(decode_wld_string(sgrass), "sgrass.bmp");

    const Bytes wt_zone = {0xC2, 0x6E, 0x9A, 0x70, 0xDA, 0x34, 0xD0, 0x6A};
    EXPECT_EQ(encode_wld_string("WT_ZONE"), wt_zone);
    EXPECT_EQ(decode_wld_string(wt_zone), "WT_ZONE");
    // QL writes the string without its NUL: the text is the same.
    EXPECT_EQ(decode_wld_string(std::span<const uint8_t>(wt_zone).first(7)), "WT_ZONE");

    Bytes round = spec_xor("anything at all");
    wld_xor(round);
    EXPECT_EQ(std::string(round.begin(), round.end()), "anything at all");
}

// ---------------------------------------------------------------------------------------------
// §3.4 BSP tree known answer

const Bytes kTreeFragment = {
    0x5c, 0x00, 0x00, 0x00, 0x21, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00, //
    0x00, 0x00, 0x80, 0x3f, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xc8, 0xc2, //
    0x00, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, //
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, //
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, //
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, //
    0x00, 0x00, 0x00, 0x00,
};

// Finds fragment `number`'s bytes (header included) in a file.
Bytes fragment_bytes(const WldFile& wld, uint32_t number)
{
    const WldFragment& f = wld.fragment(number);
    const auto begin = wld.bytes.begin() + static_cast<std::ptrdiff_t>(f.body_offset - 8);
    return Bytes(begin, begin + 8 + f.body_size);
}

// The walk the spec's table describes (WQ rule: s >= 0 goes to the front child).
uint32_t region_at(const WldBspTree& tree, glm::vec3 p)
{
    uint32_t n = 1;
    while (n != 0) {
        const WldBspNode& node = tree.nodes[n - 1];
        if (node.region > 0)
            return node.region;
        const float s = node.normal.x * p.x + node.normal.y * p.y + node.normal.z * p.z + node.d;
        n = s >= 0 ? node.front : node.back;
    }
    return 0;
}

TEST(WldBspTree, SpecTreeParsesAndWritesByteExact)
{
    const Bytes body(kTreeFragment.begin() + 8, kTreeFragment.end());
    const WldRegion empty = make_interoperable_region(0, {0xC2}, glm::vec4(0.0f), 0);
    const std::vector<WldFragmentBytes> fragments = {
        {kWldBspTree, body}, {kWldRegion, write_region(empty)}, {kWldRegion, write_region(empty)}};
    const Bytes file = write_wld(kWldVersionOld, {}, fragments);
    const WldFile wld = parse_wld(file, "tree.wld");
    ASSERT_EQ(wld.fragments.size(), 3u);
    EXPECT_EQ(fragment_bytes(wld, 1), kTreeFragment);

    const WldBspTree tree = parse_bsp_tree(wld, 1);
    EXPECT_EQ(tree.name_ref, 0);
    ASSERT_EQ(tree.nodes.size(), 3u);
    EXPECT_EQ(tree.nodes[0], (WldBspNode{glm::vec3(1, 0, 0), -100.0f, 0, 2, 3}));
    EXPECT_EQ(tree.nodes[1], (WldBspNode{glm::vec3(0.0f), 0.0f, 1, 0, 0}));
    EXPECT_EQ(tree.nodes[2], (WldBspNode{glm::vec3(0.0f), 0.0f, 2, 0, 0}));
    EXPECT_EQ(write_bsp_tree(tree), body);

    EXPECT_EQ(region_at(tree, {150, 0, 0}), 1u);
    EXPECT_EQ(region_at(tree, {50, 7, -3}), 2u);
    EXPECT_EQ(region_at(tree, {100, 0, 0}), 1u);
}

// ---------------------------------------------------------------------------------------------
// §4.7 region known answer

const Bytes kRegionFragment = {
    0x64, 0x00, 0x00, 0x00, 0x22, 0x00, 0x00, 0x00, 0xff, 0xff, 0xff, 0xff, 0x81, 0x01, 0x00, 0x00, //
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, //
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, //
    0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, //
    0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, //
    0x02, 0x00, 0x9a, 0xc1, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, //
    0x00, 0x00, 0xc8, 0x42, 0x00, 0x00, 0x00, 0x00, 0x05, 0x00, 0x00, 0x00,
};

TEST(WldRegion, SpecRegionParsesAndWritesByteExact)
{
    // mesh_ref 5 must name an earlier 0x36: the region is fragment 6.
    const Bytes body(kRegionFragment.begin() + 8, kRegionFragment.end());
    WldStringTable strings;
    ASSERT_EQ(strings.add("R000001"), -1);
    const Bytes name0 = {0, 0, 0, 0};
    const WldBspTree leaf{0, {WldBspNode{glm::vec3(0.0f), 0.0f, 1, 0, 0}}};
    const std::vector<WldFragmentBytes> fragments = {{kWldBitmapName, name0}, {kWldSpriteDef, name0},
                                                     {kWldSprite, name0},     {kWldBspTree, write_bsp_tree(leaf)},
                                                     {kWldMesh, name0},       {kWldRegion, body}};
    const Bytes file = write_wld(kWldVersionOld, strings.data(), fragments);
    const WldFile wld = parse_wld(file, "region.wld");
    EXPECT_EQ(fragment_bytes(wld, 6), kRegionFragment);
    EXPECT_EQ(fragment_name(wld, wld.fragment(6)), "R000001");

    const WldRegion region = parse_region(wld, 6);
    EXPECT_EQ(region.name_ref, -1);
    EXPECT_EQ(region.flags, 0x181u);
    EXPECT_EQ(region.ambient_light, 0);
    EXPECT_TRUE(region.vertices.empty() && region.proximal_regions.empty() && region.render_vertices.empty());
    EXPECT_TRUE(region.walls.empty() && region.obstacles.empty());
    EXPECT_EQ(region.cutting_obstacle_count, 0u);
    ASSERT_EQ(region.vis_nodes.size(), 1u);
    EXPECT_EQ(region.vis_nodes[0], (WldVisNode{glm::vec4(0.0f), 1, 0, 0}));
    ASSERT_EQ(region.vis_lists.size(), 1u);
    EXPECT_EQ(region.vis_lists[0], (WldVisList{true, {0x9A, 0xC1}}));
    EXPECT_EQ(region.sphere, glm::vec4(0, 0, 0, 100));
    EXPECT_TRUE(region.user_data.empty());
    EXPECT_EQ(region.mesh_ref, 5);
    EXPECT_EQ(resolve_fragment_ref(wld, region.mesh_ref), 5u);
    EXPECT_TRUE(is_interoperable_region(region));

    uint64_t row[1];
    const EqVislistResult decoded = decode_vis_list(region.vis_lists[0], 8, row);
    EXPECT_TRUE(decoded.well_formed);
    EXPECT_EQ(set_bits(row), (std::vector<uint32_t>{0, 1, 2, 5}));

    EXPECT_EQ(write_region(region), body);
    EXPECT_EQ(write_region(make_interoperable_region(-1, {0x9A, 0xC1}, glm::vec4(0, 0, 0, 100), 5)), body);
}

// ---------------------------------------------------------------------------------------------
// A hand-assembled WLD from the spec's tables:
//   1 0x36 placeholder mesh   2 0x21 tree (§3.4 shape)   3 0x22 region A (every counted part,
//   byte-form list)   4 0x22 region B (word-form lists)   5 0x29 WT_ZONE   6 0x29 Z0000_ZONE

const std::string kZoneLine = "DRNTP00002-00030000357999999999___000000000000"; // LQ fixture, §5.2

struct HandMade {
    Bytes file;
    std::string strings; // decoded
    std::map<std::string, int32_t> refs;
    std::vector<Bytes> bodies; // as built, unpadded
    std::vector<uint64_t> body_at;
    std::map<std::string, uint64_t> at; // absolute offsets of fields the bad-input tests change

    uint64_t field(uint32_t fragment, uint64_t body_offset) const { return body_at[fragment - 1] + body_offset; }
};

HandMade build_hand_made()
{
    HandMade h;
    SpecStrings strings;
    for (const char* s : {"MESH_DMSPRITEDEF", "WORLD_TREE", "R000001", "R000002", "WT_ZONE", "Z0000_ZONE"})
        strings.add(s);
    h.strings = strings.decoded;
    h.refs = strings.refs;
    std::map<std::string, uint64_t> rel; // body-relative offsets, made absolute below
    std::vector<std::pair<std::string, uint32_t>> rel_fragment;
    const auto mark = [&](const char* key, uint32_t fragment, const Builder& b) {
        rel[key] = b.size();
        rel_fragment.emplace_back(key, fragment);
    };

    // 1: placeholder mesh (only its name; nothing here parses 0x36)
    h.bodies.push_back(Builder().i32(h.refs["MESH_DMSPRITEDEF"]).out);

    // 2: tree, §3.1
    {
        Builder b;
        b.i32(h.refs["WORLD_TREE"]).u32(3);
        b.f32(1).f32(0).f32(0).f32(-100).i32(0).i32(2).i32(3);
        b.f32(0).f32(0).f32(0).f32(0);
        mark("tree.node2.region", 2, b);
        b.i32(1);
        mark("tree.node2.front", 2, b);
        b.i32(0).i32(0);
        b.f32(0).f32(0).f32(0).f32(0).i32(2).i32(0).i32(0);
        h.bodies.push_back(b.out);
    }
    // 3: region A, §4.1 / §4.3: flags sphere + reverb volume + reverb offset + bytes + mesh
    {
        Builder b;
        b.i32(h.refs["R000001"]).u32(0x187).i32(0);
        mark("A.nv", 3, b);
        b.u32(3).u32(1).u32(2).u32(2).u32(4).u32(0).u32(1).u32(1); // NV NP NR NW NO NC NN NL
        b.f32(0).f32(0).f32(0).f32(10).f32(0).f32(0).f32(10).f32(10).f32(5);
        b.u32(2).f32(12.5f);
        b.f32(1).f32(2).f32(3).f32(4).f32(5).f32(6);
        // wall 0: floor + render data, every render info part
        b.u32(0x3);
        mark("A.wall0.count", 3, b);
        b.u32(3).u32(0).u32(1).u32(2);
        b.u32(0x80000001u).u32(0x7F).u32(201).f32(1.0f).f32(0.5f);
        mark("A.wall0.sprite", 3, b);
        b.i32(1);
        b.f32(1).f32(2).f32(3).f32(4).f32(5).f32(6).f32(7).f32(8).f32(9);
        b.u32(3).f32(0).f32(1).f32(1).f32(1).f32(1).f32(0);
        b.f32(0).f32(0).f32(1).f32(-5);
        // wall 1: no render data
        b.u32(0x0).u32(2).u32(1).u32(2);
        // obstacles: EDGEPOLYGON+NORMALABCD, EDGEWALL with user data, EDGEPOLYGON, XY_VERTEX
        b.u32(0).i32(2);
        mark("A.ob0.type", 3, b);
        b.i32(-15).u32(3).u32(0).u32(1).u32(2).f32(1).f32(0).f32(0).f32(-10);
        b.u32(0x5).i32(0).i32(18);
        mark("A.ob1.wall", 3, b);
        b.u32(1).u32(5).raw({'h', 'e', 'l', 'l', 'o'});
        b.u32(0).i32(1).i32(14).u32(2).u32(2).u32(0);
        b.u32(0x2).i32(0).i32(8);
        // vis node, one byte-form list of 3 bytes: include 0, skip 0, include 1
        b.f32(0).f32(0).f32(0).f32(0).u32(1).u32(0).u32(0);
        b.u16(3).u8(0xC1).u8(0x00).u8(0xC1);
        b.f32(5).f32(5).f32(2.5f).f32(8).f32(0.25f).i32(-3);
        b.u32(3).raw({'x', 'y', 'z'});
        mark("A.mesh_ref", 3, b);
        b.i32(1);
        h.bodies.push_back(b.out);
    }
    // 4: region B: flags 0 (word form, no sphere, no mesh), one vis node naming list 2, two lists
    {
        Builder b;
        b.i32(h.refs["R000002"]).u32(0x0).i32(0);
        b.u32(0).u32(0).u32(0).u32(0).u32(0).u32(0).u32(1).u32(2);
        b.f32(0).f32(0).f32(1).f32(0).u32(2).u32(0).u32(0);
        mark("B.list1", 4, b);
        b.u16(2).u16(0x0005).u16(0x0101); // §8.1 #23
        b.u16(1).u16(0x0000);
        b.u32(0);
        h.bodies.push_back(b.out);
    }
    // 5: WT_ZONE over region 0; its user data says lava, but the name decides (ZU order)
    {
        Builder b;
        b.i32(h.refs["WT_ZONE"]).u32(0).u32(1).u32(0);
        b.u32(8).raw(spec_xor(std::string("LA_ZONE\0", 8)));
        h.bodies.push_back(b.out);
    }
    // 6: Z0000_ZONE over regions 0 and 1; the type is in the user data (a zone line)
    {
        Builder b;
        b.i32(h.refs["Z0000_ZONE"]).u32(0);
        mark("flag6.count", 6, b);
        b.u32(2).u32(0);
        mark("flag6.entry1", 6, b);
        b.u32(1);
        b.u32(uint32_t(kZoneLine.size() + 1)).raw(spec_xor(kZoneLine + std::string(1, '\0')));
        h.bodies.push_back(b.out);
    }

    const uint32_t types[6] = {kWldMesh, kWldBspTree, kWldRegion, kWldRegion, kWldRegionFlag, kWldRegionFlag};
    SpecFile f = spec_wld(0x00015500, h.strings, types, h.bodies);
    h.file = std::move(f.file);
    h.body_at = std::move(f.body_at);
    for (size_t i = 0; i < 6; ++i)
        h.at["fragment" + std::to_string(i + 1)] = f.header_at[i];
    for (const auto& [key, fragment] : rel_fragment)
        h.at[key] = h.field(fragment, rel[key]);
    return h;
}

const HandMade& hand_made()
{
    static const HandMade h = build_hand_made();
    return h;
}

TEST(WldFile, HandMadeContainer)
{
    const HandMade& h = hand_made();
    const WldFile wld = parse_wld(h.file, "hand.wld");
    EXPECT_EQ(wld.name, "hand.wld");
    EXPECT_EQ(wld.header.version, kWldVersionOld);
    EXPECT_EQ(wld.header.fragment_count, 6u);
    EXPECT_EQ(wld.header.region_count, 2u);
    EXPECT_EQ(wld.header.string_hash_size, padded(Bytes(h.strings.begin(), h.strings.end())).size());
    EXPECT_EQ(wld.header.string_count, 6u);
    EXPECT_EQ(std::string(wld.strings.begin(), wld.strings.end()), h.strings);
    EXPECT_TRUE(wld.has_trailer);
    EXPECT_EQ(wld.region_fragments, (std::vector<uint32_t>{3, 4}));
    EXPECT_EQ(wld.region_count(), 2u);

    const uint32_t types[6] = {kWldMesh, kWldBspTree, kWldRegion, kWldRegion, kWldRegionFlag, kWldRegionFlag};
    const char* names[6] = {"MESH_DMSPRITEDEF", "WORLD_TREE", "R000001", "R000002", "WT_ZONE", "Z0000_ZONE"};
    ASSERT_EQ(wld.fragments.size(), 6u);
    for (uint32_t n = 1; n <= 6; ++n) {
        const WldFragment& f = wld.fragment(n);
        EXPECT_EQ(f.type, types[n - 1]);
        EXPECT_EQ(f.name_ref, h.refs.at(names[n - 1]));
        EXPECT_EQ(f.body_offset, h.body_at[n - 1]);
        EXPECT_EQ(f.body_size, padded(h.bodies[n - 1]).size());
        EXPECT_EQ(fragment_name(wld, f), names[n - 1]);
        EXPECT_EQ(resolve_fragment_ref(wld, f.name_ref), n); // by name: the first with that name
    }
    EXPECT_THROW(wld.fragment(0), std::out_of_range);
    EXPECT_THROW(wld.fragment(7), std::out_of_range);

    // The assembler writes the same file from the same strings and bodies.
    std::vector<WldFragmentBytes> bodies;
    for (uint32_t n = 1; n <= 6; ++n)
        bodies.push_back({types[n - 1], h.bodies[n - 1]});
    EXPECT_EQ(write_wld(kWldVersionOld, std::span<const char>(h.strings.data(), h.strings.size()), bodies), h.file);
}

TEST(WldFile, HandMadeTree)
{
    const HandMade& h = hand_made();
    const WldFile wld = parse_wld(h.file, "hand.wld");
    const WldBspTree tree = parse_bsp_tree(wld, 2);
    EXPECT_EQ(tree.name_ref, h.refs.at("WORLD_TREE"));
    ASSERT_EQ(tree.nodes.size(), 3u);
    EXPECT_EQ(tree.nodes[0], (WldBspNode{glm::vec3(1, 0, 0), -100.0f, 0, 2, 3}));
    EXPECT_EQ(tree.nodes[1], (WldBspNode{glm::vec3(0.0f), 0.0f, 1, 0, 0}));
    EXPECT_EQ(tree.nodes[2], (WldBspNode{glm::vec3(0.0f), 0.0f, 2, 0, 0}));
    EXPECT_EQ(write_bsp_tree(tree), h.bodies[1]);
}

TEST(WldFile, HandMadeRegionWithEveryPart)
{
    const HandMade& h = hand_made();
    const WldFile wld = parse_wld(h.file, "hand.wld");
    const WldRegion a = parse_region(wld, 3);
    EXPECT_EQ(a.name_ref, h.refs.at("R000001"));
    EXPECT_EQ(a.flags, 0x187u);
    EXPECT_EQ(a.ambient_light, 0);
    EXPECT_EQ(a.vertices, (std::vector<glm::vec3>{{0, 0, 0}, {10, 0, 0}, {10, 10, 5}}));
    EXPECT_EQ(a.proximal_regions, (std::vector<WldProximalRegion>{{2, 12.5f}}));
    EXPECT_EQ(a.render_vertices, (std::vector<glm::vec3>{{1, 2, 3}, {4, 5, 6}}));

    ASSERT_EQ(a.walls.size(), 2u);
    const WldWall& w0 = a.walls[0];
    EXPECT_EQ(w0.flags, kWldWallFloor | kWldWallRenderData);
    EXPECT_EQ(w0.vertices, (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(w0.render_method, 0x80000001u);
    EXPECT_EQ(w0.render_info.flags, 0x7Fu);
    EXPECT_EQ(w0.render_info.pen, 201u);
    EXPECT_EQ(w0.render_info.brightness, 1.0f);
    EXPECT_EQ(w0.render_info.scaled_ambient, 0.5f);
    EXPECT_EQ(w0.render_info.sprite_ref, 1);
    EXPECT_EQ(w0.render_info.uv_origin, glm::vec3(1, 2, 3));
    EXPECT_EQ(w0.render_info.u_axis, glm::vec3(4, 5, 6));
    EXPECT_EQ(w0.render_info.v_axis, glm::vec3(7, 8, 9));
    EXPECT_EQ(w0.render_info.uv_map, (std::vector<glm::vec2>{{0, 1}, {1, 1}, {1, 0}}));
    EXPECT_EQ(w0.normal, glm::vec4(0, 0, 1, -5));
    EXPECT_EQ(a.walls[1], (WldWall{0, {1, 2}, 0, {}, glm::vec4(0.0f)}));

    ASSERT_EQ(a.obstacles.size(), 4u);
    EXPECT_EQ(a.obstacles[0], (WldObstacle{0, 2, -15, {0, 1, 2}, glm::vec4(1, 0, 0, -10), 0, {}}));
    EXPECT_EQ(a.obstacles[1], (WldObstacle{5, 0, 18, {}, glm::vec4(0.0f), 1, {'h', 'e', 'l', 'l', 'o'}}));
    EXPECT_EQ(a.obstacles[2], (WldObstacle{0, 1, 14, {2, 0}, glm::vec4(0.0f), 0, {}}));
    EXPECT_EQ(a.obstacles[3], (WldObstacle{2, 0, 8, {}, glm::vec4(0.0f), 0, {}}));
    EXPECT_EQ(a.cutting_obstacle_count, 0u);

    ASSERT_EQ(a.vis_nodes.size(), 1u);
    EXPECT_EQ(a.vis_nodes[0], (WldVisNode{glm::vec4(0.0f), 1, 0, 0}));
    ASSERT_EQ(a.vis_lists.size(), 1u);
    EXPECT_EQ(a.vis_lists[0], (WldVisList{true, {0xC1, 0x00, 0xC1}}));
    EXPECT_EQ(a.vis_lists[0].range_count(), 3u);
    EXPECT_EQ(a.sphere, glm::vec4(5, 5, 2.5f, 8));
    EXPECT_EQ(a.reverb_volume, 0.25f);
    EXPECT_EQ(a.reverb_offset, -3);
    EXPECT_EQ(a.user_data, (Bytes{'x', 'y', 'z'}));
    EXPECT_EQ(a.mesh_ref, 1);
    EXPECT_FALSE(is_interoperable_region(a));

    uint64_t row[1];
    EXPECT_TRUE(decode_vis_list(a.vis_lists[0], wld.region_count(), row).well_formed);
    EXPECT_EQ(set_bits(row), (std::vector<uint32_t>{0, 1}));

    EXPECT_EQ(write_region(a), padded(h.bodies[2]));
}

TEST(WldFile, HandMadeRegionWithWordLists)
{
    const HandMade& h = hand_made();
    const WldFile wld = parse_wld(h.file, "hand.wld");
    const WldRegion b = parse_region(wld, 4);
    EXPECT_EQ(b.flags, 0u);
    ASSERT_EQ(b.vis_nodes.size(), 1u);
    EXPECT_EQ(b.vis_nodes[0], (WldVisNode{glm::vec4(0, 0, 1, 0), 2, 0, 0}));
    ASSERT_EQ(b.vis_lists.size(), 2u);
    EXPECT_EQ(b.vis_lists[0], (WldVisList{false, {0x05, 0x00, 0x01, 0x01}}));
    EXPECT_EQ(b.vis_lists[0].range_count(), 2u);
    EXPECT_EQ(b.vis_lists[1], (WldVisList{false, {0x00, 0x00}}));
    EXPECT_EQ(b.sphere, glm::vec4(0.0f)); // flag bit 0 clear: not in the file
    EXPECT_TRUE(b.user_data.empty());
    EXPECT_EQ(b.mesh_ref, 0);

    // §8.1 #23: the words are 0-based region numbers.
    uint64_t row[bits::words_for(300)];
    EXPECT_TRUE(decode_vis_list(b.vis_lists[0], 300, row).well_formed);
    EXPECT_EQ(set_bits(row), (std::vector<uint32_t>{5, 257}));

    EXPECT_EQ(write_region(b), padded(h.bodies[3]));
}

TEST(WldFile, HandMadeRegionFlags)
{
    const HandMade& h = hand_made();
    const WldFile wld = parse_wld(h.file, "hand.wld");

    const WldRegionFlag water = parse_region_flag(wld, 5);
    EXPECT_EQ(water.name_ref, h.refs.at("WT_ZONE"));
    EXPECT_EQ(water.flags, 0u);
    EXPECT_EQ(water.regions, (std::vector<uint32_t>{0}));
    EXPECT_EQ(water.user_data, "LA_ZONE");
    EXPECT_EQ(water.type.flags, uint32_t(kRegionWater)); // the name wins over the user data
    EXPECT_EQ(water.type.zone_line, std::nullopt);
    EXPECT_EQ(water.type_source, WldTypeSource::Name);
    EXPECT_EQ(write_region_flag(water), padded(h.bodies[4]));

    const WldRegionFlag line = parse_region_flag(wld, 6);
    EXPECT_EQ(line.regions, (std::vector<uint32_t>{0, 1}));
    EXPECT_EQ(line.user_data, kZoneLine);
    EXPECT_EQ(line.type.flags, uint32_t(kRegionZoneLine));
    EXPECT_EQ(line.type_source, WldTypeSource::UserData);
    ASSERT_TRUE(line.type.zone_line.has_value());
    // LX's positions give y = 357 and z = 999999 ([16,22) = "000357", [22,28) = "999999"); the
    // spec's "z = 799999" reads the fields one character early.
    EXPECT_EQ(*line.type.zone_line, (WldZoneLineTarget{2, 0, -30, 357, 999999, 999}));
    EXPECT_EQ(write_region_flag(line), padded(h.bodies[5]));
}

TEST(WldRegionFlagType, PrefixesAndZoneLines)
{
    const auto flags = [](std::string_view s) { return classify_region_type(s).flags; };
    EXPECT_EQ(flags("WT_ZONE"), uint32_t(kRegionWater));
    EXPECT_EQ(flags("wtn__01521000000000000000000000___000000000000"), uint32_t(kRegionWater));
    EXPECT_EQ(flags("LA_ZONE"), uint32_t(kRegionLava));
    EXPECT_EQ(flags("lan_zone"), uint32_t(kRegionLava));
    EXPECT_EQ(flags("SLN_ZONE"), uint32_t(kRegionSlime));
    EXPECT_EQ(flags("DRP_ZONE"), uint32_t(kRegionPvp));
    EXPECT_EQ(flags("DRN__00000000000000000000000000___000000000000"), uint32_t(kRegionIce));
    EXPECT_EQ(flags("VWA_ZONE"), uint32_t(kRegionVWater));
    EXPECT_EQ(flags("vwn_zone"), uint32_t(kRegionVWater));
    EXPECT_EQ(flags("WTNTP00002-00030000357999999999"), uint32_t(kRegionWater | kRegionZoneLine));
    EXPECT_EQ(flags("LANTP00002-00030000357999999999"), uint32_t(kRegionLava | kRegionZoneLine));
    EXPECT_EQ(flags("Z0001_ZONE"), 0u); // the type is in its user data
    EXPECT_EQ(flags(""), 0u);
    EXPECT_EQ(flags("R000001"), 0u);

    EXPECT_EQ(classify_region_type("drntp_zone").zone_line, (WldZoneLineTarget{255, 0, 0, 0, 0, 0}));
    EXPECT_EQ(classify_region_type("DRNTP00255000123___").zone_line, (WldZoneLineTarget{255, 123, 0, 0, 0, 0}));
    EXPECT_EQ(classify_region_type("DRNTP00054001500-00200000100128").zone_line,
              (WldZoneLineTarget{54, 0, 1500, -200, 100, 128}));
    const WldRegionType garbled = classify_region_type("DRNTPxx");
    EXPECT_EQ(garbled.flags, uint32_t(kRegionZoneLine));
    EXPECT_EQ(garbled.zone_line, std::nullopt); // a zone line whose target is not readable
}

// ---------------------------------------------------------------------------------------------
// Writers refuse what the file cannot hold

TEST(WldWriters, RejectUnwritableData)
{
    WldRegion region = make_interoperable_region(0, {0xC1}, glm::vec4(0.0f), 0);
    region.vis_lists[0].byte_form = false; // differs from flags bit 7
    EXPECT_THROW(write_region(region), std::invalid_argument);
    region = make_interoperable_region(0, Bytes(65536, 0xC1), glm::vec4(0.0f), 0);
    EXPECT_THROW(write_region(region), std::invalid_argument);
    EXPECT_FALSE(is_interoperable_region(region));
    region = make_interoperable_region(0, {0xC1}, glm::vec4(0.0f), 0);
    region.obstacles.push_back(WldObstacle{0, 0, 99, {}, glm::vec4(0.0f), 0, {}});
    EXPECT_THROW(write_region(region), std::invalid_argument);
    region.obstacles.back().type = kWldObstacleEdgeWall; // names wall 0 of none
    EXPECT_THROW(write_region(region), std::invalid_argument);
    region = make_interoperable_region(0, {0xC1}, glm::vec4(0.0f), 0);
    region.vis_nodes[0].vis_list_index = 2;
    EXPECT_THROW(write_region(region), std::invalid_argument);
    EXPECT_THROW(make_interoperable_region(0, {}, glm::vec4(0.0f), -4), std::invalid_argument);

    const Bytes tree = write_bsp_tree(WldBspTree{0, {WldBspNode{glm::vec3(0.0f), 0.0f, 1, 0, 0}}});
    const Bytes reg = write_region(make_interoperable_region(0, {0xC1}, glm::vec4(0.0f), 0));
    const Bytes flag = write_region_flag(WldRegionFlag{0, 0, {0}, "", {}, WldTypeSource::None});
    const auto wld = [](std::vector<WldFragmentBytes> f) { return write_wld(kWldVersionOld, {}, f); };
    EXPECT_NO_THROW(wld({{kWldBspTree, tree}, {kWldRegion, reg}, {kWldRegionFlag, flag}}));
    EXPECT_THROW(wld({{kWldRegion, reg}, {kWldBspTree, tree}}), std::invalid_argument);
    EXPECT_THROW(wld({{kWldBspTree, tree}, {kWldRegionFlag, flag}, {kWldRegion, reg}}), std::invalid_argument);
    EXPECT_THROW(wld({{kWldBspTree, tree}, {kWldBspTree, tree}}), std::invalid_argument);
    EXPECT_THROW(wld({{kWldMesh, {1, 0, 0, 0}}}), std::invalid_argument); // positive name_ref
    EXPECT_THROW(wld({{kWldMesh, {0xF0, 0xFF, 0xFF, 0xFF}}}), std::invalid_argument); // outside the strings
    EXPECT_THROW(wld({{kWldMesh, {0, 0}}}), std::invalid_argument);
    EXPECT_THROW(write_wld(0x1234, {}, {}), std::invalid_argument);
    EXPECT_THROW(write_wld(kWldVersionOld, std::string_view("x\0", 2), {}), std::invalid_argument);

    // A file with no fragments is still a valid file.
    const Bytes empty = write_wld(kWldVersionNew, {}, {});
    const WldFile parsed = parse_wld(empty, "empty.wld");
    EXPECT_EQ(parsed.header.version, kWldVersionNew);
    EXPECT_TRUE(parsed.fragments.empty());
    EXPECT_TRUE(parsed.has_trailer);
}

// ---------------------------------------------------------------------------------------------
// Bad input: FileError naming the file, the absolute offset, the fragment and the problem

const auto kParseFile = [](const Bytes& b) { parse_wld(b, "bad.wld"); };

TEST(WldBadInput, TruncatedHeaderAndBadMagic)
{
    const Bytes& good = hand_made().file;
    expect_error(Bytes(good.begin(), good.begin() + 20), kParseFile, 0, {"WLD header", "runs past the end"});
    Bytes bad = good;
    bad[0] = 0x03;
    expect_error(bad, kParseFile, 0, {"not a WLD file", "magic"});
    expect_error(Bytes{1, 2}, kParseFile, 0, {"WLD header"});
    bad = good;
    put_u32(bad, 4, 0x00015501);
    expect_error(bad, kParseFile, 4, {"unknown WLD version 0x15501"});
    bad = good;
    put_u32(bad, 20, 0x7FFFFFFF);
    expect_error(bad, kParseFile, 28, {"string hash", "runs past the end"});
}

TEST(WldBadInput, FragmentSizePastTheEnd)
{
    const HandMade& h = hand_made();
    Bytes bad = h.file;
    put_u32(bad, h.at.at("fragment6"), 0x10000);
    expect_error(bad, kParseFile, h.at.at("fragment6"),
                 {"fragment 6 (0x29 region flag)", "runs past the end of the file"});
    bad = h.file;
    put_u32(bad, h.at.at("fragment2"), 2);
    expect_error(bad, kParseFile, h.at.at("fragment2"),
                 {"fragment 2 (0x21 bsp tree)", "smaller than its 4-byte name_ref"});
    // A fragment count no file of this size can hold is refused before anything is reserved.
    bad = h.file;
    put_u32(bad, 8, 0xFFFFFFFF);
    expect_error(bad, kParseFile, 8, {"fragment_count 4294967295 cannot fit"});
    // One fragment more than the file holds: the 7th header would start at the trailer.
    bad = h.file;
    put_u32(bad, 8, 7);
    expect_error(bad, kParseFile, h.file.size() - 4, {"fragment 7 of 7", "runs past the end of the file"});
    // The name_ref of every fragment must name a string.
    bad = h.file;
    put_u32(bad, h.body_at[0], uint32_t(-5000));
    expect_error(bad, kParseFile, h.body_at[0],
                 {"fragment 1 (0x36 mesh)", "name_ref -5000 is outside the string hash"});
}

TEST(WldBadInput, RegionCountMismatch)
{
    Bytes bad = hand_made().file;
    put_u32(bad, 12, 3);
    expect_error(bad, kParseFile, 12, {"header region_count 3", "2 0x22 region fragments"});
}

TEST(WldBadInput, ForwardAndOutOfRangeReferences)
{
    const HandMade& h = hand_made();
    const auto region3 = parse_fragment<parse_region>(3);
    Bytes bad = h.file;
    put_u32(bad, h.at.at("A.mesh_ref"), 5);
    expect_error(bad, region3, h.at.at("A.mesh_ref"),
                 {"fragment 3 (0x22 region)", "mesh_ref 5 is a forward reference"});
    put_u32(bad, h.at.at("A.mesh_ref"), 3); // itself
    expect_error(bad, region3, h.at.at("A.mesh_ref"), {"fragment 3 (0x22 region)", "forward reference"});
    put_u32(bad, h.at.at("A.mesh_ref"), 99);
    expect_error(bad, region3, h.at.at("A.mesh_ref"), {"fragment 3 (0x22 region)", "mesh_ref 99 is out of range"});
    put_u32(bad, h.at.at("A.mesh_ref"), 2);
    expect_error(bad, region3, h.at.at("A.mesh_ref"), {"mesh_ref 2 names fragment 2 (0x21 bsp tree), not a mesh"});
    bad = h.file;
    put_u32(bad, h.at.at("A.wall0.sprite"), 4);
    expect_error(bad, region3, h.at.at("A.wall0.sprite"), {"fragment 3 (0x22 region)", "wall sprite reference 0 4"});
    bad = h.file;
    put_u32(bad, h.at.at("A.ob1.wall"), 2);
    expect_error(bad, region3, h.at.at("A.ob1.wall"), {"obstacle 1 names wall 2 but the region has 2 walls"});
    bad = h.file;
    put_u32(bad, h.at.at("A.ob0.type"), 99);
    expect_error(bad, region3, h.at.at("A.ob0.type"), {"obstacle 0 has unknown type 99"});

    const auto tree2 = parse_fragment<parse_bsp_tree>(2);
    bad = h.file;
    put_u32(bad, h.at.at("tree.node2.region"), 3);
    expect_error(bad, tree2, h.at.at("tree.node2.region"),
                 {"fragment 2 (0x21 bsp tree)", "node 2 region 3 is out of range"});
    bad = h.file;
    put_u32(bad, h.at.at("tree.node2.front"), 4);
    expect_error(bad, tree2, h.at.at("tree.node2.front"),
                 {"fragment 2 (0x21 bsp tree)", "node 2 child 4 is out of range"});
    put_u32(bad, h.at.at("tree.node2.front"), 1); // node 2 -> node 1: a cycle
    expect_error(bad, tree2, h.field(2, 8), {"node 1 is reached twice from the root"});

    const auto flag6 = parse_fragment<parse_region_flag>(6);
    bad = h.file;
    put_u32(bad, h.at.at("flag6.entry1"), 2);
    expect_error(bad, flag6, h.at.at("flag6.entry1"),
                 {"fragment 6 (0x29 region flag)", "is region 2 (0-based) but the file has 2"});

    // The typed parsers check the type they were asked for.
    expect_error(h.file, parse_fragment<parse_region>(2), h.field(2, 0) - 4,
                 {"fragment 2 (0x21 bsp tree)", "expected a 0x22 region"});
}

TEST(WldBadInput, VisListPastTheFragment)
{
    const HandMade& h = hand_made();
    Bytes bad = h.file;
    bad[h.at.at("B.list1")] = 0xE8; // range_count 1000 words
    bad[h.at.at("B.list1") + 1] = 0x03;
    expect_error(bad, parse_fragment<parse_region>(4), h.at.at("B.list1") + 2,
                 {"fragment 4 (0x22 region)", "vis list 1 runs past the end of the fragment"});
}

TEST(WldBadInput, WallFieldsNameTheirWall)
{
    // Region A's body cut (on a hand-made WldFile) just before wall 0's uv origin and just
    // before its normal: the message names wall 0, and the offset is the field's.
    const HandMade& h = hand_made();
    const WldFile wld = parse_wld(h.file, "cut.wld");
    const uint64_t sprite = h.at.at("A.wall0.sprite");
    const uint64_t uv_origin = sprite + 4;              // after the sprite reference
    const uint64_t normal = uv_origin + 36 + 4 + 3 * 8; // after uv info, uv map count, 3 uv pairs
    for (const auto& [field_at, phrase] : {std::pair{uv_origin, "wall uv origin 0 runs past the end"},
                                           std::pair{normal, "wall normal 0 runs past the end"}}) {
        WldFile cut = wld;
        cut.fragments[2].body_size = static_cast<uint32_t>(field_at - h.body_at[2]);
        try {
            (void)parse_region(cut, 3);
            ADD_FAILURE() << "no FileError; expected: " << phrase;
        } catch (const FileError& e) {
            EXPECT_EQ(e.file(), "cut.wld");
            EXPECT_EQ(e.offset(), field_at) << e.what();
            EXPECT_NE(e.reason().find("fragment 3 (0x22 region)"), std::string::npos) << e.reason();
            EXPECT_NE(e.reason().find(phrase), std::string::npos) << e.reason();
        }
    }
}

TEST(WldBadInput, CountsThatOverflow)
{
    const HandMade& h = hand_made();
    const auto region3 = parse_fragment<parse_region>(3);
    Bytes bad = h.file;
    put_u32(bad, h.at.at("A.nv"), 0x80000000u); // 2^31 vertices: 12 * 2^31 overflows 32 bits
    expect_error(bad, region3, h.at.at("A.nv"),
                 {"fragment 3 (0x22 region)", "num_region_vertices 2147483648 does not fit"});
    bad = h.file;
    put_u32(bad, h.at.at("A.nv") + 12, 0xFFFFFFFFu); // NW
    expect_error(bad, region3, h.at.at("A.nv") + 12, {"num_walls 4294967295 does not fit"});
    bad = h.file;
    put_u32(bad, h.at.at("A.wall0.count"), 0x40000000u); // 4 * 2^30 == 2^32
    expect_error(bad, region3, h.at.at("A.wall0.count"), {"wall vertex count 0 1073741824 does not fit"});
    bad = h.file;
    put_u32(bad, h.field(2, 4), 0x80000000u);
    expect_error(bad, parse_fragment<parse_bsp_tree>(2), h.field(2, 4),
                 {"fragment 2 (0x21 bsp tree)", "node_count 2147483648 does not fit"});
    bad = h.file;
    put_u32(bad, h.at.at("flag6.count"), 0x40000000u);
    expect_error(bad, parse_fragment<parse_region_flag>(6), h.at.at("flag6.count"),
                 {"fragment 6 (0x29 region flag)", "region_count 1073741824 does not fit"});
}

// ---------------------------------------------------------------------------------------------
// Sweep: every truncation and 300 random changes parse or throw FileError, nothing else.

// Parses the container and every fragment pvscope knows; FileError escapes to the caller.
void parse_everything(const Bytes& bytes)
{
    const WldFile wld = parse_wld(bytes, "sweep.wld");
    std::vector<uint64_t> row(bits::words_for(wld.region_count()) + 1);
    for (uint32_t n = 1; n <= wld.fragments.size(); ++n) {
        const WldFragment& f = wld.fragment(n);
        (void)fragment_name(wld, f);
        if (f.type == kWldBspTree)
            (void)parse_bsp_tree(wld, n);
        if (f.type == kWldRegion)
            for (const WldVisList& list : parse_region(wld, n).vis_lists)
                (void)decode_vis_list(list, wld.region_count(), row);
        if (f.type == kWldRegionFlag)
            (void)parse_region_flag(wld, n);
    }
}

TEST(WldSweep, EveryTruncationParsesOrThrowsFileError)
{
    const Bytes& good = hand_made().file;
    ASSERT_TRUE(parses(good, parse_everything));
    // Only cuts inside the optional trailer keep every fragment.
    EXPECT_EQ(prefixes_that_parse(good, parse_everything), 4u);
}

TEST(WldSweep, RandomByteChangesParseOrThrowFileError)
{
    // Many changes hit a count, a reference or a size.
    EXPECT_GT(random_changes_that_fail(hand_made().file, 2024, parse_everything), 30u);
}

} // namespace
} // namespace pvs::eq
