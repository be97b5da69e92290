// The crossing invariant and the zone health check (visibility/eval/zone_check.h), on a tree
// built on the failure (a sliver of solid along a portal) and on every real level at hand:
// the shared Quake maps, EverQuest zones converted from one and generated, and every map of
// both Freedoom IWADs with glbsp's and zdbsp's GL nodes. One blocked crossing fails.
// Also the Doom line plane (wld/doom/line_plane.h) that took the Freedoom slivers away.
#include "tests/support/freedoom.h"
#include "tests/support/test_data.h"
#include "visibility/eval/zone_check.h"
#include "visibility/portal/portalize.h"
#include "wld/convert.h"
#include "wld/doom/doom_map.h"
#include "wld/doom/doom_zone.h"
#include "wld/doom/line_plane.h"
#include "wld/doom/wad_file.h"
#include "gen/generate_zone.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <filesystem>

namespace pvs {
namespace {

using doom::LinePlane;
using doom::vertical_line_plane;

bool same_bits(const LinePlane& a, const LinePlane& b)
{
    return std::bit_cast<uint32_t>(a.nx) == std::bit_cast<uint32_t>(b.nx) &&
           std::bit_cast<uint32_t>(a.ny) == std::bit_cast<uint32_t>(b.ny) &&
           std::bit_cast<uint32_t>(a.dist) == std::bit_cast<uint32_t>(b.dist);
}

TEST(LinePlane, EveryNameOfOneLineGivesTheSameBits)
{
    // The line through (-1000, 37) along (3, 7): points at every integer step k, named with
    // directions of every length, and a 16.16 point on it (k = 1/65536 steps are exact).
    const LinePlane reference = vertical_line_plane(-1000, 37, 3, 7);
    for (int k = -50; k <= 50; ++k)
        for (int len = 1; len <= 9; ++len) {
            const LinePlane p = vertical_line_plane(-1000 + 3 * k, 37 + 7 * k, 3 * len, 7 * len);
            ASSERT_TRUE(same_bits(p, reference)) << "k " << k << " len " << len;
        }
    const double t = 12345.0 / 65536.0;
    EXPECT_TRUE(same_bits(vertical_line_plane(-1000 + 3 * t, 37 + 7 * t, 6, 14), reference));
    // The plane is that line's: its points at distance 0 (in long double), the right side in front.
    for (int k : {-7, 0, 11})
        EXPECT_LT(std::abs(reference.nx * (-1000.0L + 3 * k) + reference.ny * (37.0L + 7 * k) - reference.dist), 1e-3L);
    EXPECT_GT(reference.nx * (-1000.0 + 7) + reference.ny * (37.0 - 3) - reference.dist, 0.0); // right of (3, 7)
}

TEST(LinePlane, TheOppositeDirectionIsTheExactNegation)
{
    for (const auto& [x, y, dx, dy] : {std::array{0.0, 0.0, 1.0, 0.0}, std::array{-768.0, 1200.0, -64.0, 48.0},
                                       std::array{3000.5, -17.25, 9.0, -4.0}}) {
        const LinePlane a = vertical_line_plane(x, y, dx, dy), b = vertical_line_plane(x + dx, y + dy, -dx, -dy);
        EXPECT_EQ(a.nx, -b.nx);
        EXPECT_EQ(a.ny, -b.ny);
        EXPECT_EQ(a.dist, -b.dist);
    }
    const LinePlane zero = vertical_line_plane(5, 5, 0, 0);
    EXPECT_EQ(zero.nx, 0.0f);
    EXPECT_EQ(zero.ny, 0.0f);
}

// A closed box split at x = 0 into regions 0 (front) and 1 (back); below the split, region 0's
// leaf sits behind a wall plane at x = sliver: a solid strip sliver wide along the portal, what
// the Doom loader built when a wall's plane came from a rounded GL vertex.
Zone split_box(float sliver)
{
    Zone zone;
    zone.regions.resize(2);
    zone.regions[0].bounds.grow(glm::vec3(0, -10, -10));
    zone.regions[0].bounds.grow(glm::vec3(10, 10, 10));
    zone.regions[1].bounds.grow(glm::vec3(-10, -10, -10));
    zone.regions[1].bounds.grow(glm::vec3(0, 10, 10));
    zone.region_face_offsets = {0, 0, 0};
    BspTree& tree = zone.tree;
    tree.leaf_region = {kLeafSolid, 0, 1};
    constexpr int32_t solid = ~0;
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const glm::vec3& axis : axes) { // six walls of the box: open inside
        const int32_t next = int32_t(tree.nodes.size()) + 1;
        tree.nodes.push_back({axis, -10.0f, {next, solid}});
        tree.nodes.push_back({-axis, -10.0f, {next + 1, solid}});
    }
    const int32_t split = int32_t(tree.nodes.size());
    tree.nodes.push_back({glm::vec3(1, 0, 0), 0.0f, {split + 1, ~2}});
    tree.nodes.push_back({glm::vec3(1, 0, 0), sliver, {~1, solid}});
    tree.root = 0;
    return zone;
}

TEST(ZoneCheck, ASliverOfSolidAlongAPortalIsABlockedCrossing)
{
    const ZoneHealth health = check_zone(split_box(1e-5f));
    ASSERT_EQ(health.tree_crossings.traced, 1u);
    ASSERT_EQ(health.tree_crossings.blocked.size(), 1u);
    const BlockedCrossing& b = health.tree_crossings.blocked[0];
    EXPECT_NEAR(b.centre.x, 0.0, 1e-6);
    EXPECT_NEAR(b.centre.y, 0.0, 1e-3);
    EXPECT_NEAR(b.blocked_at.x, 0.0, 1e-4);
    EXPECT_EQ(health.errors(), 1u);
    const CheckItem& crossings = *health.item("portal_crossings");
    EXPECT_FALSE(crossings.passed());
    // Its place: the portal's two regions and its centre, where a viewer goes to look.
    ASSERT_EQ(crossings.places.size(), 1u);
    EXPECT_EQ(crossings.places[0].region, b.regions[0]);
    EXPECT_EQ(crossings.places[0].other, b.regions[1]);
    ASSERT_TRUE(crossings.places[0].has_point);
    EXPECT_EQ(crossings.places[0].point, glm::vec3(b.centre));
}

TEST(ZoneCheck, TheSamePlaneLeavesTheCrossingOpen)
{
    const ZoneHealth health = check_zone(split_box(0.0f));
    EXPECT_EQ(health.tree_crossings.traced, 1u);
    EXPECT_TRUE(health.tree_crossings.blocked.empty());
    EXPECT_EQ(health.errors(), 0u);
    EXPECT_TRUE(health.item("tree")->passed());
    EXPECT_FALSE(health.item("pvs_rows")->applicable);
    EXPECT_EQ(health.item("faces")->failed, 2u); // neither region lists a face
    ASSERT_EQ(health.item("faces")->places.size(), 2u);
    EXPECT_EQ(health.item("faces")->places[1].region, 1);
}

TEST(ZoneCheck, ABrokenTreeIsAnErrorAndIsNotPortalized)
{
    Zone zone = split_box(0.0f);
    zone.tree.nodes[3].children[0] = 1; // a cycle
    zone.tree.leaf_region[0] = 7;       // a region that does not exist (every wall reaches leaf 0)
    const ZoneHealth health = check_zone(zone);
    EXPECT_FALSE(health.item("tree")->passed());
    EXPECT_GE(health.item("tree")->failed, 2u);
    EXPECT_FALSE(health.item("portal_crossings")->applicable);
    EXPECT_GE(health.errors(), 1u);
}

// Every crossing of `zone`'s portals open: the invariant every real level must keep.
void expect_every_crossing_open(const Zone& zone, const std::string& what)
{
    const CrossingReport r = trace_portal_crossings(zone, build_zone_portals(zone));
    EXPECT_GT(r.traced, 0u) << what;
    EXPECT_GE(double(r.traced), 0.9 * double(r.portals - r.opaque)) << what << ": most crossings placed";
    for (size_t i = 0; i < std::min<size_t>(r.blocked.size(), 5); ++i) {
        const BlockedCrossing& b = r.blocked[i];
        ADD_FAILURE() << what << ": crossing of portal " << b.portal << " (regions " << b.regions[0] << " | "
                      << b.regions[1] << ") at (" << b.centre.x << ", " << b.centre.y << ", " << b.centre.z
                      << ") blocked at (" << b.blocked_at.x << ", " << b.blocked_at.y << ", " << b.blocked_at.z << ")";
    }
    EXPECT_EQ(r.blocked.size(), 0u) << what << ": " << r.traced << " traced";
}

class QuakeCrossings : public ::testing::TestWithParam<const char*> {};

TEST_P(QuakeCrossings, EveryPortalCrossingIsOpen)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const Zone zone = load_zone(path);
    expect_every_crossing_open(zone, GetParam());
    const ZoneHealth health = check_zone(zone);
    EXPECT_EQ(health.errors(), 0u) << GetParam();
    EXPECT_TRUE(health.item("leaks")->passed()) << GetParam() << ": a Quake map as compiled is sealed";
    EXPECT_TRUE(health.item("pvs_self")->passed()) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(SharedLevels, QuakeCrossings,
                         ::testing::Values("quake/e1m1.bsp", "quake/e1m2.bsp", "quake/e2m1.bsp", "quake/dm2.bsp",
                                           "quake/start.bsp", "quake/end.bsp", "visdemo/example.bsp",
                                           "modern-quake/q1/lqdm2.bsp", "modern-quake/q1/lqdm5.bsp"),
                         [](const testing::TestParamInfo<const char*>& p) { return test::param_name(p.param); });

TEST(ZoneCheck, ConvertedAndGeneratedEverQuestZonesHaveEveryCrossingOpen)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path();
    gen::GenParams params{120, 7, 32.0f, true};
    params.bake_threads = 2;
    const Zone generated = gen::generate_zone(params);
    const std::string gen_path = (dir / "pvscope_check_gen.s3d").string();
    write_zone(generated, gen_path, ZoneOutput::S3d);
    const Zone generated_eq = load_zone(gen_path);
    std::filesystem::remove(gen_path);
    expect_every_crossing_open(generated_eq, "generated .s3d");
    const ZoneHealth health = check_zone(generated_eq);
    EXPECT_EQ(health.errors(), 0u);
    EXPECT_TRUE(health.item("pvs_neighbours")->passed()) << "portal-full holds every neighbour";

