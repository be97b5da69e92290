// The batch behind `pvscope stats` (report/zone_batch.h, region_report.h) and the PVS
// percentiles of the zone report: a folder with a real map, a broken file and a Doom WAD with
// its .gwa; per-region counts checked against the PVS read bit by bit.
#include "report/region_report.h"
#include "report/zone_batch.h"
#include "tests/support/freedoom.h"
#include "tests/support/test_data.h"
#include "tests/wld/doom_test_maps.h"
#include "visibility/zone_stats.h"
#include "wld/common/read_file.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

namespace pvs {
namespace {

namespace fs = std::filesystem;

struct ScratchDir {
    fs::path dir = fs::temp_directory_path() / ("pvscope-batch-" + std::to_string(getpid()));
    ScratchDir() { fs::create_directories(dir / "sub"); }
    ~ScratchDir() { fs::remove_all(dir); }
};

TEST(ZoneBatch, FolderIsRecursedSortedAndBadFilesAreErrorItems)
{
    SHARED_DATA_OR_SKIP(e1m1, "quake/e1m1.bsp");
    ScratchDir scratch;
    fs::copy_file(e1m1, scratch.dir / "sub" / "e1m1.bsp");
    write_whole_file((scratch.dir / "broken.bsp").string(), {'B', 'S', 'P', '?', 1, 2, 3});
    write_whole_file((scratch.dir / "notes.txt").string(), {'h', 'i'});
    write_whole_file((scratch.dir / "x.hepvs").string(), {0});
    const std::vector<BatchItem> items = batch_items({scratch.dir.string(), (scratch.dir / "missing.bsp").string()});
    ASSERT_EQ(items.size(), 3u);
    EXPECT_EQ(fs::path(items[0].path).filename(), "broken.bsp");
    EXPECT_EQ(fs::path(items[1].path).filename(), "e1m1.bsp");
    EXPECT_EQ(items[2].error, "no such file or folder");

    const LoadedZone broken = load_batch_item(items[0]);
    EXPECT_FALSE(broken.zone);
    EXPECT_NE(broken.error.find("broken.bsp"), std::string::npos) << broken.error;
    const LoadedZone map = load_batch_item(items[1]);
    ASSERT_TRUE(map.zone) << map.error;
    EXPECT_EQ(map.zone->region_count(), load_zone(e1m1).region_count());
    EXPECT_GT(map.load_ms, 0.0);
}

TEST(ZoneBatch, AWadIsOneItemPerMap)
{
    ScratchDir scratch;
    const std::string wad = (scratch.dir / "hand.wad").string();
    write_whole_file(wad, doom_test::hand_made_wad(false));
    const auto gwa = test::gl_nodes_file(wad, test::GlBuilder::glbsp_v2);
    if (!gwa) {
        if (test::shared_data_required()) {
            FAIL() << "glbsp could not build the hand-made map";
        }
        GTEST_SKIP() << "SKIPPED: needs glbsp";
    }
    fs::copy_file(*gwa, scratch.dir / "hand.gwa");
    const std::vector<BatchItem> items = batch_items({scratch.dir.string()});
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items[0].map, "MAP01");
    const LoadedZone loaded = load_batch_item(items[0]);
    ASSERT_TRUE(loaded.zone) << loaded.error;
    EXPECT_GE(loaded.zone->region_count(), 5u);
}

TEST(RegionReport, CountsAgreeWithThePvsReadBitByBit)
{
    const Zone* zone = test::shared_zone("quake/e1m1.bsp");
    if (!zone) {
        if (test::shared_data_required()) {
            FAIL() << "missing quake/e1m1.bsp";
        }
        GTEST_SKIP() << "SKIPPED: needs ../shared/data/quake/e1m1.bsp";
    }
    ASSERT_TRUE(zone->baked_pvs);
    const std::vector<RegionRow> rows = region_rows(*zone);
    ASSERT_EQ(rows.size(), zone->region_count());
    const uint32_t n = uint32_t(rows.size());
    int64_t neighbour_total = 0;
    for (uint32_t r = 0; r < n; r += 37) { // a sample of rows keeps the O(n^2) check short
        int64_t visible = 0, from = 0;
        for (uint32_t j = 0; j < n; ++j) {
            visible += zone->baked_pvs->visible(r, j);
            from += zone->baked_pvs->visible(j, r);
        }
        EXPECT_EQ(rows[r].visible, visible) << r;
        EXPECT_EQ(rows[r].visible_from, from) << r;
        EXPECT_EQ(rows[r].faces, zone->faces_of_region(r).size());
    }
    for (const RegionRow& row : rows)
        neighbour_total += row.portal_neighbours;
    EXPECT_GT(neighbour_total, int64_t(n)); // a connected map: most leaves have two or more
    EXPECT_EQ(neighbour_total % 2, 0);      // each neighbour pair counted from both sides
    const CsvFields fields = region_fields(*zone, rows[0]);
    EXPECT_EQ(fields.front().first, "region");
    EXPECT_EQ(fields.back().first, "portal_neighbours");
}

TEST(ZoneStats, PvsPercentilesAreNearestRank)
{
    // Row r sees regions 0..r: counts 1..100 over 100 rows.
    const Pvs pvs = Pvs::build(100, [](uint32_t r, std::span<uint64_t> row) {
        std::fill(row.begin(), row.end(), 0);
        for (uint32_t j = 0; j <= r; ++j)
            row[j / 64] |= uint64_t(1) << (j % 64);
        return true;
    });
    const PvsDensity d = compute_pvs_density(pvs);
    EXPECT_EQ(d.min_visible, 1u);
    EXPECT_EQ(d.p50_visible, 50u);
    EXPECT_EQ(d.p90_visible, 90u);
    EXPECT_EQ(d.p99_visible, 99u);
    EXPECT_EQ(d.max_visible, 100u);
}

} // namespace
} // namespace pvs
