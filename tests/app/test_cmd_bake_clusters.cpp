// `pvscope bake --clusters none|auto` (app/cmd_bake.h) through its command function:
//  - a generated zone written as .s3d and baked with --clusters auto: its regions are boxes, so
//    the rows read back from OUT.s3d are the clustered bake of the same portals over
//    box_merge_clusters (computed here with the library directly) and constant within each
//    cluster; the report names the clusters;
//  - visdemo's example.bsp with --clusters auto: a Quake map is baked per leaf, with a note;
//  - --write-prt after a clustered bake writes PRT2 (the box clusters as its cluster map), and
//    baking again from that file with --prt gives the same rows;
//  - a bad --clusters value: exit code 2, a message, nothing written.
#include "app/cmd_bake.h"

#include "tests/app/bake_command_fixture.h"

#include "tests/support/test_data.h"
#include "visibility/portal/box_clusters.h"
#include "visibility/portal/cluster_vis.h"
#include "visibility/portal/portal_vis.h"
#include "visibility/portal/portalize.h"
#include "wld/quake/bsp29_reader.h"
#include "wld/quake/prt_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace pvs {
namespace {

namespace fs = std::filesystem;
using test::Rows;

using test::rows_of;

class BakeClusters : public test::BakeCommand {};

TEST_F(BakeClusters, AGeneratedZoneIsBakedOverBoxClusters)
{
    app::BakeOptions o = bake_generated({30, 5, 32.0f}, "baked.s3d");
    o.report = path("report.json");
    o.clusters = "auto";
    ASSERT_EQ(run(o), 0) << err_;

    const Zone in = test::load_s3d(o.input);
    const Zone out = test::load_s3d(o.output);
    ASSERT_TRUE(out.baked_pvs.has_value());
    const PortalSet portals = build_zone_portals(in);
    ASSERT_TRUE(regions_are_boxes(in.regions, portals));
    const RegionClusters clusters = box_merge_clusters(in.regions, portals);
    ASSERT_LT(clusters.cluster_count, in.region_count());
    VisParams params;
    params.threads = 1;
    const Pvs expected =
        bake_clustered_portal_vis(portals, clusters.cluster_of_region, clusters.cluster_count, params);
    const Rows rows = rows_of(*out.baked_pvs);
    EXPECT_EQ(rows, rows_of(expected));
    for (uint32_t r = 1; r < in.region_count(); ++r)
        for (uint32_t s = 0; s < r; ++s)
            if (clusters.cluster_of_region[r] == clusters.cluster_of_region[s]) {
                EXPECT_EQ(rows[r], rows[s]) << "regions " << s << " and " << r << " share a cluster";
                break;
            }

    std::ifstream report_file(o.report);
    const nlohmann::json report = nlohmann::json::parse(report_file);
    ASSERT_TRUE(report["clusters"].is_object());
    EXPECT_EQ(report["clusters"]["clusters"], clusters.cluster_count);
    EXPECT_NE(err_.find("box clusters"), std::string::npos) << err_;
}

TEST_F(BakeClusters, AClusteredBakeWritesPrt2AndBakesTheSameFromIt)
{
    app::BakeOptions o = bake_generated({20, 9, 32.0f}, "baked.s3d");
    o.prt_out = path("clusters.prt");
    o.clusters = "auto";
    ASSERT_EQ(run(o), 0) << err_;

    const Zone in = test::load_s3d(o.input);
    const PortalSet portals = build_zone_portals(in);
    const RegionClusters clusters = box_merge_clusters(in.regions, portals);
    const quake::PrtFile prt = quake::load_prt(o.prt_out);
    EXPECT_EQ(prt.version, quake::PrtVersion::Prt2);
    EXPECT_EQ(prt.leaf_count, in.region_count());
    EXPECT_EQ(prt.cluster_count, clusters.cluster_count);
    EXPECT_EQ(prt.cluster_of_leaf, clusters.cluster_of_region);
    size_t between_clusters = 0;
    for (const Portal& portal : portals.portals)
        between_clusters += clusters.cluster_of_region[size_t(portal.regions[0])] !=
                            clusters.cluster_of_region[size_t(portal.regions[1])];
    EXPECT_EQ(prt.portals.portals.size(), between_clusters);

    app::BakeOptions again = o;
    again.output = path("again.s3d");
    again.prt_out.clear();
    again.prt_in = o.prt_out;
    again.clusters = "none"; // the file's clusters are used anyway
    ASSERT_EQ(run(again), 0) << err_;
    const Zone first = test::load_s3d(o.output);
    const Zone second = test::load_s3d(again.output);
    ASSERT_TRUE(first.baked_pvs && second.baked_pvs);
    EXPECT_EQ(rows_of(*second.baked_pvs), rows_of(*first.baked_pvs));
}

TEST_F(BakeClusters, AQuakeMapIsBakedPerLeafEvenWithAuto)
{
    SHARED_DATA_OR_SKIP(input, "visdemo/example.bsp");
    app::BakeOptions o;
    o.input = input;
    o.output = path("out.bsp");
    o.report = path("report.json");
    o.clusters = "auto";
    o.threads = 1;
    ASSERT_EQ(run(o), 0) << err_;
    EXPECT_NE(err_.find("baked per leaf"), std::string::npos) << err_;

    const Zone zone = quake::load_bsp29(test::read_bytes(input), input);
    const Zone out = quake::load_bsp29(test::read_bytes(o.output), o.output);
    VisParams params;
    params.threads = 1;
    const Pvs expected = bake_portal_vis(build_zone_portals(zone), uint32_t(zone.region_count()), params);
    ASSERT_TRUE(out.baked_pvs.has_value());
    EXPECT_EQ(rows_of(*out.baked_pvs), rows_of(expected));
    std::ifstream report_file(o.report);
    EXPECT_TRUE(nlohmann::json::parse(report_file)["clusters"].is_null());
}

TEST_F(BakeClusters, ABadClustersValueIsRefused)
{
    app::BakeOptions o;
    o.input = path("missing.s3d");
    o.output = path("out.s3d");
    o.clusters = "maybe";
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find("--clusters must be none or auto, not 'maybe'"), std::string::npos) << err_;
    EXPECT_FALSE(fs::exists(o.output));
}

} // namespace
} // namespace pvs
