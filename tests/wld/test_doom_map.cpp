// Doom maps from Freedoom with GL nodes made by glbsp (V2, V3, V5) and zdbsp (V2, V5):
// format facts of ../shared/formats/quake-doom-hepvs.md §4 checked on the real lumps, point ->
// subsector against an independent half-plane test, and bad WADs by lump and offset.
#include "tests/support/freedoom.h"
#include "visibility/file_error.h"
#include "visibility/region_lookup.h"
#include "wld/doom/doom_map.h"
#include "wld/doom/doom_zone.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace {

using namespace pvs;
using namespace pvs::doom;
using pvs::test::GlBuilder;

struct BuilderCase {
    GlBuilder builder;
    int version;
};

class DoomGlNodes : public ::testing::TestWithParam<BuilderCase> {};

// The map's lumps by the test's own reading of the directory (not read_doom_map's).
uint32_t lump_size_after(const WadFile& wad, const std::string& marker, size_t offset)
{
    const size_t m = *wad.find_last(marker);
    return wad.lumps[m + offset].size;
}

// Strictly inside the convex polygon of subsector s: right of every seg (§4.4: the interior
// lies to the right of each seg going start -> end), by an independent cross product.
bool inside_polygon(const DoomMap& map, uint32_t s, double x, double y)
{
    const GlSubsector& ss = map.subsectors[s];
    for (uint32_t k = 0; k < ss.seg_count; ++k) {
        const GlSeg& seg = map.segs[ss.first_seg + k];
        const MapVertex a = map.vertices[seg.v1], b = map.vertices[seg.v2];
        const double cross = (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
        if (cross > -1e-9) // left of or on the seg's line
            return false;
    }
    return true;
}

TEST_P(DoomGlNodes, FormatFactsAndPointToSubsectorOnEveryFreedoom2Map)
{
    FREEDOOM_OR_SKIP(wad_path, "freedoom2.wad");
    GL_NODES_OR_SKIP(gl_path, wad_path, GetParam().builder);
    const bool separate = gl_path.ends_with(".gwa");
    const WadFile wad = read_wad(separate ? wad_path : gl_path);
    const WadFile gl = read_wad(gl_path);
    const std::vector<std::string> maps = map_names(wad);
    ASSERT_EQ(maps.size(), 32u);
    EXPECT_EQ(maps.front(), "MAP01");
    EXPECT_EQ(maps.back(), "MAP32");
    size_t checked_points = 0;
    for (const std::string& name : {std::string("MAP01"), std::string("MAP10"), std::string("MAP28")}) {
        const DoomMap map = read_doom_map(wad, separate ? &gl : nullptr, name);
        EXPECT_EQ(map.gl_version, GetParam().version) << name;
        // Record counts from the lump sizes (§4.3's table), not from the reader.
        const size_t ssect_size = GetParam().version >= 3 ? 8 : 4;
        const size_t ssect_magic = GetParam().version == 3 ? 4 : 0;
        EXPECT_EQ(map.subsectors.size(), (lump_size_after(gl, "GL_" + name, 3) - ssect_magic) / ssect_size) << name;
        EXPECT_EQ(map.vertices.size() - map.map_vertex_count, (lump_size_after(gl, "GL_" + name, 1) - 4) / 8) << name;
        // Consecutive segs of a subsector share endpoints, and its polygon closes.
        size_t open_polygons = 0;
        for (const GlSubsector& ss : map.subsectors)
            for (uint32_t k = 0; k < ss.seg_count; ++k) {
                const GlSeg& seg = map.segs[ss.first_seg + k];
                const GlSeg& next = map.segs[ss.first_seg + (k + 1) % ss.seg_count];
                const MapVertex a = map.vertices[seg.v2], b = map.vertices[next.v1];
                open_polygons += (std::abs(a.x - b.x) > 1e-3 || std::abs(a.y - b.y) > 1e-3);
            }
        EXPECT_EQ(open_polygons, 0u) << name;
        // Partners are mutual and run the opposite way.
        for (size_t i = 0; i < map.segs.size(); ++i)
            if (map.segs[i].partner != kNoPartner) {
                const GlSeg& p = map.segs[map.segs[i].partner];
                ASSERT_EQ(p.partner, i) << name << " seg " << i;
                EXPECT_EQ(p.v1, map.segs[i].v2);
            }
        // The centre of each subsector polygon is inside it by the half-plane test, and the
        // GL nodes and the zone's tree both find that subsector.
        const Zone zone = build_doom_zone(map, nullptr);
        for (uint32_t s = 0; s < map.subsectors.size(); ++s) {
            const GlSubsector& ss = map.subsectors[s];
            double cx = 0, cy = 0;
            for (uint32_t k = 0; k < ss.seg_count; ++k) {
                cx += map.vertices[map.segs[ss.first_seg + k].v1].x;
                cy += map.vertices[map.segs[ss.first_seg + k].v1].y;
            }
            cx /= ss.seg_count;
            cy /= ss.seg_count;
            if (!inside_polygon(map, s, cx, cy))
                continue; // a sliver whose centre is within round-off of an edge
            EXPECT_EQ(locate_subsector(map, cx, cy), s) << name << " at " << cx << "," << cy;
            const Sector& sector = map.sectors[ss.sector];
            if (sector.ceiling_height - sector.floor_height >= 2) {
                const glm::vec3 p(float(cx), float(cy), sector.floor_height + 1.0f);
                EXPECT_EQ(locate_point(zone.tree, p).region, int32_t(s)) << name;
                EXPECT_EQ(locate_point(zone.tree, glm::vec3(p.x, p.y, sector.ceiling_height + 1.0f)).region, kLeafSolid);
            }
            ++checked_points;
        }
    }
    EXPECT_GT(checked_points, 1000u);
}

INSTANTIATE_TEST_SUITE_P(Builders, DoomGlNodes,
                         ::testing::Values(BuilderCase{GlBuilder::glbsp_v2, 2}, BuilderCase{GlBuilder::glbsp_v3, 3},
                                           BuilderCase{GlBuilder::glbsp_v5, 5}, BuilderCase{GlBuilder::zdbsp_v2, 2},
                                           BuilderCase{GlBuilder::zdbsp_v5, 5}),
                         [](const auto& param_info) {
                             std::string name = pvs::test::gl_builder_name(param_info.param.builder);
                             for (char& c : name)
                                 if (!std::isalnum(uint8_t(c)))
                                     c = '_';
                             return name;
                         });

// Every map of both IWADs loads with GL nodes from glbsp (.gwa) and from zdbsp (in the WAD),
// and both builders' trees agree with their own subsector polygons at the polygon centres.
TEST(DoomMap, EveryFreedoomMapLoadsWithGlbspAndZdbspNodes)
{
    size_t maps = 0;
    for (const char* iwad : {"freedoom1.wad", "freedoom2.wad"}) {
        FREEDOOM_OR_SKIP(wad_path, iwad);
        for (GlBuilder builder : {GlBuilder::glbsp_v2, GlBuilder::zdbsp_v2}) {
            GL_NODES_OR_SKIP(gl_path, wad_path, builder);
            const bool separate = gl_path.ends_with(".gwa");
            const WadFile wad = read_wad(separate ? wad_path : gl_path);
            const std::optional<WadFile> gl = separate ? std::optional<WadFile>(read_wad(gl_path)) : std::nullopt;
            for (const std::string& name : map_names(wad)) {
                const DoomMap map = read_doom_map(wad, gl ? &*gl : nullptr, name);
                const Zone zone = build_doom_zone(map, nullptr);
                EXPECT_EQ(zone.region_count(), map.subsectors.size()) << iwad << " " << name;
                EXPECT_GT(zone.mesh.triangle_count(), 0u) << iwad << " " << name;
                ++maps;
            }
        }
    }
    EXPECT_EQ(maps, 2u * (36 + 32));
}

TEST(DoomMap, Freedoom1HasEveryEpisodeMap)
{
    FREEDOOM_OR_SKIP(wad_path, "freedoom1.wad");
    const std::vector<std::string> maps = map_names(read_wad(wad_path));
    ASSERT_EQ(maps.size(), 36u);
    EXPECT_EQ(maps.front(), "E1M1");
    EXPECT_EQ(maps.back(), "E4M9");
}

TEST(DoomMap, AWadWithoutGlNodesSaysHowToMakeThem)
{
    FREEDOOM_OR_SKIP(wad_path, "freedoom2.wad");
    const WadFile wad = read_wad(wad_path);
    try {
        read_doom_map(wad, nullptr, "MAP01");
        FAIL() << "no error";
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("no GL nodes"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("glbsp"), std::string::npos) << e.what();
    }
    EXPECT_THROW(read_doom_map(wad, nullptr, "MAP99"), FileError);
}

TEST(DoomMap, NextMapNamesFollowTheEngines)
{
    EXPECT_EQ(next_map_name("E1M1", false), "E1M2");
    EXPECT_EQ(next_map_name("E1M3", true), "E1M9");
    EXPECT_EQ(next_map_name("E1M9", false), "E1M4");
    EXPECT_EQ(next_map_name("E1M8", false), "");
    EXPECT_EQ(next_map_name("MAP09", false), "MAP10");
    EXPECT_EQ(next_map_name("MAP15", true), "MAP31");
    EXPECT_EQ(next_map_name("MAP31", false), "MAP16");
}

} // namespace

