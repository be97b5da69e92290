// How much memory a loaded EverQuest zone takes (issue target: the model under 3x the archive),
// and the reader's parts that get it there: one zone vertex per distinct (position, uv), one
// face per convex polygon rebuilt from the file's triangles (wld/eq/convex_face_builder.h).
#include "tests/support/test_data.h"
#include "visibility/geometry/split_faces.h"
#include "wld/eq/convex_face_builder.h"
#include "wld/eq/eq_zone_reader.h"
#include "wld/eq/eq_zone_writer.h"
#include "gen/generate_zone.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cstring>
#include <set>
#include <tuple>

namespace pvs {
namespace {

using eq::ConvexFaceBuilder;

double model_per_archive(const Zone& zone, const std::vector<uint8_t>& archive)
{
    return double(zone.memory_bytes()) / double(archive.size());
}

// Every face of the model is a convex planar polygon: its triangles' corners all lie on the
// left of (or on) each edge of its outline, seen from its first triangle's normal.
void expect_convex_planar_faces(const Zone& z)
{
    for (size_t f = 0; f < z.mesh.faces.size(); ++f) {
        const Face& face = z.mesh.faces[f];
        if (face.triangle_count < 2)
            continue;
        const uint32_t* first = &z.mesh.indices[3 * size_t(face.first_triangle)];
        const glm::vec3 a = z.mesh.positions[first[0]];
        const glm::vec3 n = glm::normalize(glm::cross(z.mesh.positions[first[1]] - a, z.mesh.positions[first[2]] - a));
        for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t) {
            const uint32_t* tri = &z.mesh.indices[3 * size_t(t)];
            const glm::vec3 p0 = z.mesh.positions[tri[0]], p1 = z.mesh.positions[tri[1]], p2 = z.mesh.positions[tri[2]];
            const glm::vec3 tn = glm::normalize(glm::cross(p1 - p0, p2 - p0));
            ASSERT_GT(glm::dot(tn, n), 0.999f) << "face " << f << " triangle " << t;
        }
    }
}

TEST(EqZoneMemory, E1m1ConvertedTakesUnderThreeTimesTheArchive)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    // As `pvscope convert e1m1.bsp e1m1.s3d` makes it.
    const std::vector<uint8_t> archive =
        eq::write_eq_zone(clip_faces_to_region_cells(*test::shared_zone("quake/e1m1.bsp")), "e1m1");
    const Zone z = eq::load_eq_zone(archive, "e1m1.s3d");
    const double ratio = model_per_archive(z, archive);
    std::printf("[ e1m1.s3d ] archive %zu bytes, model %zu bytes: %.2fx; %zu vertices, %zu faces\n", archive.size(),
                z.memory_bytes(), ratio, z.mesh.positions.size(), z.mesh.faces.size());
    EXPECT_LT(ratio, 3.0);
    expect_convex_planar_faces(z);
}

// Generated zones are all rectangles: 2 triangles and 4 corners each, which the Mesh's float
// positions, uvs and 32-bit indices keep at about 3.7x (50 rooms) to 5.3x (5000 rooms) of the
// zlib-compressed archive. The bound guards against regressions; the 3x target is not met.
TEST(EqZoneMemory, GeneratedZoneStaysUnderItsMeasuredRatio)
{
    const Zone generated = gen::generate_zone({.rooms = 50, .seed = 1, .cell_size = 32.0f});
    const std::vector<uint8_t> archive = eq::write_eq_zone(generated, "gen");
    const Zone z = eq::load_eq_zone(archive, "gen.s3d");
    EXPECT_LT(model_per_archive(z, archive), 4.0);
    EXPECT_EQ(z.mesh.faces.size() * 2, z.mesh.triangle_count()) << "each rectangle is one face again";
    expect_convex_planar_faces(z);
}

TEST(EqZoneMemory, EachPositionAndUvIsOneVertex)
{
    const Zone generated = gen::generate_zone({.rooms = 20, .seed = 4, .cell_size = 32.0f});
    const Zone z = eq::load_eq_zone(eq::write_eq_zone(generated, "gen"), "gen.s3d");
    std::set<std::tuple<float, float, float, float, float>> seen;
    for (size_t v = 0; v < z.mesh.positions.size(); ++v) {
        const glm::vec3 p = z.mesh.positions[v];
        const glm::vec2 uv = z.mesh.uvs[v];
        EXPECT_TRUE(seen.insert({p.x, p.y, p.z, uv.x, uv.y}).second) << "vertex " << v << " repeats";
    }
    // Regions share the corners on their common walls: fewer vertices than their meshes hold.
    EXPECT_LT(z.mesh.positions.size(), 4 * z.mesh.faces.size());
}

// ---- Convex faces from triangles ----

// A regular hexagon in the z = 0 plane (counter-clockwise seen from +z) and its centre.
const std::vector<glm::vec3> kHexagon = {{2, 0, 0}, {1, 1.7f, 0}, {-1, 1.7f, 0}, {-2, 0, 0},
                                         {-1, -1.7f, 0}, {1, -1.7f, 0}, {0, 0, 0}};

TEST(ConvexFaceBuilder, JoinsAFanIntoOnePolygon)
{
    ConvexFaceBuilder face;
    ASSERT_TRUE(face.start(kHexagon, {0, 1, 2}));
    EXPECT_TRUE(face.try_add({0, 2, 3}));
    EXPECT_TRUE(face.try_add({0, 3, 4}));
    EXPECT_TRUE(face.try_add({0, 4, 5}));
    EXPECT_FALSE(face.try_add({0, 5, 1})) << "a corner already on the outline";
}

TEST(ConvexFaceBuilder, JoinsTrianglesAcrossAnyOutlineEdge)
{
    ConvexFaceBuilder face;
    ASSERT_TRUE(face.start(kHexagon, {6, 0, 1}));
    EXPECT_TRUE(face.try_add({6, 1, 2}));  // fan around the centre...
    EXPECT_FALSE(face.try_add({6, 3, 4})) << "shares no edge";
    EXPECT_TRUE(face.try_add({2, 3, 6})); // ...and a triangle on the edge (2, 6), other apex
}

TEST(ConvexFaceBuilder, RefusesAReflexCornerAnotherPlaneAndTheOtherWinding)
{
    const std::vector<glm::vec3> p = {{0, 0, 0}, {2, 0, 0}, {1, 0.2f, 0}, {0, 2, 0}, {1, 1, 1}, {2, 2, 0}};
    ConvexFaceBuilder face;
    ASSERT_TRUE(face.start(p, {0, 1, 2}));
    EXPECT_FALSE(face.try_add({0, 2, 3})) << "reflex corner at (1, 0.2)";
    EXPECT_FALSE(face.try_add({0, 2, 4})) << "not in the plane";
    EXPECT_FALSE(face.try_add({0, 3, 2})) << "other winding: the edge is walked the same way";
    ASSERT_TRUE(face.start(p, {0, 1, 5}));
    EXPECT_TRUE(face.try_add({0, 5, 3}));
}

TEST(ConvexFaceBuilder, DegenerateTrianglesStandAlone)
{
    const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}};
    ConvexFaceBuilder face;
    EXPECT_FALSE(face.start(p, {0, 1, 2}));
    EXPECT_FALSE(face.try_add({0, 2, 3}));
    ASSERT_TRUE(face.start(p, {0, 1, 3}));
    EXPECT_FALSE(face.try_add({1, 0, 2})) << "collinear: no area";
}

} // namespace
} // namespace pvs
