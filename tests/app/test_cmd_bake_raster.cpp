// `pvscope bake --method raster` as a user runs it:
//  - on the HateEngine E1M1.obj with --cell 8 --grid-size 16: a .hepvs on the shared file's own
//    grid (min, cell size, counts), over the OBJ's object names, readable back with the OBJ;
//  - on a generated .s3d (regions as cells): the zone written back with the raster rows;
//  - an OBJ level asked for a portal method is refused with the reason (no BSP tree);
//  - --device: gpu draws on the GPU (the summary names it) and writes the rows the GPU path
//    bakes; refused for methods that draw nothing and for shards that could draw on different
//    devices (auto).
#include "app/cmd_bake.h"

#include "app/bake_options.h"
#include "tests/app/bake_command_fixture.h"
#include "tests/support/gpu_driver.h"
#include "tests/support/test_data.h"
#include "visibility/methods/vis_method.h"
#include "wld/common/read_file.h"
#include "wld/hepvs/hepvs_file.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>


namespace pvs::test {
namespace {

using BakeRaster = BakeCommand;

TEST_F(BakeRaster, ObjLevelToHepvsOnTheSharedGrid)
{
    SHARED_DATA_OR_SKIP(obj, "hateengine/E1M1.obj");
    SHARED_DATA_OR_SKIP(shared_hepvs, "hateengine/E1M1.hepvs");
    app::BakeOptions o;
    o.input = obj;
    o.output = path("out.hepvs");
    o.method = "raster";
    o.cell = 8.0f;
    o.grid_size = 16.0f;
    o.resolution = 16;
    o.threads = 2;
    ASSERT_EQ(run(o), 0) << err_;
    const HepvsFile ours = read_hepvs(read_whole_file(o.output), o.output);
    const HepvsFile theirs = read_hepvs(read_whole_file(shared_hepvs), shared_hepvs);
    EXPECT_EQ(ours.min, theirs.min);
    EXPECT_EQ(ours.cell_size, theirs.cell_size);
    EXPECT_EQ(ours.counts, theirs.counts);
    EXPECT_EQ(ours.names.size(), theirs.names.size());
    EXPECT_GT(ours.cell_objects.size(), ours.cell_count()); // cells see something
    ZoneLoadOptions load;
    load.hepvs = o.output;
    const Zone back = load_zone(obj, load);
    ASSERT_TRUE(back.baked_pvs);
    EXPECT_EQ(back.baked_pvs->row_count(), theirs.cell_count());

    o.method = "portal-full";
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find("needs a BSP tree"), std::string::npos) << err_;
    o.method = "raster";
    o.output = path("out.bsp");
    EXPECT_EQ(run(o), 2) << err_; // an OBJ's PVS is written as a .hepvs
}

TEST_F(BakeRaster, GeneratedZoneOverRegions)
{
    app::BakeOptions o = bake_generated({8, 3}, "raster.s3d");
    o.method = "raster";
    o.resolution = 16;
    o.points = 4;
    ASSERT_EQ(run(o), 0) << err_;
    EXPECT_NE(err_.find("raster:"), std::string::npos) << err_;
    const Zone back = load_zone(o.output);
    ASSERT_TRUE(back.baked_pvs);
    EXPECT_EQ(back.baked_pvs->row_count(), back.region_count());
}

TEST_F(BakeRaster, DeviceChoice)
{
    app::BakeOptions o = bake_generated({8, 3}, "gpu.s3d");
    o.method = "portal-full";
    o.device = "gpu";
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find("only the raster method draws on a GPU"), std::string::npos) << err_;
    o.method = "raster";
    o.device = "auto";
    o.shard = "0/2";
    o.output = path("part.pvsp");
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find("name the device"), std::string::npos) << err_;
    o.shard.clear();
    o.output = path("gpu.s3d");
    o.device = "sideways";
    EXPECT_EQ(run(o), 2);

    GPU_DRIVER_OR_SKIP();
    o.device = "gpu";
    o.resolution = 16;
    o.points = 4;
    ASSERT_EQ(run(o), 0) << err_;
    EXPECT_NE(err_.find("(gpu: "), std::string::npos) << err_;
    const Zone back = load_zone(o.output);
    ASSERT_TRUE(back.baked_pvs);
    MethodSettings settings = app::bake_method_settings(o);
    const MethodRun direct = find_vis_method("raster")->run(load_zone(o.input), settings);
    ASSERT_TRUE(direct.pvs);
    for (uint32_t r = 0; r < back.region_count(); ++r)
        for (uint32_t s = 0; s < back.region_count(); ++s)
            ASSERT_EQ(back.baked_pvs->visible(r, s), direct.pvs->visible(r, s)) << r << " -> " << s;
}

} // namespace
} // namespace pvs::test
