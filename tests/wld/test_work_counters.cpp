// The regression net for the bakes' speed: their work counters (frames the flow enters, windings
// clipped, separators used, ...: MethodRun::fields under "work.") on every map of the project's
// test data and of Freedoom, against the committed baseline tests/baselines/work_counters.tsv.
// Counts are deterministic (the same at any thread count, on any machine), so unlike a timed test
// they cannot be fooled by a loaded or slower host: a count more than 5 % above its baseline fails,
// naming the map, the counter and both values. A count more than 5 % below passes with a note, so
// the baseline is tightened in a commit that says why; changing it is always such a commit.
//
// To rewrite the baseline after a deliberate change: tests/support/work_baseline.h.
//
// The bakes are what users run: `pvscope bake MAP --method portal-full` on maps without a portal
// file (from the tree, Quake's default sky rule; Doom maps in the plane), `pvscope vis MAP` on maps
// with qbsp's .prt beside them (over its clusters for PRT2 and Quake 2).
#include "tests/support/freedoom.h"
#include "tests/support/test_data.h"
#include "tests/support/work_baseline.h"
#include "visibility/methods/vis_method.h"
#include "wld/common/read_file.h"
#include "wld/doom/doom_map.h"
#include "wld/doom/doom_zone.h"
#include "wld/doom/wad_file.h"
#include "wld/quake/prt_file.h"
#include "wld/quake2/ibsp38_file.h"
#include "wld/quake2/quake2_vis.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

namespace {

using namespace pvs;

std::map<std::string, uint64_t> work_of(const std::vector<ReportField>& fields)
{
    std::map<std::string, uint64_t> work;
    for (const ReportField& f : fields)
        if (f.name.starts_with(kWorkPrefix))
            work[f.name.substr(kWorkPrefix.size())] = std::get<uint64_t>(f.value);
    return work;
}

// `pvscope vis MAP` where the map has qbsp's portal file beside it: the registry's portal-full on
// the file's portals, over its clusters (PRT2 / PRT1-AM; a Quake 2 map's PRT1 names its clusters).
std::map<std::string, uint64_t> vis_with_portal_file(const std::string& path)
{
    const std::string prt_path = std::filesystem::path(path).replace_extension(".prt").string();
    const Zone zone = load_zone(path);
    quake::PrtFile prt = quake::load_prt(prt_path);
    PortalInput input;
    input.portals = std::move(prt.portals);
    if (prt.has_clusters()) {
        input.clusters = RegionClusters{std::move(prt.cluster_of_leaf), prt.cluster_count};
    } else if (const std::vector<uint8_t> bytes = read_whole_file(path); quake2::looks_like_ibsp38(bytes)) {
        const quake2::RegionClusterMap map = quake2::region_clusters(bytes, path, zone);
        input.clusters = RegionClusters{{map.cluster_of_region.begin(), map.cluster_of_region.end()}, map.clusters};
    }
    MethodSettings settings;
    settings.threads = 1; // the counts are the same at any count (WorkCounters.SameAtAnyThreadCount)
    settings.portals = &input;
    return work_of(find_vis_method("portal-full")->run(zone, settings).fields);
}

// `pvscope bake MAP --method portal-full`.
std::map<std::string, uint64_t> bake_portal_full(const Zone& zone, unsigned threads = 1)
{
    MethodSettings settings;
    settings.threads = threads;
    return work_of(find_vis_method("portal-full")->run(zone, settings).fields);
}

void check_against_baseline(const std::string& key, const std::map<std::string, uint64_t>& measured)
{
    test::check_work("work_counters.tsv", key, measured);
}

class QuakeWork : public testing::TestWithParam<const char*> {};

TEST_P(QuakeWork, WithinBaseline)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const std::string prt = std::filesystem::path(path).replace_extension(".prt").string();
    if (std::filesystem::exists(prt))
        check_against_baseline(GetParam(), vis_with_portal_file(path));
    else
        check_against_baseline(GetParam(), bake_portal_full(*test::shared_zone(GetParam())));
}

