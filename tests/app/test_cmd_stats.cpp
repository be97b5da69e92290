// `pvscope stats` as a user runs it on a folder holding a real map and a broken file: one CSV
// row per zone with the broken one as an error row (and exit 1), the JSON array, and one CSV row
// per region whose counts match the zone's own.
#include "app/cmd_stats.h"

#include "tests/support/test_data.h"
#include "wld/common/read_file.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace pvs::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines_of(const fs::path& path)
{
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

TEST(StatsCommand, FolderGivesOneRowPerZoneAndAnErrorRowForABadFile)
{
    SHARED_DATA_OR_SKIP(e1m1, "quake/e1m1.bsp");
    const fs::path dir = fs::temp_directory_path() / ("pvscope-stats-" + std::to_string(getpid()));
    fs::create_directories(dir / "maps");
    fs::copy_file(e1m1, dir / "maps" / "e1m1.bsp", fs::copy_options::overwrite_existing);
    write_whole_file((dir / "maps" / "zz_broken.s3d").string(), {'n', 'o', 'p', 'e'});
    app::StatsOptions o;
    o.inputs = {dir.string()};
    o.csv = (dir / "zones.csv").string();
    o.json = (dir / "zones.json").string();
    o.regions_csv = (dir / "regions.csv").string();
    std::FILE* out = std::tmpfile();
    std::FILE* err = std::tmpfile();
    EXPECT_EQ(app::run_stats(o, out, err), 1) << "a zone failed";
    std::fclose(out);
    std::fclose(err);

    const std::vector<std::string> zones = lines_of(o.csv);
    ASSERT_EQ(zones.size(), 3u); // header + 2 zones
    EXPECT_EQ(zones[0].rfind("file,map,status,error,", 0), 0u) << zones[0];
    // A point is three columns; a part the zone lacks (a Quake map has no view grid) is none.
    const std::string header = "," + zones[0] + ",";
    for (const char* column : {",bounds.min.0,", ",bounds.min.1,", ",bounds.min.2,", ",bounds.max.2,"})
        EXPECT_NE(header.find(column), std::string::npos) << column << " in " << zones[0];
    EXPECT_EQ(header.find(",view_grid"), std::string::npos) << zones[0];
    EXPECT_NE(zones[1].find("\"ok\""), std::string::npos);
    EXPECT_NE(zones[2].find("zz_broken.s3d"), std::string::npos);
    EXPECT_NE(zones[2].find("\"error\""), std::string::npos);

    std::ifstream json_in(o.json);
    const nlohmann::json reports = nlohmann::json::parse(json_in);
    ASSERT_EQ(reports.size(), 2u);
    const Zone zone = load_zone(e1m1);
    EXPECT_EQ(reports[0]["counts"]["regions"], zone.region_count());
    // e1m1's known answers (../shared/data's README): mean 142.0 visible of 1206 rows; 33 water,
    // 108 slime, 44 sky leaves.
    EXPECT_NEAR(reports[0]["pvs"]["mean_visible"].get<double>(), 142.0, 0.05);
    EXPECT_EQ(reports[1]["status"], "error");
    EXPECT_FALSE(reports[1]["error"].get<std::string>().empty());

    const std::vector<std::string> regions = lines_of(o.regions_csv);
    EXPECT_EQ(regions.size(), zone.region_count() + 1);
    EXPECT_EQ(regions[0], "file,map,region,flags,min_x,min_y,min_z,max_x,max_y,max_z,faces,triangles,visible,"
                          "visible_from,portal_neighbours");
    // The per-region rows add up to the same PVS: visible and visible-from both sum to its bits.
    double visible = 0, visible_from = 0;
    size_t water = 0, slime = 0, sky = 0;
    for (size_t i = 1; i < regions.size(); ++i) {
        std::vector<std::string> c;
        std::stringstream in(regions[i]);
        for (std::string cell; std::getline(in, cell, ',');)
            c.push_back(cell);
        ASSERT_EQ(c.size(), 15u) << regions[i];
        visible += std::stod(c[12]);
        visible_from += std::stod(c[13]);
        water += c[3].find("water") != std::string::npos;
        slime += c[3].find("slime") != std::string::npos;
        sky += c[3].find("sky") != std::string::npos;
    }
    EXPECT_NEAR(visible / double(zone.region_count()), 142.0, 0.05);
    EXPECT_EQ(visible, visible_from);
    EXPECT_EQ(water, 33u);
    EXPECT_EQ(slime, 108u);
    EXPECT_EQ(sky, 44u);
    fs::remove_all(dir);
}

TEST(StatsCommand, NoInputIsABadArgument)
{
    std::FILE* err = std::tmpfile();
    EXPECT_EQ(app::run_stats(app::StatsOptions{}, stdout, err), 2);
    std::fclose(err);
}

// An output that cannot be created is an error (exit 1, the reason on stderr), not an abort.
TEST(StatsCommand, AnOutputThatCannotBeMadeIsAnError)
{
    const fs::path dir = fs::temp_directory_path() / ("pvscope-stats-out-" + std::to_string(getpid()));
    fs::create_directories(dir);
    write_whole_file((dir / "broken.s3d").string(), {'n', 'o', 'p', 'e'});
    for (const char* which : {"csv", "json", "regions-csv"}) {
        app::StatsOptions o;
        o.inputs = {(dir / "broken.s3d").string()};
        const std::string missing = (dir / "no-such-folder" / "out").string();
        (which == std::string("csv") ? o.csv : which == std::string("json") ? o.json : o.regions_csv) = missing;
        std::FILE* out = std::tmpfile();
        std::FILE* err = std::tmpfile();
        EXPECT_EQ(app::run_stats(o, out, err), 1) << which;
        std::rewind(err);
        std::string said(4096, '\0');
        said.resize(std::fread(said.data(), 1, said.size(), err));
        EXPECT_NE(said.find("no-such-folder/out"), std::string::npos) << which << ": " << said;
        std::fclose(out);
        std::fclose(err);
    }
    fs::remove_all(dir);
}

} // namespace
} // namespace pvs::test
