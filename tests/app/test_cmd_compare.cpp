// `pvscope compare` as a user runs it: a generated .s3d zone in, the table on stdout, CSV with the
// documented columns, JSON, the chart as PNG and SVG; bad arguments refused with exit code 2.
#include "app/cmd_compare.h"

#include "tests/app/bake_command_fixture.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

namespace pvs::test {
namespace {

class CompareCommand : public BakeCommand {
protected:
    int compare(const app::CompareCommandOptions& o)
    {
        std::FILE* out = std::tmpfile();
        std::FILE* err = std::tmpfile();
        const int code = app::run_compare_command(o, out, err);
        out_ = read_and_close(out);
        err_ = read_and_close(err);
        return code;
    }
    std::string out_;
};

TEST_F(CompareCommand, WritesTableCsvJsonAndCharts)
{
    app::CompareCommandOptions o;
    o.input = bake_generated({12, 5}, "unused.s3d").input;
    o.methods = "none,portal-fast,portal-full";
    o.samples = 64;
    o.cameras = 4;
    o.threads = 1;
    o.csv = path("c.csv");
    o.json = path("c.json");
    o.chart = path("c.png");
    ASSERT_EQ(compare(o), 0) << err_;
    EXPECT_NE(out_.find("portal-fast"), std::string::npos) << out_;
    const std::string csv = read_text(o.csv);
    EXPECT_EQ(csv.rfind("method,params,bound,wall_s,cpu_s,peak_mib,estimate_mib,pvs_bytes,mean_visible,missing_bits,"
                        "excess_bits,rows_missing_bits,popping_pixels,crack_pixels,grazing_pixels,triangle_overdraw\n",
                        0),
              0u);
    const size_t lines = size_t(std::count(csv.begin(), csv.end(), '\n'));
    EXPECT_EQ(lines, 1u + 1u + 1u + 1u + 6u) << "header, reference, none, portal-fast, six portal-full";
    const nlohmann::json j = nlohmann::json::parse(read_text(o.json));
    EXPECT_EQ(j["methods"].size(), lines - 1);
    EXPECT_GT(std::filesystem::file_size(o.chart), 1000u);

    o.chart = path("c.svg");
    o.csv = o.json = "";
    o.methods = "none";
    ASSERT_EQ(compare(o), 0) << err_;
    EXPECT_NE(read_text(o.chart).find("</svg>"), std::string::npos);
}

TEST_F(CompareCommand, BadArgumentsAndFilesAreRefused)
{
    app::CompareCommandOptions o;
    o.input = bake_generated({5, 5}, "unused.s3d").input;
    o.methods = "portal-medium";
    EXPECT_EQ(compare(o), 2);
    EXPECT_NE(err_.find("unknown method 'portal-medium'"), std::string::npos) << err_;
    o.methods = "";
    o.size = "big";
    EXPECT_EQ(compare(o), 2);
    o.size = "320x240";
    o.input = path("missing.bsp");
    EXPECT_EQ(compare(o), 1);
    EXPECT_NE(err_.find("missing.bsp"), std::string::npos) << err_;
}

} // namespace
} // namespace pvs::test
