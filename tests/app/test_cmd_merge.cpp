// `pvscope bake --shard K/N` and `pvscope merge` as a user runs them: the merged file holds exactly
// the bytes of the one-machine bake (raster on a generated .s3d, the shared e1m1 .bsp with its
// ambient levels and the HateEngine OBJ grid's .hepvs; the per-source reference, whose parts are
// ORed, on a generated zone and e1m1), at any shard count, more shards than rows included;
// and every part that does not belong is refused with its name and what is wrong.
#include "app/cmd_merge.h"

#include "tests/app/bake_command_fixture.h"
#include "tests/support/test_data.h"
#include "wld/common/read_file.h"
#include "wld/pvs_part_file.h"

#include <gtest/gtest.h>

namespace pvs::test {
namespace {

class ShardMerge : public BakeCommand {
protected:
    int merge(const std::vector<std::string>& parts, const std::string& zone, const std::string& output)
    {
        app::MergeOptions m;
        m.parts = parts;
        m.zone = zone;
        m.output = output;
        std::FILE* err = std::tmpfile();
        const int code = app::run_merge(m, err);
        err_ = read_and_close(err);
        return code;
    }

    // Bakes `whole` on one machine, then as `shards` shards merged; the two files' bytes.
    void expect_merge_is_the_whole_bake(app::BakeOptions whole, uint32_t shards)
    {
        ASSERT_EQ(run(whole), 0) << err_;
        std::vector<std::string> parts;
        for (uint32_t k = 0; k < shards; ++k) {
            app::BakeOptions shard = whole;
            shard.shard = std::to_string(k) + "/" + std::to_string(shards);
            shard.output = path("part-" + std::to_string(k) + ".pvsp");
            ASSERT_EQ(run(shard), 0) << err_;
            parts.insert(parts.begin(), shard.output); // any order
        }
        // The same file name in another folder: an .s3d names its .wld after its own name.
        std::filesystem::create_directories(path("merged"));
        const std::string merged = path("merged/" + std::filesystem::path(whole.output).filename().string());
        ASSERT_EQ(merge(parts, whole.input, merged), 0) << err_;
        EXPECT_TRUE(read_whole_file(merged) == read_whole_file(whole.output))
            << shards << " shards merged differ from the one-machine bake";
    }

