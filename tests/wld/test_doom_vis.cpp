// 2-D portal vis on Doom maps (visibility/portal/portal_vis_2d.h through the method registry):
// a hand-made map whose visibility is known by construction, with GL nodes made by glbsp (data
// made elsewhere from our WAD); full within fast, the reference within full, the same rows on
// 1, 2 and 3 threads; the --heights option on a closed door; and on a Freedoom map, nothing
// the reference finds is missing.
#include "tests/support/freedoom.h"
#include "tests/wld/doom_test_maps.h"
#include "visibility/bit_row.h"
#include "visibility/methods/vis_method.h"
#include "wld/common/read_file.h"
#include "wld/doom/doom_map.h"
#include "wld/doom/doom_zone.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace {

using namespace pvs;
using namespace pvs::doom;
using pvs::test::GlBuilder;
using namespace pvs::doom_test;

struct HandMade {
    Zone zone;
    std::vector<uint32_t> sector_of; // per subsector
};

std::optional<HandMade> load_hand_made(bool door_closed)
{
    const std::string wad = (std::filesystem::temp_directory_path() /
                             ("pvscope-doom-vis-" + std::to_string(getpid()) + (door_closed ? "-door" : "") + ".wad"))
                                .string();
    write_whole_file(wad, hand_made_wad(door_closed));
    const auto gwa = pvs::test::gl_nodes_file(wad, GlBuilder::glbsp_v2);
    if (!gwa)
        return std::nullopt;
    const WadFile w = read_wad(wad), g = read_wad(*gwa);
    const DoomMap map = read_doom_map(w, &g, "MAP01");
    HandMade out{build_doom_zone(map, nullptr), {}};
    for (const GlSubsector& ss : map.subsectors)
        out.sector_of.push_back(ss.sector);
    return out;
}

Pvs run(const Zone& zone, const char* method, unsigned threads = 2, bool heights = false, uint64_t samples = 0)
{
    MethodSettings s;
    s.threads = threads;
    s.heights = heights;
    s.samples = samples;
    MethodRun r = find_vis_method(method)->run(zone, s);
    return std::move(*r.pvs);
}

// Does any subsector of sector `from` see any of sector `to`?
bool sector_sees(const HandMade& m, const Pvs& pvs, uint32_t from, uint32_t to)
{
    for (uint32_t i = 0; i < m.sector_of.size(); ++i)
        for (uint32_t j = 0; j < m.sector_of.size(); ++j)
            if (m.sector_of[i] == from && m.sector_of[j] == to && pvs.visible(i, j))
                return true;
    return false;
}

size_t bits_outside(const Pvs& inner, const Pvs& outer)
{
    size_t n = 0;
    for (uint32_t i = 0; i < inner.region_count(); ++i)
        for (uint32_t j = 0; j < inner.region_count(); ++j)
            n += inner.visible(i, j) && !outer.visible(i, j);
    return n;
}

#define HAND_MADE_OR_SKIP(var, closed)                                                                        \
    auto var##_loaded = load_hand_made(closed);                                                               \
    if (!var##_loaded) {                                                                                      \
        if (pvs::test::shared_data_required()) {                                                              \
            FAIL() << "glbsp could not build the hand-made map";                                              \
        }                                                                                                     \
        GTEST_SKIP() << "SKIPPED: needs glbsp (apt-get install glbsp)";                                       \
    }                                                                                                         \
    const HandMade& var = *var##_loaded

TEST(DoomVis, HandMadeMapSeesWhatItsLayoutAllows)
{
    HAND_MADE_OR_SKIP(m, false);
    ASSERT_GE(m.zone.region_count(), 5u);
    const Pvs full = run(m.zone, "portal-full");
    // Hidden by construction, both ways.
    for (auto [a, b] : {std::pair{kA, kC}, {kA, kE}, {kC, kD}, {kD, kE}}) {
        EXPECT_FALSE(sector_sees(m, full, a, b)) << a << " -> " << b;
        EXPECT_FALSE(sector_sees(m, full, b, a)) << b << " -> " << a;
    }
    // Open by construction.
    for (auto [a, b] : {std::pair{kA, kD}, {kA, kB}, {kD, kB}, {kB, kE}, {kB, kC}, {kE, kC}})
        EXPECT_TRUE(sector_sees(m, full, a, b)) << a << " -> " << b;
    // Within a convex sector everything is visible.
    for (uint32_t i = 0; i < m.sector_of.size(); ++i)
        for (uint32_t j = 0; j < m.sector_of.size(); ++j)
            if (m.sector_of[i] == m.sector_of[j]) {
                EXPECT_TRUE(full.visible(i, j)) << i << " " << j;
            }
}

TEST(DoomVis, FullWithinFastReferenceWithinFullSameOnAnyThreadCount)
{
    HAND_MADE_OR_SKIP(m, false);
    const Pvs fast = run(m.zone, "portal-fast");
    const Pvs full1 = run(m.zone, "portal-full", 1), full2 = run(m.zone, "portal-full", 2),
              full3 = run(m.zone, "portal-full", 3);
    const Pvs reference = run(m.zone, "reference", 2, false, 4096);
    EXPECT_EQ(bits_outside(full2, fast), 0u);
    EXPECT_EQ(bits_outside(reference, full2), 0u);
    EXPECT_EQ(bits_outside(full1, full2) + bits_outside(full2, full1), 0u);
    EXPECT_EQ(bits_outside(full3, full2) + bits_outside(full2, full3), 0u);
    // The reference is not trivial: it found the open pairs too.
    EXPECT_TRUE(sector_sees(m, reference, kA, kB));
    EXPECT_TRUE(sector_sees(m, reference, kB, kC));
}

TEST(DoomVis, ClosedDoorBlocksOnlyWithHeights)
{
    HAND_MADE_OR_SKIP(m, true);
    const Pvs flat = run(m.zone, "portal-full");
    const Pvs heights = run(m.zone, "portal-full", 2, true);
    EXPECT_TRUE(sector_sees(m, flat, kB, kC)) << "glVIS ignores heights: a closed door does not block";
    EXPECT_FALSE(sector_sees(m, heights, kB, kC)) << "with heights, E's closed door hides C from B";
    EXPECT_FALSE(sector_sees(m, heights, kC, kB));
    EXPECT_TRUE(sector_sees(m, heights, kA, kB));
    EXPECT_EQ(bits_outside(heights, flat), 0u) << "heights only remove sight lines";
}

TEST(DoomVis, Freedoom2Map01MissesNothingTheReferenceFinds)
{
    FREEDOOM_OR_SKIP(wad_path, "freedoom2.wad");
    GL_NODES_OR_SKIP(gwa_path, wad_path, GlBuilder::glbsp_v2);
    const WadFile wad = read_wad(wad_path), gwa = read_wad(gwa_path);
    const Zone zone = build_doom_zone(read_doom_map(wad, &gwa, "MAP01"), nullptr);
    const Pvs full = run(zone, "portal-full");
    const Pvs fast = run(zone, "portal-fast");
    const Pvs reference = run(zone, "reference", 2, false, 256);
    EXPECT_EQ(bits_outside(reference, full), 0u);
    EXPECT_EQ(bits_outside(full, fast), 0u);
    EXPECT_LT(bits_outside(full, fast) + 1, bits_outside(fast, full)) << "full is tighter than fast";
}

} // namespace
