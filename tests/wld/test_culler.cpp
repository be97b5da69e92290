// The culler on e1m1 with its baked PVS (made by WVis, elsewhere), and its defined behaviour for
// cameras that are not in a region. Independent checks: the frustum stage is compared with the
// clip-space test of points sampled inside regions; the PVS stage with the decoded row.
#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/culler.h"
#include "visibility/eval/camera_set.h"
#include "visibility/region_lookup.h"
#include "gen/generate_outdoor_zone.h"
#include "wld/zone_file.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

namespace pvs {
namespace {

class CullE1m1 : public ::testing::Test {
protected:
    void SetUp() override
    {
        SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
        zone_ = test::shared_zone("quake/e1m1.bsp");
        ASSERT_NE(zone_, nullptr);
    }
    // Seeded cameras at random points inside regions, looking anywhere.
    static std::vector<Camera> cameras(size_t count, uint32_t seed)
    {
        std::vector<Camera> out;
        const Aabb box = zone_->bounds();
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y),
            uz(box.min.z, box.max.z), yaw(0.0f, 360.0f), pitch(-60.0f, 60.0f);
        while (out.size() < count) {
            Camera c;
            c.position = {ux(rng), uy(rng), uz(rng)};
            c.yaw_degrees = yaw(rng);
            c.pitch_degrees = pitch(rng);
            if (locate_point(zone_->tree, c.position).in_region())
                out.push_back(c);
        }
        return out;
    }
    static const Zone* zone_;
};
const Zone* CullE1m1::zone_ = nullptr;

TEST_F(CullE1m1, PlayerStartUsesLeaf1199sRowThenTheFrustum)
{
    Culler culler(*zone_, &*zone_->baked_pvs);
    Camera camera;
    camera.position = {480, -352, 88};
    std::vector<uint32_t> visible;
    const CullStats s = culler.cull(camera, {CullMode::PvsFrustum, true}, visible);
    EXPECT_EQ(s.camera, CameraPlace::InRegion);
    EXPECT_EQ(s.region, 1198);
    EXPECT_TRUE(s.pvs_used);
    std::vector<uint64_t> row(zone_->baked_pvs->words_per_row());
    zone_->baked_pvs->decode_row(1198, row);
    EXPECT_EQ(s.regions_after_pvs, bits::count(row));
    EXPECT_LE(s.regions_after_frustum, s.regions_after_pvs);
    EXPECT_GT(s.regions_after_frustum, 0u);
    EXPECT_TRUE(std::is_sorted(visible.begin(), visible.end()));
    for (uint32_t r : visible)
        EXPECT_TRUE(bits::test(row, r));
    EXPECT_LE(s.triangles_after_frustum, s.triangles_after_pvs);
    EXPECT_LT(s.triangles_after_pvs, s.triangles_total);
}

TEST_F(CullE1m1, ModeNoneDrawsEverythingAndPvsModeIgnoresTheFrustum)
{
    Culler culler(*zone_, &*zone_->baked_pvs);
    Camera camera;
    camera.position = {480, -352, 88};
    std::vector<uint32_t> visible;
    EXPECT_EQ(culler.cull(camera, {CullMode::None, false}, visible).regions_after_frustum, 1206u);
    const CullStats pvs_only = culler.cull(camera, {CullMode::Pvs, false}, visible);
    EXPECT_EQ(pvs_only.regions_after_frustum, pvs_only.regions_after_pvs);
}

TEST_F(CullE1m1, FrustumNeverDropsARegionWithAPointOnScreen)
{
    Culler culler(*zone_, &*zone_->baked_pvs);
    std::mt19937 rng(8);
    const Aabb box = zone_->bounds();
    std::uniform_real_distribution<float> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y), uz(box.min.z, box.max.z);
    std::vector<uint32_t> visible;
    for (const Camera& camera : cameras(200, 21)) {
        culler.cull(camera, {CullMode::Frustum, false}, visible);
        const glm::mat4 vp = camera.view_projection();
        for (int i = 0; i < 300; ++i) {
            const glm::vec3 p{ux(rng), uy(rng), uz(rng)};
            const glm::vec4 c = vp * glm::vec4(p, 1.0f);
            if (!(c.w > 0 && std::abs(c.x) < c.w && std::abs(c.y) < c.w && std::abs(c.z) < c.w))
                continue;
            const PointLocation at = locate_point(zone_->tree, p);
            if (at.in_region()) {
                ASSERT_TRUE(std::binary_search(visible.begin(), visible.end(), uint32_t(at.region)))
                    << "region " << at.region << " has an on-screen point but was culled";
            }
        }
    }
}

