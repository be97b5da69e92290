// Quake BSP -> EverQuest .s3d through the converter (faces clipped to region cells), read back:
// the same regions, flags (sky has no EverQuest type), PVS rows and point lookups, and the same
// area per texture as the original faces counted once each. And the OBJ export's structure.
#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/region_lookup.h"
#include "wld/convert.h"
#include "wld/eq/eq_zone_writer.h"
#include "gen/generate_zone.h"
#include "wld/obj/obj_writer.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <glm/geometric.hpp>
#include <map>
#include <random>
#include <sstream>

namespace pvs {
namespace {

// Area per material name; `names` renames materials (the .s3d names them by texture file).
std::map<std::string, double> area_per_texture(const Zone& zone, const std::vector<std::string>& names = {})
{
    std::vector<uint8_t> listed(zone.mesh.faces.size(), 0);
    for (uint32_t f : zone.region_faces)
        listed[f] = 1;
    std::map<std::string, double> areas;
    for (uint32_t f = 0; f < zone.mesh.faces.size(); ++f) {
        if (!listed[f])
            continue;
        const Face& face = zone.mesh.faces[f];
        for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t) {
            const glm::vec3 a = zone.mesh.positions[zone.mesh.indices[3 * size_t(t)]];
            const glm::vec3 b = zone.mesh.positions[zone.mesh.indices[3 * size_t(t) + 1]];
            const glm::vec3 c = zone.mesh.positions[zone.mesh.indices[3 * size_t(t) + 2]];
            const std::string& name = names.empty() ? zone.materials[face.material].name : names[face.material];
            areas[name] += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
        }
    }
    return areas;
}

TEST(Convert, E1m1ToS3dKeepsRegionsFlagsPvsLookupsAndAreaPerTexture)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    const Zone& quake = *test::shared_zone("quake/e1m1.bsp");
    const std::string out = (std::filesystem::temp_directory_path() / "pvscope_test_e1m1.s3d").string();
    write_zone(quake, out, ZoneOutput::S3d);
    const Zone eq = load_zone(out);
    std::filesystem::remove(out);

    ASSERT_EQ(eq.region_count(), quake.region_count());
    for (uint32_t r = 0; r < quake.region_count(); ++r)
        ASSERT_EQ(eq.regions[r].flags, quake.regions[r].flags & ~kRegionSky) << "region " << r;
    ASSERT_TRUE(eq.baked_pvs.has_value());
    std::vector<uint64_t> a(quake.baked_pvs->words_per_row()), b(a.size());
    for (uint32_t r = 0; r < quake.region_count(); ++r) {
        quake.baked_pvs->decode_row(r, a);
        eq.baked_pvs->decode_row(r, b);
        ASSERT_EQ(a, b) << "row " << r;
    }
    const Aabb box = quake.bounds();
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y), uz(box.min.z, box.max.z);
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 p{ux(rng), uy(rng), uz(rng)};
        const int32_t expected = locate_point(quake.tree, p).region;
        ASSERT_EQ(locate_point(eq.tree, p).region, expected < 0 ? kLeafOutside : expected) << i;
    }
    const auto before = area_per_texture(quake, eq::eq_texture_file_names(quake)), after = area_per_texture(eq);
    for (const auto& [name, area] : before)
        EXPECT_NEAR(after.at(name), area, 1e-3 * area) << name;
}

// A face whose texture repeats 2000 times across it: the old WLD form (i16 / 256 uvs) cannot hold
// that, so convert writes the new version (f32 uvs) with a note, and the uvs read back as given;
// a zone whose uvs fit keeps the old form (no note). An OBJ level (no tree) is refused by name.
TEST(Convert, UvsBeyondTheOldWldFormAreWrittenInTheNewVersion)
{
    Zone zone = gen::generate_zone({5, 7, 32.0f, false});
    ASSERT_FALSE(eq::face_beyond_old_wld_form(zone).has_value());
    const std::filesystem::path dir = std::filesystem::temp_directory_path();
    const std::string plain = (dir / "pvscope-convert-plain.s3d").string();
    for (const std::string& note : write_zone(zone, plain, ZoneOutput::S3d))
        EXPECT_EQ(note.find("new WLD version"), std::string::npos) << note;

    const uint32_t stretched = zone.region_faces[0];
    const Face& face = zone.mesh.faces[stretched];
    for (uint32_t i = face.first_triangle * 3; i < (face.first_triangle + face.triangle_count) * 3; ++i)
        zone.mesh.uvs[zone.mesh.indices[i]] *= 2000.0f;
    EXPECT_EQ(eq::face_beyond_old_wld_form(zone), stretched);
    const std::string path = (dir / "pvscope-convert-stretched.s3d").string();
    const std::vector<std::string> notes = write_zone(zone, path, ZoneOutput::S3d);
    EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
        return n.find("new WLD version") != std::string::npos;
    }));
    const Zone back = load_zone(path);
    ASSERT_EQ(back.region_count(), zone.region_count());
    float widest = 0.0f;
    for (const glm::vec2& uv : back.mesh.uvs)
        widest = std::max({widest, std::abs(uv.x), std::abs(uv.y)});
    EXPECT_GT(widest, 256.0f) << "the stretched face's uvs survive";
    std::filesystem::remove(plain);
    std::filesystem::remove(path);

    Zone level;
    level.view_grid.emplace();
    EXPECT_THROW(write_zone(level, (dir / "pvscope-convert-level.s3d").string(), ZoneOutput::S3d),
                 std::invalid_argument);
}

TEST(Convert, OutputFormatFromTheExtensionOrTo)
{
    EXPECT_EQ(zone_output_for("x/zone.S3D", ""), ZoneOutput::S3d);
    EXPECT_EQ(zone_output_for("zone.obj", ""), ZoneOutput::Obj);
    EXPECT_EQ(zone_output_for("zone.bin", "obj"), ZoneOutput::Obj);
    EXPECT_FALSE(zone_output_for("zone.bin", "").has_value());
}

TEST(Convert, ObjHasOneObjectPerRegionAndOneFaceLinePerTriangle)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.bsp");
    const Zone& zone = *test::shared_zone("visdemo/example.bsp");
    const ObjExport e = export_obj(zone, "example");
    std::istringstream lines(e.obj);
    size_t objects = 0, faces = 0, vertices = 0;
    for (std::string line; std::getline(lines, line);) {
        objects += line.rfind("o ", 0) == 0;
        faces += line.rfind("f ", 0) == 0;
        vertices += line.rfind("v ", 0) == 0;
    }
    size_t expected_faces = 0;
    for (uint32_t r = 0; r < zone.region_count(); ++r)
        for (uint32_t f : zone.faces_of_region(r))
            expected_faces += zone.mesh.faces[f].triangle_count;
    EXPECT_EQ(objects, zone.region_count());
    EXPECT_EQ(faces, expected_faces);
    EXPECT_EQ(vertices, zone.mesh.positions.size());
    EXPECT_NE(e.obj.find("mtllib example.mtl"), std::string::npos);
}

} // namespace
} // namespace pvs
