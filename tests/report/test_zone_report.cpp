// The JSON report of `pvscope info --json`: stable field names with the values of e1m1's
// known answers (../shared/data/README.md), and a report for an empty zone.
#include "report/zone_report.h"
#include "tests/support/test_data.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

namespace pvs {
namespace {

TEST(ZoneReport, E1m1ReportCarriesTheKnownAnswers)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    const Zone zone = load_zone(path);
    const nlohmann::json report = zone_report_json(zone, compute_zone_stats(zone), 1.0);
    EXPECT_EQ(report["format"], "Quake BSP");
    EXPECT_EQ(report["version"], "29");
    EXPECT_EQ(report["counts"]["regions"], 1206);
    EXPECT_EQ(report["counts"]["nodes"], 2912);
    EXPECT_EQ(report["counts"]["solid_leaves"], 1);
    EXPECT_EQ(report["region_flags"]["water"], 33);
    EXPECT_EQ(report["region_flags"]["slime"], 108);
    EXPECT_EQ(report["region_flags"]["sky"], 44);
    EXPECT_EQ(report["source_counts"]["leaves.empty"], 1407);
    EXPECT_TRUE(report["pvs"]["present"]);
    EXPECT_NEAR(report["pvs"]["mean_visible"].get<double>(), 142.0, 0.05);
    EXPECT_NEAR(report["pvs"]["mean_visible_percent"].get<double>(), 11.8, 0.05);
    EXPECT_EQ(report["zone_lines"][0]["target"], "e1m2");
    EXPECT_GT(report["tree"]["max_depth"].get<int>(), 0);
    EXPECT_GT(report["memory_bytes"].get<size_t>(), 1000000u);
    EXPECT_EQ(report["bounds"]["min"].size(), 3u);
}

TEST(ZoneReport, EmptyZoneHasNoPvsAndNoBounds)
{
    Zone zone;
    zone.tree.leaf_region = {kLeafOutside};
    zone.tree.root = ~0;
    zone.region_face_offsets = {0};
    const ZoneStats stats = compute_zone_stats(zone);
    const nlohmann::json report = zone_report_json(zone, stats, 0.0);
    EXPECT_EQ(report["counts"]["regions"], 0);
    EXPECT_EQ(report["counts"]["outside_leaves"], 1);
    EXPECT_FALSE(report["pvs"]["present"]);
    EXPECT_FALSE(report.contains("bounds"));
}

} // namespace
} // namespace pvs