TEST_F(CullE1m1, PvsPlusFrustumDrawsFewerTrianglesThanFrustumOnTheMedianCamera)
{
    Culler culler(*zone_, &*zone_->baked_pvs);
    std::vector<uint64_t> frustum_only, both;
    std::vector<uint32_t> visible;
    for (const Camera& camera : cameras(2000, 77)) {
        frustum_only.push_back(culler.cull(camera, {CullMode::Frustum, true}, visible).triangles_after_frustum);
        both.push_back(culler.cull(camera, {CullMode::PvsFrustum, true}, visible).triangles_after_frustum);
        ASSERT_LE(both.back(), frustum_only.back());
    }
    std::nth_element(frustum_only.begin(), frustum_only.begin() + 1000, frustum_only.end());
    std::nth_element(both.begin(), both.begin() + 1000, both.end());
    EXPECT_LT(both[1000], frustum_only[1000]);
}

TEST_F(CullE1m1, CameraInSolidOutsideOrNanFallsBackToTheFrustumAndSaysSo)
{
    Culler culler(*zone_, &*zone_->baked_pvs);
    std::vector<uint32_t> visible, frustum_only;
    Camera camera;
    camera.position = zone_->bounds().max + glm::vec3(5000.0f); // far outside the world
    camera.yaw_degrees = 225.0f;
    camera.pitch_degrees = -20.0f;
    const CullStats outside = culler.cull(camera, {CullMode::PvsFrustum, false}, visible);
    EXPECT_NE(outside.camera, CameraPlace::InRegion);
    EXPECT_FALSE(outside.pvs_used);
    EXPECT_EQ(outside.regions_after_pvs, 1206u);
    culler.cull(camera, {CullMode::Frustum, false}, frustum_only);
    EXPECT_EQ(visible, frustum_only);

    camera.position = {std::nanf(""), 0.0f, 0.0f};
    const CullStats nan = culler.cull(camera, {CullMode::PvsFrustum, false}, visible);
    EXPECT_FALSE(nan.pvs_used);
    EXPECT_EQ(nan.region, -1);
}

TEST(Culler, DamagedRowWithoutItsOwnBitStillDrawsTheCameraRegion)
{
    // Two regions split by the plane x = 0; region 0's row is empty.
    Zone zone;
    zone.tree.nodes.push_back({{1.0f, 0.0f, 0.0f}, 0.0f, {~1, ~2}});
    zone.tree.leaf_region = {kLeafSolid, 0, 1};
    zone.tree.root = 0;
    zone.regions.resize(2);
    zone.regions[0].bounds.grow({0, -10, -10});
    zone.regions[0].bounds.grow({10, 10, 10});
    zone.regions[1].bounds.grow({-10, -10, -10});
    zone.regions[1].bounds.grow({0, 10, 10});
    zone.region_face_offsets = {0, 0, 0};
    const Pvs pvs = Pvs::build(2, [](uint32_t r, std::span<uint64_t> row) {
        if (r == 1)
            row[0] = 3;
        return true;
    });
    Culler culler(zone, &pvs);
    Camera camera;
    camera.position = {5, 0, 0};
    camera.yaw_degrees = 180.0f;
    std::vector<uint32_t> visible;
    const CullStats s = culler.cull(camera, {CullMode::Pvs, false}, visible);
    EXPECT_EQ(s.region, 0);
    EXPECT_EQ(visible, std::vector<uint32_t>{0});
}

TEST(Culler, ModeNamesRoundTrip)
{
    for (CullMode m : {CullMode::None, CullMode::Frustum, CullMode::Pvs, CullMode::PvsFrustum})
        EXPECT_EQ(parse_cull_mode(cull_mode_name(m)), m);
    EXPECT_FALSE(parse_cull_mode("everything").has_value());
}

