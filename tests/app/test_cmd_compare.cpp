// `pvscope compare` as a user runs it: a generated .s3d zone in, the table on stdout, CSV with the
// documented columns, JSON, the chart as PNG, SVG and PDF; bad arguments refused with exit code 2. The
// outputs are read back and hold what the engine tests hold: conservative rows miss nothing and
// pop nowhere, the reference's rows have no excess, CSV and JSON agree, and on e1m1 the file's
// row has the known mean visible of its WVis PVS.
#include "app/cmd_compare.h"

#include "tests/app/bake_command_fixture.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
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

// The cells of one CSV line (no quoted commas in compare's CSV).
std::vector<std::string> cells(const std::string& line)
{
    std::vector<std::string> out;
    std::stringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');)
        out.push_back(cell);
    return out;
}

// What every compare report must hold, read back from its JSON and CSV.
void expect_relations(const nlohmann::json& j, const std::string& csv)
{
    const uint64_t regions = j["regions"].get<uint64_t>();
    const auto& rows = j["methods"];
    ASSERT_GE(rows.size(), 1u);
    for (const auto& row : rows) {
        const std::string what = row["method"].get<std::string>() + " " + row["params"].get<std::string>();
        if (row["method"] == "reference") {
            EXPECT_EQ(row["bound"], "lower") << what;
            EXPECT_EQ(row["excess_bits"], 0) << what << ": the reference is the yardstick's own rows";
        }
        if (row["bound"] == "upper") {
            EXPECT_EQ(row["missing_bits"], 0) << what << ": a conservative method misses no reference bit";
            EXPECT_EQ(row["rows_missing_bits"], 0) << what;
            EXPECT_TRUE(row["missing_pairs"].empty()) << what;
            EXPECT_EQ(row["popping_pixels"], 0) << what << ": and pops nowhere";
            EXPECT_GE(row["mean_visible"].get<double>() * double(regions) + 0.5, double(j["reference"]["bits"].get<uint64_t>()))
                << what << ": holds at least the reference's bits";
        }
        EXPECT_LE(row["missing_pairs"].size(), row["missing_bits"].get<uint64_t>()) << what;
    }
    // The last reference row is the reference the others are measured against: mean visible
    // times regions is its bit count, and it misses nothing of itself.
    nlohmann::json reference_row;
    for (const auto& row : rows)
        if (row["method"] == "reference")
            reference_row = row;
    ASSERT_FALSE(reference_row.is_null());
    EXPECT_EQ(reference_row["missing_bits"], 0);
    EXPECT_NEAR(reference_row["mean_visible"].get<double>() * double(regions),
                double(j["reference"]["bits"].get<uint64_t>()), 0.5);
    // CSV and JSON: the same rows, the same numbers.
    std::stringstream lines(csv);
    std::string line;
    std::getline(lines, line);
    const std::vector<std::string> header = cells(line);
    size_t k = 0;
    for (; std::getline(lines, line); ++k) {
        ASSERT_LT(k, rows.size());
        const std::vector<std::string> c = cells(line);
        ASSERT_EQ(c.size(), header.size()) << line;
        for (size_t col = 0; col < header.size(); ++col)
            if (header[col] == "missing_bits" || header[col] == "excess_bits" || header[col] == "popping_pixels") {
                EXPECT_EQ(std::stoull(c[col]), rows[k][header[col]].get<uint64_t>()) << header[col] << " of " << line;
            }
    }
    EXPECT_EQ(k, rows.size());
}

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
                        "excess_bits,rows_missing_bits,popping_pixels,crack_pixels,unknown_pixels,grazing_pixels,unfaced_pixels,triangle_overdraw\n",
                        0),
              0u);
    const size_t lines = size_t(std::count(csv.begin(), csv.end(), '\n'));
    EXPECT_EQ(lines, 1u + 1u + 1u + 1u + 6u) << "header, reference, none, portal-fast, six portal-full";
    const nlohmann::json j = nlohmann::json::parse(read_text(o.json));
    EXPECT_EQ(j["methods"].size(), lines - 1);
    EXPECT_GT(std::filesystem::file_size(o.chart), 1000u);
    expect_relations(j, csv);

    o.chart = path("c.svg");
    o.csv = o.json = "";
    o.methods = "none";
    ASSERT_EQ(compare(o), 0) << err_;
    EXPECT_NE(read_text(o.chart).find("</svg>"), std::string::npos);

    o.chart = path("c.pdf");
    ASSERT_EQ(compare(o), 0) << err_;
    EXPECT_EQ(read_text(o.chart).rfind("%PDF-", 0), 0u);
}

// A shared level: the file's row is its own PVS, whose mean visible is known (142.0 on e1m1,
// ../shared/data's README); conservative rows against the reference hold as on any zone.
TEST_F(CompareCommand, E1m1FileRowHasItsKnownMeanVisible)
{
    SHARED_DATA_OR_SKIP(e1m1, "quake/e1m1.bsp");
    app::CompareCommandOptions o;
    o.input = e1m1;
    o.methods = "file,portal-fast";
    o.samples = 64;
    o.cameras = 2;
    o.sky = "none"; // WVis's content rule: the file's PVS is an upper bound under it
    o.threads = 2;
    o.csv = path("e.csv");
    o.json = path("e.json");
    ASSERT_EQ(compare(o), 0) << err_;
    const nlohmann::json j = nlohmann::json::parse(read_text(o.json));
    EXPECT_EQ(j["regions"], 1206);
    bool found = false;
    for (const auto& row : j["methods"])
        if (row["method"] == "file") {
            found = true;
            EXPECT_NEAR(row["mean_visible"].get<double>(), 142.0, 0.05);
            EXPECT_EQ(row["missing_bits"], 0) << "WVis's PVS holds every sight line the reference traced";
        }
    EXPECT_TRUE(found);
    expect_relations(j, read_text(o.csv));
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
