// OBJ levels as zones (wld/obj/obj_reader.h) and the way back (convert: OBJ + .hepvs):
//  - a hand-made OBJ of two rooms and a wall: objects are regions with their names, y-up file
//    points land z-up, materials named by usemtl exist without an .mtl;
//  - bad OBJ text names the object and the offset of its line; a file with no faces is refused;
//  - e1m1 converted to OBJ + .hepvs and read back: the same triangles, one object per region, and
//    every cell's row holds the file PVS's row of each region a camera in that cell can be in
//    (random points located in the BSP tree, an independent computation of the grid's rows);
//  - an OBJ zone written again keeps its object names, and its .hepvs rows.
#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/file_error.h"
#include "visibility/region_lookup.h"
#include "wld/common/read_file.h"
#include "wld/convert.h"
#include "wld/obj/obj_reader.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

namespace pvs::test {
namespace {

std::string write_text(const std::string& name, const std::string& text)
{
    const std::string path = ::testing::TempDir() + name;
    write_whole_file(path, std::vector<uint8_t>(text.begin(), text.end()));
    return path;
}

// Room A: x 0..100, room B: x 110..210, a wall between (x 100..110), all 0..50 up (y in the
// file), 0..100 deep (file z = -zone y, so zone y -100..0). Floors only, one quad each; the wall
// a box side.
const char* kTwoRooms = R"(# two rooms and a wall
o room_a
v 0 0 0
v 100 0 0
v 100 0 100
v 0 0 100
usemtl floor
f 1 2 3 4
o wall
v 100 0 0
v 100 50 0
v 100 50 100
v 100 0 100
usemtl stone
f 5 6 7 8
o room_b
v 110 0 0
v 210 0 0
v 210 0 100
v 110 0 100
usemtl floor
f 9 10 11 12
)";

TEST(ObjZone, ObjectsAreRegionsInZoneAxes)
{
    const Zone zone = load_zone(write_text("two_rooms.obj", kTwoRooms));
    ASSERT_EQ(zone.region_count(), 3u);
    EXPECT_EQ(zone.region_names, (std::vector<std::string>{"room_a", "wall", "room_b"}));
    EXPECT_FALSE(zone.tree.exists());
    EXPECT_FALSE(zone.baked_pvs);
    EXPECT_EQ(zone.mesh.triangle_count(), 6u);
    // file (x, y, z) -> zone (x, -z, y)
    EXPECT_EQ(zone.regions[0].bounds.min, glm::vec3(0.0f, -100.0f, 0.0f));
    EXPECT_EQ(zone.regions[0].bounds.max, glm::vec3(100.0f, 0.0f, 0.0f));
    EXPECT_EQ(zone.regions[1].bounds.max, glm::vec3(100.0f, 0.0f, 50.0f));
    std::vector<std::string> materials;
    for (const Material& m : zone.materials)
        materials.push_back(m.name);
    EXPECT_NE(std::find(materials.begin(), materials.end(), "floor"), materials.end());
    EXPECT_NE(std::find(materials.begin(), materials.end(), "stone"), materials.end());
    EXPECT_EQ(zone.materials[zone.mesh.faces[zone.faces_of_region(1)[0]].material].name, "stone");
}

TEST(ObjZone, BadObjNamesTheObjectAndItsLine)
{
    const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\no broken\nf 1 2 9\n";
    try {
        load_zone(write_text("broken.obj", text));
        FAIL() << "no error";
    } catch (const FileError& e) {
        EXPECT_EQ(e.offset(), text.find("o broken"));
        EXPECT_NE(e.reason().find("broken"), std::string::npos) << e.what();
    }
    EXPECT_THROW(load_zone(write_text("empty.obj", "# nothing\nv 0 0 0\n")), FileError);
}

// Every truncation and a sweep of byte changes either loads a zone that is safe to use (every
// index in range, one cell per region, rows for every region) or is refused with FileError
// naming the file: never a crash or a read out of bounds (ASan in CI).
TEST(ObjZone, TruncatedOrDamagedTextIsLoadedOrRefused)
{
    const std::string text = kTwoRooms;
    const auto survives = [](const std::string& bytes) {
        try {
            const Zone zone = read_obj_zone(std::vector<uint8_t>(bytes.begin(), bytes.end()), "damaged.obj");
            ASSERT_EQ(zone.region_face_offsets.size(), zone.region_count() + 1);
            for (uint32_t f : zone.region_faces)
                ASSERT_LT(f, zone.mesh.faces.size());
            for (uint32_t i : zone.mesh.indices)
                ASSERT_LT(i, zone.mesh.positions.size());
            if (zone.view_grid) {
                ASSERT_EQ(zone.view_grid->cell_count(), zone.region_count());
            }
            if (zone.baked_pvs) {
                ASSERT_EQ(zone.baked_pvs->region_count(), zone.region_count());
            }
        } catch (const FileError& e) {
            EXPECT_EQ(e.file(), "damaged.obj");
        }
    };
    for (size_t cut = 0; cut <= text.size(); ++cut)
        survives(text.substr(0, cut));
    for (size_t at = 0; at < text.size(); ++at)
        for (char c : {'9', '-', ' ', '/', '\n', '\0'}) {
            std::string damaged = text;
            damaged[at] = c;
            survives(damaged);
        }
}

TEST(ObjZone, QuakeLevelAsObjAndHepvsKeepsGeometryAndIsConservative)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    const Zone& bsp = *shared_zone("quake/e1m1.bsp");
    const std::string out = ::testing::TempDir() + "e1m1_as.obj";
    write_zone(bsp, out, ZoneOutput::Obj);
    const Zone obj = load_zone(out);
    ASSERT_EQ(obj.region_count(), bsp.region_count());
    ASSERT_TRUE(obj.view_grid);
    ASSERT_TRUE(obj.baked_pvs);
    uint64_t bsp_triangles = 0;
    for (uint32_t r = 0; r < bsp.region_count(); ++r)
        for (uint32_t f : bsp.faces_of_region(r))
            bsp_triangles += bsp.mesh.faces[f].triangle_count;
    EXPECT_EQ(obj.mesh.triangle_count(), bsp_triangles); // a face listed by two regions is in both
    std::mt19937_64 rng(3);
    const Aabb box = bsp.bounds();
    std::uniform_real_distribution<float> x(box.min.x, box.max.x), y(box.min.y, box.max.y), z(box.min.z, box.max.z);
    std::vector<uint64_t> cell_row(obj.baked_pvs->words_per_row()), region_row(bsp.baked_pvs->words_per_row());
    int checked = 0;
    for (int i = 0; i < 20000 && checked < 2000; ++i) {
        const glm::vec3 p(x(rng), y(rng), z(rng));
        const int32_t region = locate_point(bsp.tree, p).region;
        const int32_t cell = obj.view_grid->cell_at(p);
        if (region < 0 || cell < 0)
            continue;
        ++checked;
        obj.baked_pvs->decode_row(uint32_t(cell), cell_row);
        bsp.baked_pvs->decode_row(uint32_t(region), region_row);
        for (size_t w = 0; w < region_row.size(); ++w)
            ASSERT_EQ(region_row[w] & ~cell_row[w], 0u) << "cell " << cell << " lacks part of region " << region;
        ASSERT_TRUE(bits::test(cell_row, uint32_t(region)));
    }
    EXPECT_EQ(checked, 2000);
}

TEST(ObjZone, WrittenAgainKeepsNamesAndRows)
{
    SHARED_DATA_OR_SKIP(path, "hateengine/E1M1.obj");
    const Zone zone = load_zone(path);
    const std::string out = ::testing::TempDir() + "E1M1_again.obj";
    write_zone(zone, out, ZoneOutput::Obj);
    const Zone again = load_zone(out);
    ASSERT_EQ(again.region_names, zone.region_names);
    ASSERT_EQ(again.mesh.triangle_count(), zone.mesh.triangle_count());
    ASSERT_TRUE(again.baked_pvs);
    std::vector<uint64_t> a(zone.baked_pvs->words_per_row()), b(a.size());
    for (uint32_t c = 0; c < zone.baked_pvs->row_count(); ++c) {
        zone.baked_pvs->decode_row(c, a);
        again.baked_pvs->decode_row(c, b);
        ASSERT_EQ(a, b) << "cell " << c;
    }
}

} // namespace
} // namespace pvs::test