// The row's regions, a word of them at a time (row_word_boxes.h), with or without the stage
// clock: the drawn list is exactly each candidate's own box test, over 4096 playable cameras.
TEST_F(CullE1m1, WordStageDrawsExactlyWhatPerRegionTestsWould)
{
    Camera lens;
    lens.aspect = 4.0f / 3.0f;
    const std::vector<Camera> cameras = random_cameras_in_regions(*zone_, 4096, 2026, lens);
    Culler culler(*zone_, &*zone_->baked_pvs);
    std::vector<uint32_t> visible;
    std::vector<uint64_t> row(zone_->baked_pvs->words_per_row());
    size_t drawn = 0;
    for (const Camera& camera : cameras) {
        const CullStats stats = culler.cull(camera, {CullMode::PvsFrustum, false, false}, visible);
        ASSERT_GE(stats.region, 0);
        zone_->baked_pvs->decode_row(uint32_t(stats.region), row);
        const Frustum frustum = Frustum::from_view_projection(camera.view_projection());
        // The culler's rule: the side planes only when the far plane lies beyond the whole zone.
        const Aabb world = zone_->bounds();
        const glm::vec3 d = glm::max(glm::abs(world.min - camera.position), glm::abs(world.max - camera.position));
        const bool sides_only = glm::dot(d, d) < camera.far_distance * camera.far_distance;
        std::vector<uint32_t> expected;
        for (uint32_t r = 0; r < zone_->region_count(); ++r) {
            const Aabb& box = zone_->regions[r].bounds;
            if ((bits::test(row, r) || r == uint32_t(stats.region)) &&
                (sides_only ? frustum.intersects_sides(box) : frustum.intersects(box)))
                expected.push_back(r);
        }
        ASSERT_EQ(visible, expected);
        drawn += visible.size();
    }
    EXPECT_GT(drawn, 4096u * 10);
}

TEST_F(CullE1m1, CameraExactlyOnASplitPlaneGetsTheTieRulesRegion)
{
    // The player start projected onto the plane of an axial node on its path (an axial plane so
    // the point is exactly on it: the other two terms of the dot product are exactly 0). The
    // deepest such node whose projected point still reaches that node and lies in a region.
    ASSERT_EQ(zone_->tree.tie_rule, TieRule::OnPlaneGoesBack);
    const glm::vec3 start{480, -352, 88};
    std::vector<PathStep> path, q_path;
    ASSERT_TRUE(trace_point(zone_->tree, start, path).in_region());
    std::optional<glm::vec3> on_plane;
    uint32_t node_index = 0;
    for (auto step = path.rbegin(); step != path.rend() && !on_plane; ++step) {
        const BspNode& node = zone_->tree.nodes[step->node];
        int axis = -1;
        for (int a = 0; a < 3; ++a)
            if (std::abs(node.normal[a]) == 1.0f)
                axis = a;
        if (axis < 0)
            continue;
        glm::vec3 q = start;
        q[axis] = node.dist * node.normal[axis];
        const float d = node.normal.x * q.x + node.normal.y * q.y + node.normal.z * q.z - node.dist;
        if (d != 0.0f || !locate_point(zone_->tree, q).in_region())
            continue;
        trace_point(zone_->tree, q, q_path);
        const auto at =
            std::find_if(q_path.begin(), q_path.end(), [&](const PathStep& s) { return s.node == step->node; });
        if (at == q_path.end())
            continue;
        EXPECT_EQ(at->side, 1) << "on the plane of node " << step->node << ": Quake sends d == 0 to the back child";
        on_plane = q;
        node_index = step->node;
    }
    ASSERT_TRUE(on_plane.has_value()) << "no axial node on the player start's path gives an in-world point";

    const PointLocation expected = locate_point(zone_->tree, *on_plane);
    Culler culler(*zone_, &*zone_->baked_pvs);
    std::vector<uint32_t> visible;
    for (float yaw : {0.0f, 90.0f, 180.0f, 270.0f}) {
        Camera camera;
        camera.position = *on_plane;
        camera.yaw_degrees = yaw;
        const CullStats s = culler.cull(camera, {CullMode::PvsFrustum, false}, visible);
        EXPECT_EQ(s.camera, CameraPlace::InRegion) << "node " << node_index;
        EXPECT_EQ(s.region, expected.region) << "node " << node_index << ", yaw " << yaw;
        EXPECT_TRUE(s.pvs_used);
        EXPECT_FALSE(visible.empty()) << "yaw " << yaw;
    }
    // Before the frustum (which may drop the camera's own region when it lies behind the camera),
    // the PVS stage keeps the region's own row, which holds the region itself.
    Camera camera;
    camera.position = *on_plane;
    const CullStats pvs_only = culler.cull(camera, {CullMode::Pvs, false}, visible);
    EXPECT_EQ(pvs_only.region, expected.region);
    EXPECT_TRUE(std::binary_search(visible.begin(), visible.end(), uint32_t(expected.region)));
}


