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
    EXPECT_NE(zones[1].find("\"ok\""), std::string::npos);
    EXPECT_NE(zones[2].find("zz_broken.s3d"), std::string::npos);
    EXPECT_NE(zones[2].find("\"error\""), std::string::npos);

    std::ifstream json_in(o.json);
    const nlohmann::json reports = nlohmann::json::parse(json_in);
    ASSERT_EQ(reports.size(), 2u);
    const Zone zone = load_zone(e1m1);
    EXPECT_EQ(reports[0]["counts"]["regions"], zone.region_count());
    EXPECT_EQ(reports[1]["status"], "error");
    EXPECT_FALSE(reports[1]["error"].get<std::string>().empty());

    const std::vector<std::string> regions = lines_of(o.regions_csv);
    EXPECT_EQ(regions.size(), zone.region_count() + 1);
    EXPECT_EQ(regions[0], "file,map,region,flags,min_x,min_y,min_z,max_x,max_y,max_z,faces,triangles,visible,"
                          "visible_from,portal_neighbours");
    fs::remove_all(dir);
}

TEST(StatsCommand, NoInputIsABadArgument)
{
    std::FILE* err = std::tmpfile();
    EXPECT_EQ(app::run_stats(app::StatsOptions{}, stdout, err), 2);
    std::fclose(err);
}

} // namespace
} // namespace pvs::test