    SHARED_DATA_OR_SKIP(e1m1, "quake/e1m1.bsp");
    const std::string converted_path = (dir / "pvscope_check_e1m1.s3d").string();
    write_zone(*test::shared_zone("quake/e1m1.bsp"), converted_path, ZoneOutput::S3d);
    const Zone converted = load_zone(converted_path);
    std::filesystem::remove(converted_path);
    expect_every_crossing_open(converted, "e1m1 converted to .s3d");
}

TEST(ZoneCheck, EveryFreedoomMapHasEveryCrossingOpenWithGlbspAndZdbspNodes)
{
    size_t maps = 0;
    for (const char* iwad : {"freedoom1.wad", "freedoom2.wad"}) {
        FREEDOOM_OR_SKIP(wad_path, iwad);
        for (test::GlBuilder builder : {test::GlBuilder::glbsp_v2, test::GlBuilder::zdbsp_v5}) {
            GL_NODES_OR_SKIP(gl_path, wad_path, builder);
            const bool separate = gl_path.ends_with(".gwa");
            const doom::WadFile wad = doom::read_wad(separate ? wad_path : gl_path);
            const std::optional<doom::WadFile> gl =
                separate ? std::optional<doom::WadFile>(doom::read_wad(gl_path)) : std::nullopt;
            for (const std::string& name : doom::map_names(wad)) {
                const Zone zone = doom::build_doom_zone(doom::read_doom_map(wad, gl ? &*gl : nullptr, name), nullptr);
                expect_every_crossing_open(zone, std::string(iwad) + " " + name + " " + test::gl_builder_name(builder));
                ++maps;
            }
        }
    }
    EXPECT_EQ(maps, 2u * (36 + 32));
}

