// Orbit, aiming and pixel rays (ui/gui/camera_math.h) against positions worked out by hand, and
// the inspector's orbit, field of view and picked point.
#include "ui/gui/camera_math.h"
#include "ui/gui/inspector_state.h"
#include "render/overlay_fill.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace pvs {
namespace {

void expect_near(const glm::vec3& a, const glm::vec3& b, float tolerance)
{
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(CameraMath, AimAlongPointsTheCameraThere)
{
    Camera c;
    gui::aim_along(c, {0, -3, 0}, 89.0f);
    EXPECT_NEAR(c.yaw_degrees, -90.0f, 1e-4f);
    EXPECT_NEAR(c.pitch_degrees, 0.0f, 1e-4f);
    gui::aim_along(c, {1, 0, 1}, 89.0f);
    EXPECT_NEAR(c.yaw_degrees, 0.0f, 1e-4f);
    EXPECT_NEAR(c.pitch_degrees, 45.0f, 1e-4f);
    gui::aim_along(c, {0, 0, -1}, 80.0f); // straight down: clamped
    EXPECT_NEAR(c.pitch_degrees, -80.0f, 1e-4f);
    const float yaw = c.yaw_degrees;
    gui::aim_along(c, {0, 0, 0}, 80.0f); // no direction: unchanged
    EXPECT_EQ(c.yaw_degrees, yaw);
}

TEST(CameraMath, OrbitTurnsAboutTheTargetAtTheSameDistance)
{
    Camera c;
    c.position = {10, 0, 0};
    gui::aim_along(c, -c.position, 89.0f); // looking at the origin: yaw 180
    gui::orbit_about(c, {0, 0, 0}, 90.0f, 0.0f, 89.0f);
    // yaw 270: forward (0, -1, 0), so the camera sits at (0, 10, 0).
    expect_near(c.position, {0, 10, 0}, 1e-4f);
    expect_near(c.forward(), {0, -1, 0}, 1e-5f);
    gui::orbit_about(c, {0, 0, 0}, 0.0f, -30.0f, 89.0f); // look down 30 degrees: rise to z = 10 sin 30
    expect_near(c.position, {0, 10 * std::cos(glm::radians(30.0f)), 5}, 1e-3f);
    EXPECT_NEAR(glm::length(c.position), 10.0f, 1e-4f);
    gui::orbit_about(c, {0, 0, 0}, 0.0f, -200.0f, 89.0f);
    EXPECT_NEAR(c.pitch_degrees, -89.0f, 1e-4f);
    EXPECT_NEAR(glm::length(c.position), 10.0f, 1e-3f);
}

TEST(CameraMath, PixelRayGoesThroughThePixelCentre)
{
    Camera c;
    c.position = {5, 6, 7};
    c.yaw_degrees = 30;
    c.pitch_degrees = -10;
    c.aspect = 2.0f;
    const gui::Ray centre = gui::pixel_ray(c, 201, 101, 100, 50);
    expect_near(centre.direction, c.forward(), 1e-4f);
    // Any pixel: a point along its ray projects back onto the pixel's centre.
    for (auto [x, y] : {std::pair{0u, 0u}, std::pair{200u, 100u}, std::pair{37u, 81u}}) {
        const gui::Ray ray = gui::pixel_ray(c, 201, 101, x, y);
        const auto back = ui::project_to_pixel(c, 201, 101, ray.origin + ray.direction * 50.0f);
        ASSERT_TRUE(back);
        EXPECT_NEAR(back->x, float(x) + 0.5f, 1e-2f);
        EXPECT_NEAR(back->y, float(y) + 0.5f, 1e-2f);
    }
}

struct DemoCamera : ::testing::Test {
    void SetUp() override
    {
        state.set_viewport_size(160, 120);
        state.open_demo();
    }
    gui::InspectorState state;
};

TEST_F(DemoCamera, PickGivesThePointUnderThePixelAndOrbitKeepsLookingAtIt)
{
    state.frame();
    const auto picked = state.pick(80, 60);
    ASSERT_TRUE(picked);
    ASSERT_TRUE(picked->point);
    // The point is in front of the camera and projects onto the clicked pixel.
    const auto back = ui::project_to_pixel(state.view_camera(), 160, 120, *picked->point);
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->x, 80.5f, 0.05f);
    EXPECT_NEAR(back->y, 60.5f, 0.05f);

    const glm::vec3 target = *picked->point;
    state.set_orbit_target(target);
    const float distance = glm::length(state.view_camera().position - target);
    for (int i = 0; i < 5; ++i) {
        state.orbit(25.0f, -7.0f);
        const Camera& c = state.view_camera();
        EXPECT_NEAR(glm::length(c.position - target), distance, distance * 1e-4f);
        expect_near(c.forward(), glm::normalize(target - c.position), 1e-3f);
        expect_near(state.cull_camera().position, c.position, 0.0f); // unlocked: culling follows
    }
    state.set_lock(true);
    const glm::vec3 locked_at = state.cull_camera().position;
    state.orbit(40.0f, 0.0f);
    expect_near(state.cull_camera().position, locked_at, 0.0f);
    state.set_orbit_target(std::nullopt);
    const glm::vec3 before = state.view_camera().position;
    state.orbit(40.0f, 0.0f); // no target: nothing
    expect_near(state.view_camera().position, before, 0.0f);
}

TEST_F(DemoCamera, FieldOfViewIsClampedAndReachesTheCuller)
{
    state.set_fov(30.0f);
    EXPECT_EQ(state.view_camera().fov_y_degrees, 30.0f);
    EXPECT_EQ(state.cull_camera().fov_y_degrees, 30.0f);
    const uint32_t narrow = state.frame().regions_after_frustum;
    state.set_fov(120.0f);
    const uint32_t wide = state.frame().regions_after_frustum;
    EXPECT_GE(wide, narrow);
    state.set_fov(1000.0f);
    EXPECT_EQ(state.view_camera().fov_y_degrees, gui::kMaxFovDegrees);
    state.set_fov(-5.0f);
    EXPECT_EQ(state.view_camera().fov_y_degrees, gui::kMinFovDegrees);
    state.set_fov(NAN);
    EXPECT_EQ(state.view_camera().fov_y_degrees, 70.0f);
}

TEST_F(DemoCamera, GoToRegionAndReset)
{
    const Zone& zone = state.zone();
    const uint32_t last = uint32_t(zone.region_count() - 1);
    state.go_to_region(last);
    expect_near(state.view_camera().position, zone.regions[last].bounds.center(), 0.0f);
    EXPECT_EQ(state.frame().region, int32_t(last)); // a generated region is a box: its centre is in it
    state.reset_camera();
    const glm::vec3 start = state.view_camera().position;
    state.go_to_region(uint32_t(zone.region_count())); // out of range: ignored
    expect_near(state.view_camera().position, start, 0.0f);
}

} // namespace
} // namespace pvs