#include "wld/doom/doom_specials.h"

namespace {

// Five sectors: 0 behind a manual door (special 1), 1 tagged by a lift (62, tag 7), 2 tagged by
// a light-only special (12, tag 8: does not move), 3 with sector special 10 (door closes after
// 30 s), 4 tagged 7 too but also a Boom generalized floor's target (tag 9).
TEST(DoomSpecials, MovingSectorsByLineAndSectorSpecials)
{
    using namespace pvs::doom;
    DoomMap map;
    map.sectors.resize(5);
    map.sectors[1].tag = 7;
    map.sectors[2].tag = 8;
    map.sectors[3].special = 10;
    map.sectors[4].tag = 9;
    map.sidedefs.resize(2);
    map.sidedefs[0].sector = 2; // front of the door line
    map.sidedefs[1].sector = 0; // behind it
    Linedef door;
    door.special = 1;
    door.side[0] = 0;
    door.side[1] = 1;
    Linedef lift;
    lift.special = 62;
    lift.tag = 7;
    Linedef light;
    light.special = 12;
    light.tag = 8;
    Linedef generalized;
    generalized.special = 0x6000 + 0x47; // a Boom generalized floor
    generalized.tag = 9;
    map.linedefs = {door, lift, light, generalized};
    const std::vector<bool> moving = moving_sectors(map);
    EXPECT_EQ(moving, (std::vector<bool>{true, true, false, true, true}));
    EXPECT_FALSE(special_moves_heights(0));
    EXPECT_FALSE(special_moves_heights(12));
    EXPECT_TRUE(special_moves_heights(62));
}

} // namespace