// ---- The distance stage (CullOptions::distance_stage) on an outdoor zone ----

// The far plane's reach, from the frustum itself: the farthest of its corners, unprojected from
// clip space (not the culler's formula).
float far_corner_distance(const Camera& camera)
{
    const glm::mat4 inverse = glm::inverse(camera.view_projection());
    float farthest = 0.0f;
    for (float x : {-1.0f, 1.0f})
        for (float y : {-1.0f, 1.0f}) {
            const glm::vec4 p = inverse * glm::vec4(x, y, 1.0f, 1.0f);
            farthest = std::max(farthest, glm::length(glm::vec3(p) / p.w - camera.position));
        }
    return farthest;
}

float box_distance(const Aabb& box, glm::vec3 p)
{
    const glm::vec3 d = glm::max(glm::max(box.min - p, p - box.max), glm::vec3(0.0f));
    return glm::length(d);
}

// Seeded cameras at region centres, looking anywhere level-ish, with the given far plane.
std::vector<Camera> cameras_in_regions(const Zone& zone, size_t count, float far, uint32_t seed)
{
    std::vector<Camera> out;
    std::mt19937 rng(seed);
    std::uniform_int_distribution<size_t> region(0, zone.region_count() - 1);
    std::uniform_real_distribution<float> yaw(0.0f, 360.0f), pitch(-30.0f, 30.0f);
    while (out.size() < count) {
        Camera c;
        c.position = zone.regions[region(rng)].bounds.center();
        c.yaw_degrees = yaw(rng);
        c.pitch_degrees = pitch(rng);
        c.far_distance = far;
        out.push_back(c);
    }
    return out;
}

class CullOutdoor : public ::testing::Test {
protected:
    static void SetUpTestSuite() { zone_ = new Zone(gen::generate_outdoor_zone({})); }
    static void TearDownTestSuite() { delete zone_; }
    static std::vector<Camera> cameras(size_t count, float far) { return cameras_in_regions(*zone_, count, far, 11); }
    static Zone* zone_;
};
Zone* CullOutdoor::zone_ = nullptr;

TEST_F(CullOutdoor, DistanceStageKeepsExactlyTheRegionsWithinTheFarPlanesReach)
{
    Culler culler(*zone_, nullptr);
    std::vector<uint32_t> visible;
    for (const Camera& camera : cameras(20, 640.0f)) {
        CullOptions options{CullMode::None, false};
        options.distance_stage = true;
        const CullStats stats = culler.cull(camera, options, visible);
        const float reach = far_corner_distance(camera);
        std::vector<uint32_t> expected;
        for (uint32_t r = 0; r < zone_->region_count(); ++r) {
            const float d = box_distance(zone_->regions[r].bounds, camera.position);
            ASSERT_TRUE(std::abs(d - reach) > 0.01f) << "no box this close to the reach: the test would be ambiguous";
            if (d < reach)
                expected.push_back(r);
        }
        EXPECT_EQ(visible, expected);
        EXPECT_EQ(stats.regions_after_distance, expected.size());
        EXPECT_LT(expected.size(), zone_->region_count() / 4) << "a far clip of ten cells drops most of the zone";
    }
}

