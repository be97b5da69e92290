// `pvscope walk` as a user runs it (through its command line), its CSV read back and checked
// against what the zone itself says: each camera's PVS stage keeps exactly the regions of its
// region's row in the file, a conservative PVS pops nowhere, every raster popping pixel lands in
// exactly one class, and without a PVS nothing is culled by it.
#include "app/cmd_walk.h"

#include "tests/app/bake_command_fixture.h"
#include "visibility/bit_row.h"
#include "wld/zone_file.h"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <map>

namespace pvs::test {
namespace {

using WalkCommand = BakeCommand;

using CsvRow = std::map<std::string, std::string>;

std::vector<CsvRow> read_csv(const std::string& path)
{
    std::stringstream in(read_text(path));
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    {
        std::stringstream h(line);
        for (std::string cell; std::getline(h, cell, ',');)
            header.push_back(cell);
    }
    std::vector<CsvRow> rows;
    while (std::getline(in, line)) {
        std::stringstream l(line);
        CsvRow row;
        size_t col = 0;
        for (std::string cell; std::getline(l, cell, ',') && col < header.size(); ++col)
            row[header[col]] = cell;
        rows.push_back(std::move(row));
    }
    return rows;
}

int walk(const std::string& arguments)
{
    CLI::App app;
    int code = -1;
    app::register_walk_command(app, code);
    app.parse("walk " + arguments, false);
    return code;
}

uint64_t number(const CsvRow& row, const char* column)
{
    const auto it = row.find(column);
    EXPECT_NE(it, row.end()) << column;
    return it == row.end() ? 0 : std::stoull(it->second);
}

TEST_F(WalkCommand, RowsAgreeWithTheZonesOwnPvs)
{
    gen::GenParams generation{12, 5, 32.0f, true}; // baked: portal-full rows in the file
    generation.bake_threads = 1;
    const std::string zone_path = bake_generated(generation, "unused.s3d").input;
    const Zone zone = load_zone(zone_path);
    ASSERT_TRUE(zone.baked_pvs.has_value());
    const std::string csv = path("walk.csv");
    ASSERT_EQ(walk(zone_path + " --cameras 40 --seed 3 --pvs file --csv " + csv), 0);
    const std::vector<CsvRow> rows = read_csv(csv);
    ASSERT_EQ(rows.size(), 40u);
    std::vector<uint64_t> row_bits(zone.baked_pvs->words_per_row());
    size_t in_region = 0;
    for (const CsvRow& r : rows) {
        EXPECT_LE(number(r, "regions_drawn"), number(r, "regions_after_pvs"));
        EXPECT_LE(number(r, "regions_after_pvs"), number(r, "regions_total"));
        EXPECT_EQ(number(r, "regions_total"), zone.region_count());
        EXPECT_EQ(number(r, "popping_confirmed"), 0u) << "portal-full is conservative";
        EXPECT_EQ(number(r, "raster_popping_pixels"), number(r, "popping_cracks") + number(r, "popping_unknown") +
                                                          number(r, "popping_grazing") + number(r, "popping_unfaced") +
                                                          number(r, "popping_unlisted") +
                                                          number(r, "popping_confirmed"));
        if (r.at("camera_place") != "region")
            continue;
        ++in_region;
        const int region = std::stoi(r.at("region"));
        zone.baked_pvs->decode_row(uint32_t(region), row_bits);
        EXPECT_EQ(number(r, "regions_after_pvs"), bits::count(row_bits)) << "camera in region " << region;
    }
    EXPECT_EQ(in_region, rows.size()) << "seeded cameras are placed inside regions";

    // A far clip: the distance stage drops regions beyond the far plane's reach, and the walk's
    // exact popping check (pixels drawn by the unculled render, with the same far plane) finds
    // nothing it dropped that was on screen.
    ASSERT_EQ(walk(zone_path + " --cameras 40 --seed 3 --pvs file --far 100 --csv " + csv), 0);
    uint64_t after_pvs = 0, after_distance = 0;
    for (const CsvRow& r : read_csv(csv)) {
        EXPECT_LE(number(r, "regions_after_distance"), number(r, "regions_after_pvs"));
        EXPECT_LE(number(r, "regions_drawn"), number(r, "regions_after_distance"));
        EXPECT_EQ(number(r, "popping_confirmed"), 0u) << "the stage keeps what the far plane lets through";
        after_pvs += number(r, "regions_after_pvs");
        after_distance += number(r, "regions_after_distance");
    }
    EXPECT_LT(after_distance, after_pvs) << "a 100-unit far clip drops regions";

    ASSERT_EQ(walk(zone_path + " --cameras 10 --seed 3 --pvs none --csv " + csv), 0);
    for (const CsvRow& r : read_csv(csv)) {
        EXPECT_EQ(number(r, "regions_after_pvs"), zone.region_count()) << "no PVS culls nothing";
        EXPECT_EQ(number(r, "popping_confirmed"), 0u);
    }
}

} // namespace
} // namespace pvs::test