INSTANTIATE_TEST_SUITE_P(SharedMaps, QuakeWork,
                         testing::Values("quake/e1m1.bsp", "quake/e1m2.bsp", "quake/e2m1.bsp", "quake/dm2.bsp",
                                         "quake/start.bsp", "quake/end.bsp", "visdemo/example.bsp",
                                         "modern-quake/q1/lqdm2.bsp", "modern-quake/q1/lqdm2-bsp2.bsp",
                                         "modern-quake/q1/lqdm2-2psb.bsp", "modern-quake/q1/lqdm5.bsp",
                                         "modern-quake/q1/lq_e1m1.bsp", "modern-quake/q1/lq_e2m2.bsp",
                                         "modern-quake/q2/q2_liquids.bsp", "modern-quake/q2/q2_areaportals.bsp",
                                         "modern-quake/q2/q2_tjunc_matrix.bsp", "modern-quake/q2/lqdm2-q2.bsp",
                                         "modern-quake/q2/lqdm5-q2.bsp"),
                         [](const testing::TestParamInfo<const char*>& p) { return test::param_name(p.param); });

// Freedoom's maps through the 2-D flow, glbsp's GL nodes. MAP12, whose bake under the sanitizers
// takes minutes, is left to the benchmark (docs/performance.md gives the command).
struct DoomCase {
    std::string wad, map;
};

void PrintTo(const DoomCase& c, std::ostream* out) { *out << c.wad << ':' << c.map; }

class DoomWork : public testing::TestWithParam<DoomCase> {};

TEST_P(DoomWork, WithinBaseline)
{
    FREEDOOM_OR_SKIP(wad, GetParam().wad);
    GL_NODES_OR_SKIP(gwa, wad, test::GlBuilder::glbsp_v2);
    const doom::OpenedMap opened = doom::open_doom_map(wad, GetParam().map, gwa);
    const Zone zone = doom::build_doom_zone(opened.map, nullptr);
    check_against_baseline(GetParam().wad + ":" + GetParam().map, bake_portal_full(zone));
}

std::vector<DoomCase> doom_cases()
{
    std::vector<DoomCase> cases;
    char name[8];
    for (int e = 1; e <= 4; ++e)
        for (int m = 1; m <= 9; ++m) {
            std::snprintf(name, sizeof name, "E%dM%d", e, m);
            cases.push_back({"freedoom1.wad", name});
        }
    for (int m = 1; m <= 32; ++m) {
        std::snprintf(name, sizeof name, "MAP%02d", m);
        if (m != 12)
            cases.push_back({"freedoom2.wad", name});
    }
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Freedoom, DoomWork, testing::ValuesIn(doom_cases()),
                         [](const testing::TestParamInfo<DoomCase>& p) {
                             std::string name = std::filesystem::path(p.param.wad).stem().string();
                             name += '_';
                             name += p.param.map;
                             return name;
                         });

// The counts are a fixed function of the input: the same at 1 and 3 threads.
TEST(WorkCounters, SameAtAnyThreadCount)
{
    const Zone* e1m1 = test::shared_zone("quake/end.bsp");
    if (!e1m1) {
        SHARED_DATA_OR_SKIP(path, "quake/end.bsp");
    }
    EXPECT_EQ(bake_portal_full(*e1m1, 1), bake_portal_full(*e1m1, 3));
    FREEDOOM_OR_SKIP(wad, "freedoom2.wad");
    GL_NODES_OR_SKIP(gwa, wad, test::GlBuilder::glbsp_v2);
    const Zone map01 = doom::build_doom_zone(doom::open_doom_map(wad, "MAP01", gwa).map, nullptr);
    EXPECT_EQ(bake_portal_full(map01, 1), bake_portal_full(map01, 3));
}

} // namespace