// glVIS's own GL_PVS of MAP10 (made elsewhere: ../shared/data/doom): 525 297 set bits (its README),
// every row holding its subsector and every neighbour across an opening; glVIS's flow is not
// symmetric, and the check counts the bits without a reverse.
TEST(ZoneCheck, GlVisPvsOfMap10HoldsItsNeighboursAndItsKnownBits)
{
    SHARED_DATA_OR_SKIP(gwa, "doom/freedoom2-MAP10.glvis.gwa");
    FREEDOOM_OR_SKIP(wad, "freedoom2.wad");
    ZoneLoadOptions options;
    options.map = "MAP10";
    options.gwa = gwa;
    const Zone zone = load_zone(wad, options);
    const ZoneHealth health = check_zone(zone);
    EXPECT_EQ(health.errors(), 0u);
    EXPECT_EQ(health.warnings(), 0u);
    EXPECT_EQ(health.item("pvs_symmetry")->checked, 525297u);
    EXPECT_GT(health.item("pvs_symmetry")->failed, 0u);
    EXPECT_EQ(health.item("pvs_neighbours")->failed, 0u);
    EXPECT_GT(health.item("pvs_neighbours")->checked, 10000u);
    EXPECT_EQ(health.item("pvs_self")->failed, 0u);
}

// A row that lacks a neighbour across a portal is a warning (a camera crossing there would see
// the region pop in), and the only failed check.
TEST(ZoneCheck, ARowWithoutItsPortalNeighbourIsAWarning)
{
    Zone zone = split_box(0.0f);
    zone.baked_pvs = Pvs::build(2, [](uint32_t r, std::span<uint64_t> row) {
        row[0] = r == 0 ? 0b01u : 0b11u; // 0 sees only itself; 1 sees both
        return true;
    });
    const ZoneHealth health = check_zone(zone);
    EXPECT_EQ(health.errors(), 0u);
    EXPECT_EQ(health.warnings(), 1u);
    EXPECT_EQ(health.item("pvs_neighbours")->failed, 1u);
    EXPECT_EQ(health.item("pvs_neighbours")->examples.at(0), "0 -> 1");
    ASSERT_EQ(health.item("pvs_neighbours")->places.size(), 1u) << "one place per example";
    EXPECT_EQ(health.item("pvs_neighbours")->places[0].region, 0);
    EXPECT_EQ(health.item("pvs_neighbours")->places[0].other, 1);
    EXPECT_EQ(health.item("pvs_symmetry")->failed, 1u) << "1 sees 0, 0 does not see 1";
    EXPECT_EQ(health.item("pvs_symmetry")->places.at(0).region, 1);
    EXPECT_TRUE(health.item("pvs_self")->passed());
}

} // namespace
} // namespace pvs
