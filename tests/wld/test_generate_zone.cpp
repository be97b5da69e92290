// Procedural zones, checked against the voxel layout they come from (an independent ground
// truth for the tree and the mesh): every cell's centre is found in a region of its content
// (or outside for solid cells), the open space is one connected level, every feature exists,
// every face lies on its region's boundary facing in, and the faces against solid cover exactly
// the open/solid cell boundaries.
#include "visibility/region_lookup.h"
#include "gen/generate_zone.h"
#include "gen/voxel_level.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <queue>

namespace pvs::gen {
namespace {

uint32_t flags_of(Cell c)
{
    switch (c) {
    case Cell::Water: return kRegionWater;
    case Cell::Lava: return kRegionLava;
    case Cell::Slime: return kRegionSlime;
    case Cell::Pvp: return kRegionPvp;
    case Cell::ZoneLine: return kRegionZoneLine;
    default: return 0;
    }
}

class Generated : public ::testing::TestWithParam<int> {
protected:
    void SetUp() override
    {
        params_.rooms = GetParam();
        params_.seed = 99;
        zone_ = generate_zone(params_);
        level_ = make_voxel_level(params_.rooms, params_.seed);
        origin_ = -glm::vec3(level_.dims) * params_.cell_size * 0.5f * glm::vec3(1, 1, 0);
    }
    glm::vec3 cell_centre(int x, int y, int z) const
    {
        return origin_ + (glm::vec3(x, y, z) + 0.5f) * params_.cell_size;
    }
    GenParams params_;
    Zone zone_;
    VoxelLevel level_;
    glm::vec3 origin_;
};

TEST_P(Generated, EveryCellCentreIsInARegionOfItsContentOrOutside)
{
    for (int z = 0; z < level_.dims.z; ++z)
        for (int y = 0; y < level_.dims.y; ++y)
            for (int x = 0; x < level_.dims.x; ++x) {
                const Cell c = level_.at(x, y, z);
                const PointLocation at = locate_point(zone_.tree, cell_centre(x, y, z));
                if (c == Cell::Solid) {
                    ASSERT_EQ(at.region, kLeafOutside) << x << "," << y << "," << z;
                    continue;
                }
                ASSERT_TRUE(at.in_region()) << x << "," << y << "," << z;
                const Region& r = zone_.regions[size_t(at.region)];
                ASSERT_TRUE(r.bounds.contains(cell_centre(x, y, z)));
                ASSERT_EQ(r.flags, flags_of(c)) << x << "," << y << "," << z;
            }
}

TEST_P(Generated, OpenSpaceIsOneConnectedLevel)
{
    std::vector<uint8_t> seen(level_.cells.size(), 0);
    const Room& first = level_.rooms[0];
    std::queue<glm::ivec3> todo;
    todo.push({first.lo.x, first.lo.y, first.lo.z + 1});
    seen[level_.index(first.lo.x, first.lo.y, first.lo.z + 1)] = 1;
    size_t reached = 1;
    while (!todo.empty()) {
        const glm::ivec3 c = todo.front();
        todo.pop();
        for (const glm::ivec3 d : {glm::ivec3(1, 0, 0), glm::ivec3(-1, 0, 0), glm::ivec3(0, 1, 0), glm::ivec3(0, -1, 0),
                                   glm::ivec3(0, 0, 1), glm::ivec3(0, 0, -1)}) {
            const glm::ivec3 n = c + d;
            if (level_.at(n.x, n.y, n.z) == Cell::Solid || seen[level_.index(n.x, n.y, n.z)])
                continue;
            seen[level_.index(n.x, n.y, n.z)] = 1;
            ++reached;
            todo.push(n);
        }
    }
    size_t open = 0;
    for (Cell c : level_.cells)
        open += c != Cell::Solid;
    EXPECT_EQ(reached, open);
}

TEST_P(Generated, HasEveryFeature)
{
    uint32_t all = 0;
    for (const Region& r : zone_.regions)
        all |= r.flags;
    for (uint32_t flag : {kRegionWater, kRegionLava, kRegionSlime, kRegionPvp, kRegionZoneLine})
        EXPECT_TRUE(all & flag) << region_flag_name(flag);
    ASSERT_EQ(zone_.zone_lines.size(), 1u);
    EXPECT_FALSE(zone_.zone_lines[0].target.empty());
    EXPECT_GE(level_.rooms.size(), size_t(GetParam()) * 9 / 10);
    if (GetParam() >= 40) {
        EXPECT_GE(level_.floors, 2);
        EXPECT_GE(level_.shafts + level_.stairs, level_.floors - 1);
    }
    EXPECT_FALSE(zone_.baked_pvs.has_value());
}

TEST_P(Generated, FacesLieOnTheirRegionBoundaryAndFaceInward)
{
    for (uint32_t r = 0; r < zone_.region_count(); ++r) {
        const Aabb& box = zone_.regions[r].bounds;
        for (uint32_t f : zone_.faces_of_region(r)) {
            const Face& face = zone_.mesh.faces[f];
            const uint32_t* tri = &zone_.mesh.indices[3 * size_t(face.first_triangle)];
            const glm::vec3 a = zone_.mesh.positions[tri[0]], b = zone_.mesh.positions[tri[1]],
                            c = zone_.mesh.positions[tri[2]];
            const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
            const glm::vec3 centre = (a + c) * 0.5f; // the quad's diagonal midpoint
            ASSERT_TRUE(box.contains(centre + n * 0.5f)) << "face " << f << " of region " << r;
            ASSERT_FALSE(box.contains(centre - n * 0.5f)) << "face " << f << " of region " << r;
        }
    }
}

TEST_P(Generated, FacesAgainstSolidCoverExactlyTheOpenSolidCellBoundaries)
{
    size_t boundary_cell_faces = 0;
    for (int z = 0; z < level_.dims.z; ++z)
        for (int y = 0; y < level_.dims.y; ++y)
            for (int x = 0; x < level_.dims.x; ++x) {
                if (level_.at(x, y, z) == Cell::Solid)
                    continue;
                for (const glm::ivec3 d : {glm::ivec3(1, 0, 0), glm::ivec3(-1, 0, 0), glm::ivec3(0, 1, 0),
                                           glm::ivec3(0, -1, 0), glm::ivec3(0, 0, 1), glm::ivec3(0, 0, -1)})
                    boundary_cell_faces += level_.at(x + d.x, y + d.y, z + d.z) == Cell::Solid;
            }
    // Faces are rectangles of whole cells; look behind each cell of each face, since one merged
    // face may border solid cells and liquid cells alike.
    size_t cells_against_solid = 0;
    const float cell = params_.cell_size;
    for (const Face& face : zone_.mesh.faces) {
        const uint32_t* tri = &zone_.mesh.indices[3 * size_t(face.first_triangle)];
        const glm::vec3 a = zone_.mesh.positions[tri[0]], b = zone_.mesh.positions[tri[1]], c = zone_.mesh.positions[tri[2]];
        const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
        const glm::vec3 lo = glm::min(a, c), hi = glm::max(a, c);
        for (float x = lo.x + 0.5f * cell; x < std::max(hi.x, lo.x + cell); x += cell)
            for (float y = lo.y + 0.5f * cell; y < std::max(hi.y, lo.y + cell); y += cell)
                for (float z = lo.z + 0.5f * cell; z < std::max(hi.z, lo.z + cell); z += cell) {
                    glm::vec3 p{x, y, z};
                    for (int k = 0; k < 3; ++k)
                        if (n[k] != 0.0f)
                            p[k] = lo[k]; // on the face's plane
                    cells_against_solid += locate_point(zone_.tree, p - n * 0.5f).region == kLeafOutside;
                }
    }
    EXPECT_EQ(cells_against_solid, boundary_cell_faces);
}

INSTANTIATE_TEST_SUITE_P(Rooms, Generated, ::testing::Values(5, 60, 400));

TEST(Generate, SameSeedSameZoneOtherSeedOtherZone)
{
    const Zone a = generate_zone({30, 7, 32.0f}), b = generate_zone({30, 7, 32.0f}), c = generate_zone({30, 8, 32.0f});
    EXPECT_EQ(a.mesh.positions, b.mesh.positions);
    EXPECT_EQ(a.mesh.indices, b.mesh.indices);
    EXPECT_EQ(a.tree.leaf_region, b.tree.leaf_region);
    EXPECT_EQ(material_rgba(a.materials[0]), material_rgba(b.materials[0]));
    EXPECT_NE(a.mesh.positions, c.mesh.positions);
}

TEST(Generate, RoomCountsOutsideTheRangeAreRefused)
{
    EXPECT_THROW(generate_zone({4, 1, 32.0f}), std::invalid_argument);
    EXPECT_THROW(generate_zone({5001, 1, 32.0f}), std::invalid_argument);
    EXPECT_THROW(generate_zone({10, 1, 0.0f}), std::invalid_argument);
}

} // namespace
} // namespace pvs::gen