TEST_F(CullOutdoor, DistanceStageNeverDropsARegionWithAPointInTheFrustum)
{
    Culler culler(*zone_, nullptr);
    std::vector<uint32_t> with_stage, without_stage;
    size_t checked = 0; // points that fell in open cells
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> ndc(-1.0f, 1.0f);
    for (const Camera& camera : cameras(20, 640.0f)) {
        CullOptions options{CullMode::Frustum, false};
        culler.cull(camera, options, without_stage);
        options.distance_stage = true;
        const CullStats stats = culler.cull(camera, options, with_stage);
        EXPECT_LE(with_stage.size(), without_stage.size());
        EXPECT_LE(stats.regions_after_frustum, stats.regions_after_distance);
        // Points of the view volume, out to the far plane, and the regions they lie in.
        const glm::mat4 inverse = glm::inverse(camera.view_projection());
        for (int i = 0; i < 2000; ++i) {
            const glm::vec4 p = inverse * glm::vec4(ndc(rng), ndc(rng), std::abs(ndc(rng)), 1.0f);
            const glm::vec3 point = glm::vec3(p) / p.w;
            const PointLocation at = locate_point(zone_->tree, point);
            // The tree sends points beyond the world's box to boundary leaves: only points in
            // their region's box count.
            if (at.in_region() && zone_->regions[size_t(at.region)].bounds.contains(point)) {
                ++checked;
                ASSERT_TRUE(std::binary_search(with_stage.begin(), with_stage.end(), uint32_t(at.region)))
                    << "region " << at.region << " has a point in the view volume; distance "
                    << box_distance(zone_->regions[size_t(at.region)].bounds, camera.position) << ", reach "
                    << far_corner_distance(camera);
            }
        }
    }
    EXPECT_GT(checked, 10000u);
}

} // namespace
// Zones this big cull by blocks of regions (region_blocks.h): the drawn list is exactly the
// per-region answer, with a PVS row or without, with a far plane or without.
TEST(CullOutdoorBlocks, BlockStageDrawsExactlyWhatPerRegionTestsWould)
{
    gen::OutdoorParams params;
    params.size = 1536.0f; // 24 columns, 5 200 regions
    const std::unique_ptr<Zone> zone_ = std::make_unique<Zone>(gen::generate_outdoor_zone(params));
    ASSERT_GE(zone_->region_count(), kBlocksFrom);
    std::mt19937 rng(17);
    const auto cameras = [&](size_t count, float far) { return cameras_in_regions(*zone_, count, far, uint32_t(rng())); };
    std::bernoulli_distribution keep(0.7);
    const Pvs pvs = Pvs::build(uint32_t(zone_->region_count()), [&](uint32_t r, std::span<uint64_t> row) {
        for (uint32_t c = 0; c < zone_->region_count(); ++c)
            if (c == r || keep(rng))
                bits::set(row, c);
        return true;
    });
    Culler culler(*zone_, &pvs);
    std::vector<uint32_t> visible;
    std::vector<uint64_t> row(pvs.words_per_row());
    size_t drawn = 0;
    for (const float far : {16384.0f, 500.0f})
        for (const Camera& camera : cameras(40, far))
            for (const CullMode mode : {CullMode::PvsFrustum, CullMode::Frustum}) {
                CullOptions options{mode, false};
                options.distance_stage = far < 16384.0f;
                const CullStats stats = culler.cull(camera, options, visible);
                const Frustum frustum = Frustum::from_view_projection(camera.view_projection());
                const bool sides_only = far >= 16384.0f; // the far plane is beyond the whole zone
                const float reach = far_corner_distance(camera);
                pvs.decode_row(uint32_t(stats.region), row);
                std::vector<uint32_t> expected;
                for (uint32_t r = 0; r < zone_->region_count(); ++r) {
                    const Aabb& box = zone_->regions[r].bounds;
                    if (mode == CullMode::PvsFrustum && !bits::test(row, r))
                        continue;
                    if (options.distance_stage) {
                        const float d = box_distance(box, camera.position);
                        ASSERT_TRUE(std::abs(d - reach) > 0.01f) << "ambiguous: no box this close to the reach";
                        if (d > reach)
                            continue;
                    }
                    if (sides_only ? frustum.intersects_sides(box) : frustum.intersects(box))
                        expected.push_back(r);
                }
                ASSERT_EQ(visible, expected) << "far " << far << ", mode " << cull_mode_name(mode);
                drawn += visible.size();
            }
    EXPECT_GT(drawn, 5000u);
}

} // namespace pvs
