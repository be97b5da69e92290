// HateEngine .hepvs (wld/hepvs/hepvs_file.h, hepvs_zone.h; spec: shared/formats/quake-doom-hepvs.md
// §5) against the baker's own E1M1.hepvs and hand-made files:
//  - the shared file's header is the spec's (version 1, min (-38, -38, -192), cell 8, 17 x 7 x 28
//    cells, 1257 names; per-cell counts 18 .. 446), and write(read(file)) is the file, byte for byte;
//  - bad files name the offset: truncated anywhere, any byte flipped, bytes after the last cell (what a 20-byte
//    header guess leaves), an index past the names, a zero count, version 0;
//  - the lookup is the engine's: strictly above min, trunc, x outermost, off the grid = none;
//  - attached to its OBJ, each cell's row holds exactly the file's objects for that cell, and the
//    culler at a camera uses the row of the cell the engine's formula gives.
#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/culler.h"
#include "visibility/file_error.h"
#include "wld/common/read_file.h"
#include "wld/hepvs/hepvs_file.h"
#include "wld/hepvs/hepvs_zone.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace pvs::test {
namespace {

// Two cells (2 x 1 x 1) over objects "a" and "b": cell 0 sees a, cell 1 sees a and b.
HepvsFile small_file()
{
    HepvsFile h;
    h.min = {-1.0f, -2.0f, -3.0f};
    h.cell_size = 4.0f;
    h.counts = {2u, 1u, 1u};
    h.names = {"a", "b"};
    h.cell_offsets = {0, 1, 3};
    h.cell_objects = {0, 0, 1};
    return h;
}

uint64_t error_offset(const std::vector<uint8_t>& bytes)
{
    try {
        read_hepvs(bytes, "bad.hepvs");
    } catch (const FileError& e) {
        EXPECT_EQ(e.file(), "bad.hepvs");
        return e.offset();
    }
    ADD_FAILURE() << "no error";
    return UINT64_MAX;
}

TEST(Hepvs, SharedFileHasTheSpecsHeaderAndRoundTripsByteForByte)
{
    SHARED_DATA_OR_SKIP(path, "hateengine/E1M1.hepvs");
    const std::vector<uint8_t> bytes = read_bytes(path);
    ASSERT_EQ(bytes.size(), 1343914u);
    const HepvsFile h = read_hepvs(bytes, path);
    EXPECT_EQ(h.version, 1u);
    EXPECT_EQ(h.min, glm::vec3(-38.0f, -38.0f, -192.0f));
    EXPECT_EQ(h.cell_size, 8.0f);
    EXPECT_EQ(h.counts, glm::uvec3(17u, 7u, 28u));
    EXPECT_EQ(h.names.size(), 1257u);
    EXPECT_TRUE(h.warnings.empty());
    size_t fewest = SIZE_MAX, most = 0;
    for (uint32_t c = 0; c < h.cell_count(); ++c) {
        fewest = std::min(fewest, h.cell(c).size());
        most = std::max(most, h.cell(c).size());
    }
    EXPECT_EQ(fewest, 18u);
    EXPECT_EQ(most, 446u);
    EXPECT_EQ(write_hepvs(h), bytes);
}

TEST(Hepvs, SmallFileRoundTrips)
{
    const std::vector<uint8_t> bytes = write_hepvs(small_file());
    ASSERT_EQ(bytes.size(), 28u + (2 + 1) + (2 + 1) + (2 + 2) + (2 + 4));
    const HepvsFile back = read_hepvs(bytes, "small.hepvs");
    EXPECT_EQ(back.names, small_file().names);
    EXPECT_EQ(back.cell_objects, small_file().cell_objects);
    EXPECT_EQ(write_hepvs(back), bytes);
}

TEST(Hepvs, BadFilesNameTheOffset)
{
    const std::vector<uint8_t> good = write_hepvs(small_file());
    for (size_t cut = 0; cut < good.size(); ++cut) { // every truncation is refused, inside the data
        const uint64_t at = error_offset(std::vector<uint8_t>(good.begin(), good.begin() + std::ptrdiff_t(cut)));
        EXPECT_LE(at, cut) << "cut at " << cut;
    }
    for (size_t at = 0; at < good.size(); ++at) // every byte flipped: read or refused, never more
        for (uint8_t mask : {uint8_t(0x01), uint8_t(0x80), uint8_t(0xFF)}) {
            std::vector<uint8_t> flipped = good;
            flipped[at] ^= mask;
            try {
                const HepvsFile h = read_hepvs(flipped, "flipped.hepvs");
                EXPECT_EQ(h.cell_offsets.size(), h.cell_count() + 1);
            } catch (const FileError& e) {
                EXPECT_LE(e.offset(), flipped.size());
            }
        }
    std::vector<uint8_t> longer = good;
    longer.insert(longer.end(), {0, 0, 0, 0, 0, 0, 0, 0});
    EXPECT_EQ(error_offset(longer), good.size()); // what reading a 28-byte file as 20 bytes would leave

    std::vector<uint8_t> bad_index = good;
    bad_index[good.size() - 2] = 2; // cell 1's second index: object 2 of 2
    EXPECT_EQ(error_offset(bad_index), good.size() - 2);

    std::vector<uint8_t> no_cells = good;
    no_cells[22] = 0; // count y
    EXPECT_EQ(error_offset(no_cells), 22u);
    std::vector<uint8_t> version0 = good;
    version0[0] = 0;
    EXPECT_EQ(error_offset(version0), 0u);
    std::vector<uint8_t> bad_cell = good;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(bad_cell.data() + 16, &nan, 4);
    EXPECT_EQ(error_offset(bad_cell), 16u);

    std::vector<uint8_t> version2 = good;
    version2[0] = 2;
    EXPECT_EQ(read_hepvs(version2, "v2.hepvs").warnings.size(), 1u);

    HepvsFile unwritable = small_file();
    unwritable.cell_objects[2] = 7;
    EXPECT_THROW(write_hepvs(unwritable), std::invalid_argument);
}

TEST(ViewGrid, LookupIsTheEnginesRule)
{
    ViewGrid g;
    g.min = {0.0f, 0.0f, 0.0f};
    g.cell_size = 1.0f;
    g.counts = {2u, 3u, 4u};
    g.grid_size = 16.0f;
    // Grid point (gx, gy, gz) is zone point (16 gx, -16 gz, 16 gy).
    const auto zone_point = [](float gx, float gy, float gz) { return glm::vec3(16 * gx, -16 * gz, 16 * gy); };
    EXPECT_EQ(g.cell_at(zone_point(0.5f, 0.5f, 0.5f)), 0);
    EXPECT_EQ(g.cell_at(zone_point(1.5f, 0.5f, 0.5f)), 12); // x outermost: (1 * 3 + 0) * 4 + 0
    EXPECT_EQ(g.cell_at(zone_point(0.5f, 2.5f, 3.5f)), 11); // (0 * 3 + 2) * 4 + 3
    EXPECT_EQ(g.cell_at(zone_point(0.0f, 0.5f, 0.5f)), -1); // on min: not strictly above
    EXPECT_EQ(g.cell_at(zone_point(2.0f, 0.5f, 0.5f)), -1); // index 2 of 2
    EXPECT_EQ(g.cell_at(zone_point(1.0f, 0.5f, 0.5f)), 12); // on an inner boundary: trunc goes up
    EXPECT_EQ(g.cell_at(glm::vec3(std::numeric_limits<float>::quiet_NaN())), -1);
    const Aabb box = g.cell_bounds(12);
    EXPECT_EQ(box.min, glm::vec3(16.0f, -16.0f, 0.0f));
    EXPECT_EQ(box.max, glm::vec3(32.0f, 0.0f, 16.0f));
}

TEST(Hepvs, AttachedToItsObjEachCellRowIsTheFilesCell)
{
    SHARED_DATA_OR_SKIP(path, "hateengine/E1M1.hepvs");
    const HepvsFile h = read_hepvs(read_bytes(path), path);
    const Zone zone = load_zone(path); // opens the OBJ beside it
    ASSERT_TRUE(zone.view_grid);
    ASSERT_TRUE(zone.baked_pvs);
    ASSERT_EQ(zone.baked_pvs->row_count(), h.cell_count());
    ASSERT_EQ(zone.region_count(), 1257u);
    std::vector<uint64_t> row(zone.baked_pvs->words_per_row());
    for (uint32_t c = 0; c < h.cell_count(); c += 7) {
        zone.baked_pvs->decode_row(c, row);
        std::vector<std::string> from_row, from_file;
        bits::for_each_set(row, [&](size_t r) { from_row.push_back(zone.region_names[r]); });
        for (uint16_t i : h.cell(c))
            from_file.push_back(h.names[i]);
        std::sort(from_row.begin(), from_row.end());
        std::sort(from_file.begin(), from_file.end());
        EXPECT_EQ(from_row, from_file) << "cell " << c;
    }
    // The engine's formula in hepvs space, for e1m1's start (Quake (480, -352, 88) is OBJ
    // (480, 88, 352)), against the culler's row.
    const glm::vec3 start(480.0f, -352.0f, 88.0f);
    const glm::vec3 p = glm::vec3(480.0f, 88.0f, 352.0f) / 16.0f;
    const glm::uvec3 i((p - h.min) / h.cell_size);
    const uint32_t cell = (i.x * h.counts.y + i.y) * h.counts.z + i.z;
    Culler culler(zone, &*zone.baked_pvs);
    Camera camera;
    camera.position = start;
    std::vector<uint32_t> visible;
    const CullStats s = culler.cull(camera, {CullMode::Pvs, false}, visible);
    EXPECT_EQ(s.cell, int32_t(cell));
    EXPECT_EQ(s.region, -1);
    EXPECT_EQ(visible.size(), h.cell(cell).size());
    // A forced value is a cell in a grid zone: camera elsewhere, the start's row.
    CullOptions forced{CullMode::Pvs, false};
    forced.forced_region = int32_t(cell);
    camera.position = glm::vec3(0.0f, 0.0f, 100000.0f);
    const CullStats f = culler.cull(camera, forced, visible);
    EXPECT_EQ(f.cell, int32_t(cell));
    EXPECT_EQ(visible.size(), h.cell(cell).size());
    forced.forced_region = int32_t(h.cell_count());
    EXPECT_FALSE(culler.cull(camera, forced, visible).pvs_used);
}

TEST(Hepvs, AHepvsWithoutItsObjOrOfAnotherObjIsRefused)
{
    const std::string dir = ::testing::TempDir();
    const std::vector<uint8_t> bytes = write_hepvs(small_file());
    write_whole_file(dir + "alone.hepvs", bytes);
    EXPECT_THROW(load_zone(dir + "alone.hepvs"), FileError);
    const std::string obj = "o other\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    write_whole_file(dir + "other.obj", std::vector<uint8_t>(obj.begin(), obj.end()));
    write_whole_file(dir + "other.hepvs", bytes);
    EXPECT_THROW(load_zone(dir + "other.obj"), FileError); // no name of the .hepvs is an object
}

TEST(Hepvs, ObjectsTheHepvsDoesNotNameAreAWarning)
{
    const std::string dir = ::testing::TempDir();
    // Objects a, b (named by small_file()) and c, which no cell can list.
    const std::string obj = "o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\no b\nf 1 2 3\no c\nf 1 2 3\n";
    write_whole_file(dir + "three.obj", std::vector<uint8_t>(obj.begin(), obj.end()));
    write_whole_file(dir + "three.hepvs", write_hepvs(small_file()));
    const Zone zone = load_zone(dir + "three.obj");
    ASSERT_EQ(zone.region_count(), 3u);
    const auto warning = std::find_if(zone.source.notes.begin(), zone.source.notes.end(), [](const std::string& n) {
        return n.find("1 of the OBJ's 3 objects are not in") != std::string::npos;
    });
    EXPECT_NE(warning, zone.source.notes.end());

    write_whole_file(dir + "two.obj", std::vector<uint8_t>(obj.begin(), obj.begin() + long(obj.find("o c"))));
    write_whole_file(dir + "two.hepvs", write_hepvs(small_file()));
    for (const std::string& note : load_zone(dir + "two.obj").source.notes)
        EXPECT_EQ(note.find("objects are not in"), std::string::npos) << note;
}

} // namespace
} // namespace pvs::test
