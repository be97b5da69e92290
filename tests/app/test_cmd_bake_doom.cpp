// `pvscope bake` on Doom maps as a user runs it, on Freedoom MAP01 with glbsp's .gwa (which
// holds an empty GL_PVS) and with zdbsp's WAD (no GL_PVS at all):
//  - -o OUT.gwa: a copy of the .gwa whose GL_PVS holds the bake, read back through load_zone
//    with --gwa as the same rows; the input files are untouched;
//  - --in-place: GL_PVS inserted into the WAD holding the GL nodes, with glVIS's .~wa backup
//    equal to the original, and --reject rebuilding REJECT (ceil(n^2 / 8) bytes);
//  - misuse: an output of the wrong kind, --reject where REJECT is in another file, a portal file.
#include "app/cmd_bake.h"

#include "tests/app/bake_command_fixture.h"
#include "tests/support/freedoom.h"
#include "visibility/methods/vis_method.h"
#include "wld/common/read_file.h"
#include "wld/doom/doom_map.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace pvs::test {
namespace {

using BakeDoom = BakeCommand;

TEST_F(BakeDoom, GwaOutputRoundTripsThroughLoadZone)
{
    FREEDOOM_OR_SKIP(wad, "freedoom2.wad");
    GL_NODES_OR_SKIP(gwa, wad, GlBuilder::glbsp_v2);
    const std::vector<uint8_t> gwa_before = read_whole_file(gwa);
    app::BakeOptions o;
    o.input = wad;
    o.gwa = gwa;
    o.map = "MAP01";
    o.output = path("map01.gwa");
    o.method = "portal-full";
    o.threads = 2;
    ASSERT_EQ(run(o), 0) << err_;
    EXPECT_NE(err_.find("portal-full (2-D)"), std::string::npos) << err_;
    EXPECT_EQ(read_whole_file(gwa), gwa_before) << "the input .gwa is not touched";

    ZoneLoadOptions load;
    load.map = "MAP01";
    load.gwa = o.output;
    const Zone back = load_zone(wad, load);
    ASSERT_TRUE(back.baked_pvs);
    MethodSettings s;
    s.threads = 2;
    const Pvs again = *find_vis_method("portal-full")->run(back, s).pvs;
    EXPECT_EQ(rows_of(*back.baked_pvs), rows_of(again)) << "GL_PVS holds the bake, bit for bit";

    o.output = path("map01.wad");
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find("must end in .gwa"), std::string::npos) << err_;
    o.output = path("map01b.gwa");
    o.reject = true;
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find("--in-place"), std::string::npos) << err_;
    // Portal files are not a Doom map's portals: refused, not silently ignored.
    o.reject = false;
    o.prt_out = path("map01.prt");
    EXPECT_EQ(run(o), 2);
    EXPECT_FALSE(std::filesystem::exists(o.prt_out));
    EXPECT_FALSE(std::filesystem::exists(o.output));
}

TEST_F(BakeDoom, InPlaceInsertsGlPvsKeepsABackupAndRebuildsReject)
{
    FREEDOOM_OR_SKIP(wad, "freedoom2.wad");
    GL_NODES_OR_SKIP(zd, wad, GlBuilder::zdbsp_v2);
    const std::string copy = path("zd.wad");
    std::filesystem::copy_file(zd, copy);
    const std::vector<uint8_t> before = read_whole_file(copy);
    app::BakeOptions o;
    o.input = copy;
    o.map = "MAP01";
    o.in_place = true;
    o.reject = true;
    o.method = "portal-fast";
    o.threads = 2;
    ASSERT_EQ(run(o), 0) << err_;
    EXPECT_EQ(read_whole_file(path("zd.~wa")), before) << "glVIS's backup";
    const doom::WadFile after = doom::read_wad(copy);
    const doom::DoomMap map = doom::read_doom_map(after, nullptr, "MAP01");
    EXPECT_TRUE(map.source.gl_pvs_present);
    const size_t n = map.subsectors.size();
    EXPECT_EQ(map.gl_pvs.size(), ((n + 7) / 8) * n);
    const size_t sectors = map.sectors.size();
    EXPECT_EQ(map.reject.size(), (sectors * sectors + 7) / 8);
    // REJECT agrees with GL_PVS: sector pair (a, b) is rejected unless some subsector of a sees
    // one of b (checked here from the lump bytes, not through the writer).
    ZoneLoadOptions load;
    load.map = "MAP01";
    const Zone zone = load_zone(copy, load);
    ASSERT_TRUE(zone.baked_pvs);
    std::vector<uint8_t> seen(sectors * sectors, 0);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < n; ++j)
            if (zone.baked_pvs->visible(uint32_t(i), uint32_t(j)))
                seen[map.subsectors[i].sector * sectors + map.subsectors[j].sector] = 1;
    size_t disagreements = 0;
    for (size_t bit = 0; bit < sectors * sectors; ++bit)
        disagreements += ((map.reject[bit / 8] >> (bit % 8)) & 1) == seen[bit];
    EXPECT_EQ(disagreements, 0u);
}

} // namespace
} // namespace pvs::test