    app::BakeOptions raster_of_generated(const std::string& output)
    {
        app::BakeOptions o = bake_generated({6, 2}, output);
        o.method = "raster";
        o.resolution = 8;
        o.points = 3;
        return o;
    }
};

TEST_F(ShardMerge, GeneratedZoneAtEveryShardCount)
{
    for (uint32_t shards : {1u, 2u, 3u})
        expect_merge_is_the_whole_bake(raster_of_generated("whole.s3d"), shards);
}

TEST_F(ShardMerge, MoreShardsThanRowsGiveEmptyParts)
{
    app::BakeOptions o = raster_of_generated("whole.s3d");
    ASSERT_EQ(run(o), 0) << err_;
    const uint32_t regions = uint32_t(load_s3d(o.output).region_count());
    expect_merge_is_the_whole_bake(o, regions + 2);
}

TEST_F(ShardMerge, SharedQuakeMapWithItsAmbientLevels)
{
    SHARED_DATA_OR_SKIP(map, "quake/e1m1.bsp");
    app::BakeOptions o;
    o.input = map;
    o.output = path("whole.bsp");
    o.method = "raster";
    o.resolution = 8;
    o.points = 1;
    o.threads = 2;
    expect_merge_is_the_whole_bake(o, 3);
}

TEST_F(ShardMerge, SharedObjGridToHepvs)
{
    SHARED_DATA_OR_SKIP(obj, "hateengine/E1M1.obj");
    app::BakeOptions o;
    o.input = obj;
    o.output = path("whole.hepvs");
    o.method = "raster";
    o.cell = 16.0f;
    o.grid_size = 16.0f;
    o.resolution = 8;
    o.points = 1;
    o.threads = 2;
    expect_merge_is_the_whole_bake(o, 2);
}

TEST_F(ShardMerge, ReferencePerSourceOnAGeneratedZone)
{
    app::BakeOptions o = bake_generated({6, 2}, "whole.s3d");
    o.method = "reference";
    o.samples = 32;
    o.per_source = true;
    o.threads = 2;
    for (uint32_t shards : {1u, 3u})
        expect_merge_is_the_whole_bake(o, shards);
}

TEST_F(ShardMerge, ReferencePerSourceOnTheSharedE1m1)
{
    SHARED_DATA_OR_SKIP(map, "quake/e1m1.bsp");
    app::BakeOptions o;
    o.input = map;
    o.output = path("whole.bsp");
    o.method = "reference";
    o.samples = 16;
    o.per_source = true;
    o.threads = 2;
    expect_merge_is_the_whole_bake(o, 2);
}

TEST_F(ShardMerge, ShardsCostAboutTheSame)
{
    app::BakeOptions o = raster_of_generated("unused.s3d");
    o.shard = "0/2";
    o.output = path("a.pvsp");
    ASSERT_EQ(run(o), 0) << err_;
    const PvsPart a = decode_pvs_part(read_whole_file(o.output), o.output);
    o.shard = "1/2";
    o.output = path("b.pvsp");
    ASSERT_EQ(run(o), 0) << err_;
    const PvsPart b = decode_pvs_part(read_whole_file(o.output), o.output);
    EXPECT_EQ(a.sources.size() + b.sources.size(), a.row_count);
    EXPECT_LE(std::abs(int(a.sources.size()) - int(b.sources.size())), 1); // equal points: round-robin
    EXPECT_NE(a.sources.back() - a.sources.front() + 1, a.sources.size()) << "not an id range";
}

TEST_F(ShardMerge, PartsThatDoNotBelongAreRefusedByName)
{
    app::BakeOptions o = raster_of_generated("whole.s3d");
    const auto shard = [&](const std::string& spec, const std::string& name, uint64_t seed) {
        app::BakeOptions s = o;
        s.shard = spec;
        s.seed = seed;
        s.output = path(name);
        EXPECT_EQ(run(s), 0) << err_;
        return s.output;
    };
    const std::string p0 = shard("0/2", "p0.pvsp", 1), p1 = shard("1/2", "p1.pvsp", 1);
    const std::string other_seed = shard("1/2", "seed2.pvsp", 2);
    const std::string out = path("out.s3d");

    EXPECT_EQ(merge({p0}, o.input, out), 1);
    EXPECT_NE(err_.find("missing: 1"), std::string::npos) << err_;
    EXPECT_EQ(merge({p0, p1, p1}, o.input, out), 1);
    EXPECT_NE(err_.find("twice"), std::string::npos) << err_;
    EXPECT_NE(err_.find("p1.pvsp"), std::string::npos) << err_;
    EXPECT_EQ(merge({p0, other_seed}, o.input, out), 1);
    EXPECT_NE(err_.find("seed2.pvsp"), std::string::npos) << err_;
    EXPECT_NE(err_.find("other settings"), std::string::npos) << err_;

    // Another zone of the same size: the hash tells them apart.
    const std::string other_zone = path("other.s3d");
    write_zone(gen::generate_zone({6, 99}), other_zone, ZoneOutput::S3d);
    EXPECT_EQ(merge({p0, p1}, other_zone, out), 1);
    EXPECT_NE(err_.find("not the zone the parts were baked from"), std::string::npos) << err_;
    EXPECT_FALSE(std::filesystem::exists(out)) << "a refused merge writes nothing";

    // A part cut short (a copy that stopped): the file and the offset, nothing written.
    std::vector<uint8_t> cut = read_whole_file(p1);
    cut.resize(cut.size() - 5);
    const std::string p1_cut = path("p1-cut.pvsp");
    write_whole_file(p1_cut, cut);
    EXPECT_EQ(merge({p0, p1_cut}, o.input, out), 1);
    EXPECT_NE(err_.find("p1-cut.pvsp"), std::string::npos) << err_;
    EXPECT_NE(err_.find("offset"), std::string::npos) << err_;
    EXPECT_FALSE(std::filesystem::exists(out));

    EXPECT_EQ(merge({p0, p1}, o.input, path("out.bsp")), 2) << "the zone's format decides the output";
    EXPECT_EQ(merge({p0, p1}, o.input, out), 0) << err_;
}

TEST_F(ShardMerge, BakeRefusesWhatCannotBeSplit)
{
    app::BakeOptions o = raster_of_generated("part.pvsp");
    o.method = "portal-full";
    o.shard = "0/2";
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find("cannot be split into shards"), std::string::npos) << err_;
    o.method = "reference"; // by default its walks aim by every region's rows
    o.samples = 32;
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find("--per-source and --samples"), std::string::npos) << err_;
    o.method = "raster";
    for (const char* bad : {"2/2", "1", "a/2", "0/0", "-1/2"}) {
        o.shard = bad;
        EXPECT_EQ(run(o), 2) << bad;
        EXPECT_NE(err_.find("--shard must be K/N"), std::string::npos) << err_;
    }
    o.shard = "0/2";
    o.output = path("part.s3d");
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find(".pvsp"), std::string::npos) << err_;
}

} // namespace
} // namespace pvs::test
