// Conservative means 0 missing: on every shared level and the Freedoom maps the docs measure,
// the converged sampled reference (a lower bound: every bit a traced sight line, open as a beam
// of kBeamMargin) lies within every method that claims to be an upper bound. Labelled "slow"
// (ctest -L slow): the converged reference takes seconds to tens of seconds a map (e1m1 about
// 20 s on 2 cores in Release, several times that under the sanitizers), so it runs in its own
// ctest step, not in the default one.
#include "tests/support/freedoom.h"
#include "tests/support/test_data.h"
#include "visibility/eval/pvs_gap.h"
#include "visibility/methods/vis_method.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace pvs {
namespace {

struct Level {
    const char* path;   // under shared/data, or a Freedoom IWAD
    const char* map;    // Doom: the map; empty otherwise
    SkyPortals sky;     // the content rule the level's vis used (id's maps: sky opaque)
};

std::string level_name(const Level& level)
{
    return level.map[0] ? std::string(level.map) : test::param_name(level.path);
}

Pvs run(const Zone& zone, const char* method, const Level& level, bool heights = false)
{
    MethodSettings settings;
    settings.sky = level.sky;
    settings.threads = 2;
    settings.heights = heights;
    MethodRun r = find_vis_method(method)->run(zone, settings);
    EXPECT_TRUE(r.pvs.has_value()) << method;
    std::printf("[ %s ] %s%s\n", level_name(level).c_str(), r.summary.c_str(), heights ? " (heights)" : "");
    return std::move(*r.pvs);
}

void expect_within(const Pvs& reference, const Pvs& method, const std::string& what)
{
    const PvsGap gap = pvs_gap(&method, reference);
    std::string pairs; // appended piecewise: GCC 12 warns (-Wrestrict) on `" " + std::to_string(a)` inlined
    for (const auto& [a, b] : gap.missing_pairs)
        pairs.append(" ").append(std::to_string(a)).append("->").append(std::to_string(b));
    EXPECT_EQ(gap.missing_bits, 0u) << what << " lacks reference bits:" << pairs;
    std::printf("    %s: %llu bits, %llu above the reference's %llu\n", what.c_str(),
                static_cast<unsigned long long>(gap.bits), static_cast<unsigned long long>(gap.excess_bits),
                static_cast<unsigned long long>(gap.reference_bits));
}

class ConservativeMethods : public testing::TestWithParam<Level> {};

TEST_P(ConservativeMethods, HoldEveryBitOfTheConvergedReference)
{
    const Level& level = GetParam();
    Zone zone;
    if (level.map[0]) {
        FREEDOOM_OR_SKIP(wad, level.path);
        GL_NODES_OR_SKIP(gwa, wad, test::GlBuilder::glbsp_v2);
        ZoneLoadOptions options;
        options.map = level.map;
        options.gwa = gwa;
        zone = load_zone(wad, options);
    } else {
        SHARED_DATA_OR_SKIP(path, level.path);
        zone = load_zone(path);
    }
    const Pvs reference = run(zone, "reference", level);
    expect_within(reference, run(zone, "portal-full", level), "portal-full");
    expect_within(reference, run(zone, "portal-fast", level), "portal-fast");
    if (zone.tree.has_height_nodes())
        expect_within(reference, run(zone, "portal-full", level, true), "portal-full --heights");
}

INSTANTIATE_TEST_SUITE_P(
    SharedLevels, ConservativeMethods,
    testing::Values(Level{"quake/e1m1.bsp", "", SkyPortals::None}, Level{"quake/e1m2.bsp", "", SkyPortals::None},
                    Level{"quake/e2m1.bsp", "", SkyPortals::None}, Level{"quake/start.bsp", "", SkyPortals::None},
                    Level{"quake/end.bsp", "", SkyPortals::None}, Level{"quake/dm2.bsp", "", SkyPortals::None},
                    Level{"visdemo/example.bsp", "", SkyPortals::SkyToSky},
                    Level{"modern-quake/q1/lqdm2.bsp", "", SkyPortals::SkyToSky},
                    Level{"modern-quake/q1/lqdm5.bsp", "", SkyPortals::SkyToSky},
                    Level{"freedoom2.wad", "MAP10", SkyPortals::SkyToSky},
                    Level{"freedoom2.wad", "MAP28", SkyPortals::SkyToSky},
                    Level{"freedoom1.wad", "E3M7", SkyPortals::SkyToSky}),
    [](const testing::TestParamInfo<Level>& p) { return level_name(p.param); });

} // namespace
} // namespace pvs
