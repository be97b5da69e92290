// Faces re-cut to region cells (the EverQuest layout) on real Quake trees: every new face lies in
// its region's cell and belongs to that region alone, and the area per texture equals the area of
// the original faces, each counted once (the pieces of a face over its listing leaves tile it).
#include "tests/support/test_data.h"
#include "visibility/geometry/bsp_volume.h"
#include "visibility/geometry/split_faces.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <map>

namespace pvs {
namespace {

double face_area(const Zone& zone, uint32_t f)
{
    const Face& face = zone.mesh.faces[f];
    double area = 0;
    for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t) {
        const glm::vec3 a = zone.mesh.positions[zone.mesh.indices[3 * size_t(t)]];
        const glm::vec3 b = zone.mesh.positions[zone.mesh.indices[3 * size_t(t) + 1]];
        const glm::vec3 c = zone.mesh.positions[zone.mesh.indices[3 * size_t(t) + 2]];
        area += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
    }
    return area;
}

std::map<std::string, double> area_per_texture(const Zone& zone, bool listed_only)
{
    std::vector<uint8_t> listed(zone.mesh.faces.size(), 0);
    for (uint32_t f : zone.region_faces)
        listed[f] = 1;
    std::map<std::string, double> areas;
    for (uint32_t f = 0; f < zone.mesh.faces.size(); ++f)
        if (!listed_only || listed[f])
            areas[zone.materials[zone.mesh.faces[f].material].name] += face_area(zone, f);
    return areas;
}

class SplitFaces : public ::testing::TestWithParam<const char*> {};

TEST_P(SplitFaces, PiecesLieInTheirRegionCellAndKeepTheAreaPerTexture)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const Zone& zone = *test::shared_zone(GetParam());
    const Zone cut = clip_faces_to_region_cells(zone);

    // Each new face is listed by exactly one region.
    std::vector<int> owners(cut.mesh.faces.size(), 0);
    for (uint32_t f : cut.region_faces)
        ++owners[f];
    for (size_t f = 0; f < owners.size(); ++f)
        ASSERT_EQ(owners[f], 1) << "face " << f;

    // Every vertex of a region's faces is inside the region's cell (within the clip epsilon).
    std::vector<int32_t> region_leaf(zone.region_count(), -1);
    for (size_t leaf = 0; leaf < zone.tree.leaf_region.size(); ++leaf)
        if (zone.tree.leaf_region[leaf] >= 0)
            region_leaf[size_t(zone.tree.leaf_region[leaf])] = int32_t(leaf);
    for (uint32_t r = 0; r < cut.region_count(); ++r) {
        const std::vector<Plane> planes = leaf_bounding_planes(cut.tree, region_leaf[r]);
        for (uint32_t f : cut.faces_of_region(r)) {
            const Face& face = cut.mesh.faces[f];
            for (uint32_t k = 0; k < 3 * face.triangle_count; ++k) {
                const glm::vec3 p = cut.mesh.positions[cut.mesh.indices[3 * size_t(face.first_triangle) + k]];
                for (const Plane& plane : planes)
                    ASSERT_GE(plane.distance(p), -kWindingOnEpsilon - 0.01f) << "region " << r << " face " << f;
            }
        }
    }

    // Area per texture: the original faces counted once each.
    const auto before = area_per_texture(zone, true), after = area_per_texture(cut, false);
    ASSERT_EQ(before.size(), after.size());
    for (const auto& [name, area] : before)
        EXPECT_NEAR(after.at(name), area, 1e-3 * area + 1e-3) << name;
}

INSTANTIATE_TEST_SUITE_P(SharedData, SplitFaces,
                         ::testing::Values("quake/e1m1.bsp", "quake/e2m1.bsp", "quake/end.bsp", "visdemo/example.bsp"),
                         [](const ::testing::TestParamInfo<const char*>& param) { return test::param_name(param.param); });

} // namespace
} // namespace pvs
