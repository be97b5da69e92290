// `pvscope stability` as a user runs it on a generated .s3d zone: the table, JSON with the
// documented fields, CSV; a method that bakes nothing is refused with exit code 2.
#include "app/cmd_stability.h"

#include "tests/app/bake_command_fixture.h"
#include "visibility/transform/zone_transform.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace pvs::test {
namespace {

using StabilityCommand = BakeCommand;

int run_stability(const app::StabilityCommandOptions& o, std::string& out)
{
    std::FILE* out_file = std::tmpfile();
    std::FILE* err_file = std::tmpfile();
    const int code = app::run_stability_command(o, out_file, err_file);
    out = read_and_close(out_file);
    read_and_close(err_file);
    return code;
}

TEST_F(StabilityCommand, WritesEveryMethodAndTransform)
{
    app::StabilityCommandOptions o;
    o.input = bake_generated({8, 2}, "unused.s3d").input;
    o.methods = "portal-fast,portal-full";
    o.samples = 64;
    o.threads = 1;
    o.json = path("s.json");
    o.csv = path("s.csv");
    std::string out;
    ASSERT_EQ(run_stability(o, out), 0);
    EXPECT_NE(out.find("rotate 90"), std::string::npos) << out;
    const nlohmann::json j = nlohmann::json::parse(read_text(o.json));
    ASSERT_EQ(j["rows"].size(), 2u * stability_transforms().size());
    for (const auto& row : j["rows"]) {
        for (const char* field : {"method", "transform", "changed_bits", "missing_bits", "seconds"})
            EXPECT_TRUE(row.contains(field)) << field;
        EXPECT_EQ(row["missing_bits"], 0) << row.dump();
        // A transform that is exact in floats (translations by powers of two, quarter turns,
        // mirrors) must not change a bit of a deterministic bake.
        if (row.contains("exact") && row["exact"].get<bool>()) {
            EXPECT_EQ(row["changed_bits"], 0) << row.dump();
        }
    }
    EXPECT_EQ(read_text(o.csv).rfind("method,params,transform,exact,changed_bits,", 0), 0u);

    o.methods = "file";
    EXPECT_EQ(run_stability(o, out), 2);
}

// --cases: the method x case table with its documented JSON fields; a file and --cases together,
// or an unknown case, are refused.
TEST_F(StabilityCommand, RunsTheCraftedCases)
{
    app::StabilityCommandOptions o;
    o.cases = "crack-0.1,leak";
    o.methods = "portal-full,reference";
    o.samples = 256;
    o.threads = 1;
    o.json = path("cases.json");
    o.csv = path("cases.csv");
    std::string out;
    ASSERT_EQ(run_stability(o, out), 0);
    EXPECT_NE(out.find("crack-0.1"), std::string::npos) << out;
    const nlohmann::json j = nlohmann::json::parse(read_text(o.json));
    ASSERT_EQ(j["rows"].size(), 4u);
    for (const auto& row : j["rows"]) {
        for (const char* field : {"case", "method", "bound", "truth_bits", "missing_bits", "excess_bits", "broken"})
            EXPECT_TRUE(row.contains(field)) << field;
        EXPECT_FALSE(row["broken"].get<bool>()) << row.dump();
        // Against a case's known truth, an upper bound misses nothing and a lower bound adds nothing.
        if (row["bound"] == "upper") {
            EXPECT_EQ(row["missing_bits"], 0) << row.dump();
        }
        if (row["bound"] == "lower") {
            EXPECT_EQ(row["excess_bits"], 0) << row.dump();
        }
        EXPECT_GT(row["truth_bits"].get<uint64_t>(), 0u) << row.dump();
    }
    EXPECT_EQ(j["rows"][0]["method"], "portal-full");
    EXPECT_EQ(j["rows"][0]["missing_bits"], 0);
    EXPECT_EQ(j["rows"][1]["missing_bits"], 6); // the beam cannot pass a 0.1 crack
    EXPECT_EQ(read_text(o.csv).rfind("case,method,params,bound,", 0), 0u);

    o.cases = "no-such-case";
    EXPECT_EQ(run_stability(o, out), 2);
    o.cases = "leak";
    o.input = bake_generated({5, 2}, "unused.s3d").input;
    EXPECT_EQ(run_stability(o, out), 2);
}

} // namespace
} // namespace pvs::test
