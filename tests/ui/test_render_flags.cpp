// The Flags render mode (the textured picture tinted by region flags), the overlay lines, and the
// locked culling camera (render_culled): a synthetic wall of quads owned by an unflagged, a water
// and a zone-line region, measured against the Textured picture of the same pixels; lines drawn
// on blank images; and on e1m1, tinted pixels from inside the slime and the water, and the lock.
#include "tests/support/test_data.h"
#include "render/overlay_lines.h"
#include "render/culled_frame.h"
#include "render/software_renderer.h"
#include "visibility/culler.h"
#include "visibility/region_lookup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <map>
#include <set>

namespace pvs {
namespace {

using ui::Image;
using ui::RenderMode;
using ui::SoftwareRenderer;

struct Rgb {
    int r, g, b;
};
Rgb rgb_of(const Image& image, uint32_t x, uint32_t y)
{
    const uint8_t* p = image.pixel(x, y);
    return {p[0], p[1], p[2]};
}
bool same_pixel(const Image& a, const Image& b, uint32_t x, uint32_t y)
{
    return std::equal(a.pixel(x, y), a.pixel(x, y) + 4, b.pixel(x, y));
}

// Pixels of each face in an ID buffer whose 3x3 neighbourhood shows the same face: the
// comparisons between modes stay off the edges, where one rasteriser may give a pixel to the
// neighbouring face.
std::map<uint32_t, std::vector<std::pair<uint32_t, uint32_t>>> interior_pixels(const Image& ids)
{
    std::map<uint32_t, std::vector<std::pair<uint32_t, uint32_t>>> out;
    for (uint32_t y = 1; y + 1 < ids.height; ++y)
        for (uint32_t x = 1; x + 1 < ids.width; ++x) {
            const uint32_t face = ui::face_at(ids, x, y);
            if (face == ui::kNoFace)
                continue;
            bool interior = true;
            for (int dy = -1; dy <= 1 && interior; ++dy)
                for (int dx = -1; dx <= 1 && interior; ++dx)
                    interior = ui::face_at(ids, uint32_t(int(x) + dx), uint32_t(int(y) + dy)) == face;
            if (interior)
                out[face].emplace_back(x, y);
        }
    return out;
}

// ---- The flag table ------------------------------------------------------------------------------

TEST(FlagTints, EveryFlagHasOneEntryAndZoneLinesComeFirst)
{
    std::set<uint32_t> flags, colours;
    for (const ui::FlagTint& t : ui::kFlagTints) {
        flags.insert(t.flag);
        colours.insert(t.rgb);
        EXPECT_EQ(t.rgb & 0xFF000000u, 0u);
    }
    EXPECT_EQ(flags.size(), size_t(kRegionFlagCount));
    for (uint32_t bit = 0; bit < kRegionFlagCount; ++bit)
        EXPECT_TRUE(flags.count(1u << bit)) << region_flag_name(1u << bit);
    EXPECT_EQ(colours.size(), size_t(kRegionFlagCount)) << "two flags share a colour";
    EXPECT_EQ(ui::kFlagTints[0].flag, uint32_t(kRegionZoneLine));

    EXPECT_EQ(ui::flag_tint_index(0), ui::kNoTint);
    EXPECT_EQ(ui::kFlagTints[ui::flag_tint_index(kRegionWater)].flag, uint32_t(kRegionWater));
    EXPECT_EQ(ui::kFlagTints[ui::flag_tint_index(kRegionWater | kRegionZoneLine)].flag, uint32_t(kRegionZoneLine));
    EXPECT_EQ(ui::kFlagTints[ui::flag_tint_index(kRegionLava | kRegionSky)].flag, uint32_t(kRegionLava));
    EXPECT_EQ(ui::flag_tint_index(1u << 20), ui::kNoTint) << "a bit that is no RegionFlag";
}

TEST(FlagTints, BlendIsHalfAndHalf)
{
    static_assert(ui::kFlagTintAlpha == 128);
    EXPECT_EQ(ui::blend_tint(0x000000, 0xFFFFFF), 0x808080u);
    EXPECT_EQ(ui::blend_tint(0xFFFFFF, 0x000000), 0x808080u);
    EXPECT_EQ(ui::blend_tint(0x204060, 0x204060), 0x204060u);
    EXPECT_EQ(ui::blend_tint(0x102030, 0x305070), 0x203850u);
}

TEST(RenderModes, FlagsIsAModeWithAName)
{
    EXPECT_EQ(ui::parse_render_mode("flags"), RenderMode::Flags);
    EXPECT_STREQ(ui::render_mode_name(RenderMode::Flags), "flags");
    for (RenderMode m : ui::kRenderModes)
        EXPECT_EQ(ui::parse_render_mode(ui::render_mode_name(m)), m);
}

// ---- Flags on a synthetic wall -----------------------------------------------------------------

// flagged_wall(): a wall at x = 10 facing the camera at the origin (looking along +x), six quads in three
// columns of two; left of the view is +y. Top row: material 0 (an 8x8 checker texture); bottom
// row: material 1 (no pixels: a flat colour).
//   region 0, no flags:            column y 3..9    faces 0 (top), 1 (bottom)
//   region 1, water:               column y -3..3   faces 2, 3   (also lists face 0)
//   region 2, water + zone line:   column y -9..-3  faces 4, 5

// The quad y0 .. y1 (y0 < y1), z0 .. z1 of the wall, counter-clockwise seen from the camera's
// side (-x), the model's convention for a face's front.
void add_wall_quad(Zone& zone, float y0, float y1, float z0, float z1, uint32_t material)
{
    Mesh& mesh = zone.mesh;
    const auto base = uint32_t(mesh.positions.size());
    const glm::vec3 a{10, y1, z0}, b{10, y0, z0}, c{10, y0, z1}, d{10, y1, z1};
    EXPECT_LT(glm::cross(b - a, c - a).x, 0.0f) << "the quad must face -x";
    for (const glm::vec3& p : {a, b, c, d}) {
        mesh.positions.push_back(p);
        mesh.uvs.push_back({p.y / 3.0f, p.z / 3.0f});
    }
    mesh.faces.push_back({uint32_t(mesh.triangle_count()), 2, material});
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
        mesh.indices.push_back(base + i);
}

Zone flagged_wall()
{
    Zone zone;
    const float columns[3][2] = {{3, 9}, {-3, 3}, {-9, -3}};
    for (const auto& col : columns) {
        add_wall_quad(zone, col[0], col[1], 0, 6, 0);
        add_wall_quad(zone, col[0], col[1], -6, 0, 1);
    }
    zone.regions.resize(3);
    for (uint32_t r = 0; r < 3; ++r) {
        zone.regions[r].bounds.grow({0, columns[r][0], -6});
        zone.regions[r].bounds.grow({10, columns[r][1], 6});
    }
    zone.regions[1].flags = kRegionWater;
    zone.regions[2].flags = kRegionWater | kRegionZoneLine;
    zone.regions[2].zone_line = 0;
    zone.zone_lines.push_back({"elsewhere", zone.regions[2].bounds});
    zone.region_faces = {0, 1, /* region 1 */ 2, 3, 0, /* region 2 */ 4, 5};
    zone.region_face_offsets = {0, 2, 5, 7};

    Material checker{"checker", 8, 8, {}, 0};
    std::vector<uint8_t> rgba;
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 0; x < 8; ++x) {
            const bool light = (x + y) % 2 == 0;
            const uint8_t texel[4] = {uint8_t(light ? 150 : 90), uint8_t(light ? 120 : 80), uint8_t(light ? 100 : 70),
                                      255};
            rgba.insert(rgba.end(), texel, texel + 4);
        }
    set_material_rgba(checker, 8, 8, rgba);
    zone.materials.push_back(checker);
    zone.materials.push_back({"plain", 0, 0, {}, 0});
    return zone;
}

Camera wall_camera()
{
    Camera camera; // at the origin, looking along +x
    camera.aspect = 4.0f / 3.0f;
    return camera;
}

class FlagsOnAWall : public ::testing::Test {
protected:
    void SetUp() override
    {
        ids_ = renderer_.render(zone_, wall_camera(), {0, 1, 2}, RenderMode::IdBuffer);
        textured_ = renderer_.render(zone_, wall_camera(), {0, 1, 2}, RenderMode::Textured);
        flags_ = renderer_.render(zone_, wall_camera(), {0, 1, 2}, RenderMode::Flags);
        interior_ = interior_pixels(ids_);
        for (uint32_t f = 0; f < 6; ++f)
            ASSERT_GE(interior_[f].size(), 100u) << "face " << f << " is not well in view";
    }
    const Zone zone_ = flagged_wall();
    SoftwareRenderer renderer_{160, 120};
    Image ids_, textured_, flags_;
    std::map<uint32_t, std::vector<std::pair<uint32_t, uint32_t>>> interior_;
};

// ---- Translucent faces (Quake 2 glass) -------------------------------------------------------------

// A pane in front of the flagged wall (x = 5, facing the camera), listed by region 1: with a
// translucent material (two thirds opaque, SURF_TRANS66) each of its pixels is the blend of its
// own colour (the pane drawn opaque) and the wall behind it (the picture without the pane), at
// Quake 2's alpha; in the ID picture it stays opaque (one face a pixel).
TEST(TranslucentFaces, BlendOverWhatIsBehindThem)
{
    Zone without = flagged_wall();
    Zone opaque = without;
    {
        Mesh& mesh = opaque.mesh;
        const auto base = uint32_t(mesh.positions.size());
        const glm::vec3 a{5, 2, -2}, b{5, -2, -2}, c{5, -2, 2}, d{5, 2, 2};
        for (const glm::vec3& p : {a, b, c, d}) {
            mesh.positions.push_back(p);
            mesh.uvs.push_back({0.0f, 0.0f});
        }
        opaque.materials.push_back({"glass", 0, 0, {}, 0});
        mesh.faces.push_back({uint32_t(mesh.triangle_count()), 2, uint32_t(opaque.materials.size() - 1)});
        for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
            mesh.indices.push_back(base + i);
        opaque.region_faces.insert(opaque.region_faces.begin() + opaque.region_face_offsets[2], 6u);
        ++opaque.region_face_offsets[2];
        ++opaque.region_face_offsets[3];
    }
    Zone glass = opaque;
    glass.materials.back().flags = kMaterialTranslucent;
    SoftwareRenderer renderer{160, 120};
    const std::vector<uint32_t> all{0, 1, 2};
    const Image behind = renderer.render(without, wall_camera(), all, RenderMode::Textured);
    const Image pane = renderer.render(opaque, wall_camera(), all, RenderMode::Textured);
    const Image blended = renderer.render(glass, wall_camera(), all, RenderMode::Textured);
    const Image opaque_ids = renderer.render(opaque, wall_camera(), all, RenderMode::IdBuffer);
    const Image glass_ids = renderer.render(glass, wall_camera(), all, RenderMode::IdBuffer);
    EXPECT_EQ(opaque_ids.rgba, glass_ids.rgba) << "the ID picture keeps the pane opaque";
    const auto pixels = interior_pixels(opaque_ids)[6];
    ASSERT_GE(pixels.size(), 100u);
    const float alpha = 168.0f / 255.0f;
    size_t differ = 0;
    for (const auto& [x, y] : pixels) {
        const Rgb p = rgb_of(pane, x, y), w = rgb_of(behind, x, y), got = rgb_of(blended, x, y);
        const Rgb want{int(std::lround(alpha * float(p.r) + (1 - alpha) * float(w.r))),
                       int(std::lround(alpha * float(p.g) + (1 - alpha) * float(w.g))),
                       int(std::lround(alpha * float(p.b) + (1 - alpha) * float(w.b)))};
        ASSERT_NEAR(got.r, want.r, 3) << "at " << x << "," << y; // Burning blends in fixed point
        ASSERT_NEAR(got.g, want.g, 3) << "at " << x << "," << y;
        ASSERT_NEAR(got.b, want.b, 3) << "at " << x << "," << y;
        differ += std::abs(p.r - w.r) + std::abs(p.g - w.g) + std::abs(p.b - w.b) > 30;
    }
    EXPECT_GT(differ, pixels.size() / 2) << "the pane and the wall must differ for the blend to show";
}

TEST_F(FlagsOnAWall, UnflaggedRegionsPixelsAreExactlyTheTexturedOnes)
{
    EXPECT_EQ(renderer_.last_stats().faces_drawn, 6u);
    // Face 0 is listed by region 0 (no flags) and region 1 (water): region 0, the first, owns it.
    for (uint32_t face : {0u, 1u})
        for (const auto& [x, y] : interior_[face])
            ASSERT_TRUE(same_pixel(flags_, textured_, x, y)) << "face " << face << " at " << x << "," << y;
    // And every pixel whose 3x3 neighbourhood holds no tinted face (background included).
    size_t compared = 0;
    for (uint32_t y = 1; y + 1 < ids_.height; ++y)
        for (uint32_t x = 1; x + 1 < ids_.width; ++x) {
            bool untinted = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const uint32_t f = ui::face_at(ids_, uint32_t(int(x) + dx), uint32_t(int(y) + dy));
                    untinted = untinted && (f == ui::kNoFace || f <= 1);
                }
            if (untinted) {
                ++compared;
                ASSERT_TRUE(same_pixel(flags_, textured_, x, y)) << "at " << x << "," << y;
            }
        }
    EXPECT_GT(compared, 2000u);
}

TEST_F(FlagsOnAWall, WaterFacesAreBluerTexturedOrFlat)
{
    for (uint32_t face : {2u, 3u}) {
        for (const auto& [x, y] : interior_[face]) {
            const Rgb t = rgb_of(textured_, x, y), f = rgb_of(flags_, x, y);
            ASSERT_GT(f.b, t.b) << "face " << face << " at " << x << "," << y;
            ASSERT_LT(f.r, t.r) << "face " << face << " at " << x << "," << y;
            ASSERT_GT(f.b - (f.r + f.g) / 2, t.b - (t.r + t.g) / 2 + 40) << "face " << face << " at " << x << "," << y;
        }
    }
}

TEST_F(FlagsOnAWall, ZoneLineWinsOverWater)
{
    // Magenta (0xFF00FF) raises red and lowers green; water blue would lower red.
    for (uint32_t face : {4u, 5u})
        for (const auto& [x, y] : interior_[face]) {
            const Rgb t = rgb_of(textured_, x, y), f = rgb_of(flags_, x, y);
            ASSERT_GT(f.r, t.r) << "face " << face << " at " << x << "," << y;
            ASSERT_LT(f.g, t.g) << "face " << face << " at " << x << "," << y;
            ASSERT_GT(f.b, t.b) << "face " << face << " at " << x << "," << y;
        }
}

TEST_F(FlagsOnAWall, AFaceSharedWithAnInvisibleRegionTakesTheVisibleOnesFlags)
{
    // Without region 0, face 0 is owned by region 1 (water) and turns blue.
    const Image textured = renderer_.render(zone_, wall_camera(), {1, 2}, RenderMode::Textured);
    const Image flags = renderer_.render(zone_, wall_camera(), {1, 2}, RenderMode::Flags);
    EXPECT_EQ(renderer_.last_stats().faces_drawn, 5u);
    for (const auto& [x, y] : interior_[0]) {
        const Rgb t = rgb_of(textured, x, y), f = rgb_of(flags, x, y);
        ASSERT_GT(f.b, t.b) << "at " << x << "," << y;
    }
    // Deterministic, and the tinted textures made by the first frame are reused.
    const Image again = renderer_.render(zone_, wall_camera(), {1, 2}, RenderMode::Flags);
    EXPECT_EQ(again.rgba, flags.rgba);
    EXPECT_EQ(renderer_.render(zone_, wall_camera(), {0, 1, 2}, RenderMode::Flags).rgba, flags_.rgba);
}

// ---- Overlay lines -----------------------------------------------------------------------------

Image blank(uint32_t width, uint32_t height)
{
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.assign(size_t(width) * height * 4, 0);
    return image;
}
bool is_set(const Image& image, uint32_t x, uint32_t y, uint32_t rgb)
{
    const uint8_t* p = image.pixel(x, y);
    return p[0] == uint8_t(rgb >> 16) && p[1] == uint8_t(rgb >> 8) && p[2] == uint8_t(rgb) && p[3] == 255;
}
size_t count_set(const Image& image)
{
    size_t n = 0;
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x)
            n += image.pixel(x, y)[3] != 0;
    return n;
}

TEST(OverlayLines, HorizontalAndDiagonalLinesSetTheirPixels)
{
    Image image = blank(20, 10);
    EXPECT_EQ(ui::draw_line_2d(image, {2.5f, 3.5f}, {15.5f, 3.5f}, 0xFF0000), 14u);
    for (uint32_t x = 2; x <= 15; ++x)
        EXPECT_TRUE(is_set(image, x, 3, 0xFF0000)) << x;
    EXPECT_EQ(count_set(image), 14u);

    image = blank(20, 10);
    EXPECT_EQ(ui::draw_line_2d(image, {0.5f, 0.5f}, {9.5f, 9.5f}, 0x00FF00), 10u);
    for (uint32_t i = 0; i < 10; ++i)
        EXPECT_TRUE(is_set(image, i, i, 0x00FF00)) << i;
    EXPECT_FALSE(is_set(image, 5, 4, 0x00FF00));
    EXPECT_EQ(count_set(image), 10u);
}

TEST(OverlayLines, ASlopedLineHasBothEndsAndOnePixelPerColumn)
{
    Image image = blank(20, 10);
    ui::draw_line_2d(image, {1.5f, 1.5f}, {17.5f, 8.5f}, 0xFFFF00);
    EXPECT_TRUE(is_set(image, 1, 1, 0xFFFF00));
    EXPECT_TRUE(is_set(image, 17, 8, 0xFFFF00));
    for (uint32_t x = 1; x <= 17; ++x) {
        uint32_t in_column = 0;
        for (uint32_t y = 0; y < 10; ++y)
            in_column += is_set(image, x, y, 0xFFFF00);
        EXPECT_EQ(in_column, 1u) << "column " << x;
    }
    // The middle: x = 9 is half way, y = 1 + 7/2 = 4.5 -> row 4 or 5.
    EXPECT_TRUE(is_set(image, 9, 4, 0xFFFF00) || is_set(image, 9, 5, 0xFFFF00));
    EXPECT_EQ(count_set(image), 17u);
}

TEST(OverlayLines, LinesAreClippedToTheImage)
{
    Image image = blank(20, 10);
    EXPECT_EQ(ui::draw_line_2d(image, {-1e9f, 5.5f}, {1e9f, 5.5f}, 0x0000FF), 20u);
    for (uint32_t x = 0; x < 20; ++x)
        EXPECT_TRUE(is_set(image, x, 5, 0x0000FF));
    image = blank(20, 10);
    EXPECT_EQ(ui::draw_line_2d(image, {-5.0f, -5.0f}, {30.0f, -1.0f}, 0x0000FF), 0u);
    EXPECT_EQ(ui::draw_line_2d(image, {20.0f, 0.0f}, {20.0f, 10.0f}, 0x0000FF), 0u) << "on the right edge";
    EXPECT_EQ(ui::draw_line_2d(image, {std::nanf(""), 1.0f}, {5.0f, 5.0f}, 0x0000FF), 0u);
    EXPECT_EQ(count_set(image), 0u);
}

// The 3-D lines use a camera at the origin looking along +x, vertical fov 70, 160x120. Worked out
// by hand: tan 35 deg = 0.7002, so at distance 10 the view spans z +-7.002 and y +-9.336; a
// point (10, y, z) lands at pixel x = 80 - 80 y / 9.336, y = 60 - 60 z / 7.002.
constexpr float kZ = 0.0875f; // lands on pixel row 59.25 at distance 10, 52.50 at distance 1

TEST(OverlayLines, ASegmentInFrontOfTheCameraProjectsWhereWorkedOut)
{
    Image image = blank(160, 120);
    const uint32_t set = ui::draw_line_3d(image, wall_camera(), {10, 1, kZ}, {10, -1, kZ}, 0xFFFF00);
    // y = +1 -> x 71.43, y = -1 -> x 88.57: pixels 71 .. 88 of row 59.
    EXPECT_EQ(set, 18u);
    EXPECT_TRUE(is_set(image, 71, 59, 0xFFFF00));
    EXPECT_TRUE(is_set(image, 88, 59, 0xFFFF00));
    EXPECT_TRUE(is_set(image, 80, 59, 0xFFFF00));
    EXPECT_FALSE(is_set(image, 70, 59, 0xFFFF00));
    EXPECT_FALSE(is_set(image, 89, 59, 0xFFFF00));
}

TEST(OverlayLines, LinesBehindTheCameraDrawNothingAndCrossingOnesAreCut)
{
    Image image = blank(160, 120);
    EXPECT_EQ(ui::draw_line_3d(image, wall_camera(), {-10, -1, 0}, {-10, 1, 0}, 0xFFFF00), 0u);
    EXPECT_EQ(ui::draw_line_3d(image, wall_camera(), {-10, -50, 30}, {-0.5f, 50, -30}, 0xFFFF00), 0u);
    EXPECT_EQ(ui::draw_line_3d(image, wall_camera(), {0.5f, 0, 0}, {0.9f, 0, 0}, 0xFFFF00), 0u)
        << "before the near plane";
    EXPECT_EQ(count_set(image), 0u);

    // From behind the camera to 10 ahead, along the view axis raised by kZ: only the part past
    // the near plane (distance 1 .. 10) is drawn, rows 52 .. 59 of column 80; nothing below the
    // centre, where the part behind the camera would have projected had it not been cut.
    const uint32_t set = ui::draw_line_3d(image, wall_camera(), {-10, 0, kZ}, {10, 0, kZ}, 0xFFFF00);
    EXPECT_EQ(set, 8u);
    for (uint32_t y = 52; y <= 59; ++y)
        EXPECT_TRUE(is_set(image, 80, y, 0xFFFF00)) << y;
    for (uint32_t y = 60; y < 120; ++y)
        EXPECT_FALSE(is_set(image, 80, y, 0xFFFF00)) << y;
    EXPECT_EQ(count_set(image), set);
}

TEST(OverlayLines, FrustumCornersAreTheCullersViewVolume)
{
    Camera camera;
    camera.position = {12, -40, 7};
    camera.yaw_degrees = 123.0f;
    camera.pitch_degrees = -21.0f;
    camera.far_distance = 2000.0f;
    const auto corners = ui::frustum_corners(camera);
    const glm::vec2 ndc[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (size_t i = 0; i < 8; ++i) {
        const glm::vec4 c = camera.view_projection() * glm::vec4(corners[i], 1.0f);
        EXPECT_NEAR(c.x / c.w, ndc[i % 4].x, 1e-3) << i;
        EXPECT_NEAR(c.y / c.w, ndc[i % 4].y, 1e-3) << i;
        EXPECT_NEAR(c.z / c.w, i < 4 ? -1.0 : 1.0, 1e-3) << i;
    }
    // Seen from behind and above, the volume is drawn.
    Camera behind = camera;
    behind.position -= camera.forward() * 50.0f - glm::vec3(0, 0, 20);
    behind.pitch_degrees = -35.0f;
    Image image = blank(160, 120);
    EXPECT_GT(ui::draw_frustum(image, behind, camera, ui::kLockedFrustumColor), 150u);
}

// ---- e1m1 --------------------------------------------------------------------------------------

class FlagsE1m1 : public ::testing::Test {
protected:
    void SetUp() override
    {
        SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
        zone_ = test::shared_zone("quake/e1m1.bsp");
        ASSERT_NE(zone_, nullptr);
        ASSERT_TRUE(zone_->baked_pvs.has_value());
    }
    static Camera camera(glm::vec3 position, float yaw, float pitch)
    {
        Camera c;
        c.position = position;
        c.yaw_degrees = yaw;
        c.pitch_degrees = pitch;
        c.aspect = 4.0f / 3.0f;
        return c;
    }
    const Zone* zone_ = nullptr;
};

// A camera inside a liquid: the faces around it belong to the liquid's regions and are tinted;
// every tinted pixel's face is owned by a region with that flag, and untinted faces are the
// Textured pixels.
// `dominant` is the tint's strongest channel (0 r, 1 g, 2 b): on every tinted pixel it gains on
// the other two.
void expect_tinted_view(const Zone& zone, const Camera& camera, uint32_t flag, int dominant, double min_tinted_share)
{
    Culler culler(zone, &*zone.baked_pvs);
    std::vector<uint32_t> visible;
    const CullStats s = culler.cull(camera, {CullMode::PvsFrustum, false}, visible);
    ASSERT_EQ(s.camera, CameraPlace::InRegion);
    ASSERT_TRUE(zone.regions[size_t(s.region)].flags & flag)
        << "the camera is not in a " << region_flag_name(flag) << " region";

    std::map<uint32_t, uint32_t> owner; // face -> first visible region listing it
    for (uint32_t r : visible)
        for (uint32_t f : zone.faces_of_region(r))
            owner.emplace(f, r);

    SoftwareRenderer renderer(320, 240);
    const Image ids = renderer.render(zone, camera, visible, RenderMode::IdBuffer);
    const Image textured = renderer.render(zone, camera, visible, RenderMode::Textured);
    const Image flags = renderer.render(zone, camera, visible, RenderMode::Flags);
    auto score = [dominant](const Rgb& c) {
        const int ch[3] = {c.r, c.g, c.b};
        return ch[dominant] - std::max(ch[(dominant + 1) % 3], ch[(dominant + 2) % 3]);
    };
    size_t tinted = 0, total = 0, toward = 0; // toward: pixels that gained on the dominant channel
    for (const auto& [face, pixels] : interior_pixels(ids)) {
        ASSERT_TRUE(owner.count(face));
        const uint32_t region_flags = zone.regions[owner[face]].flags;
        for (const auto& [x, y] : pixels) {
            ++total;
            if (ui::flag_tint_index(region_flags) == ui::kNoTint) {
                ASSERT_TRUE(same_pixel(flags, textured, x, y)) << "face " << face << " at " << x << "," << y;
                continue;
            }
            if (!(region_flags & flag))
                continue;
            ++tinted;
            toward += score(rgb_of(flags, x, y)) > score(rgb_of(textured, x, y));
        }
    }
    EXPECT_GT(double(tinted), min_tinted_share * double(total)) << tinted << " of " << total;
    EXPECT_EQ(toward, tinted);
}

TEST_F(FlagsE1m1, FromInsideTheSlimeTheViewIsGreen)
{
    // In the slime pool near the end of the level (region 1068), looking along +x.
    expect_tinted_view(*zone_, camera({928, 2496, -492}, 0, 0), kRegionSlime, 1, 0.5);
}

TEST_F(FlagsE1m1, FromInsideTheWaterTheViewIsBlue)
{
    // In the flooded tunnel (region 993), looking along +x.
    expect_tinted_view(*zone_, camera({552, 1208, -316}, 0, 0), kRegionWater, 2, 0.5);
}

TEST_F(FlagsE1m1, TheSlipgateIsMagenta)
{
    // The exit slipgate (trigger_changelevel to e1m2) seen from the room before it.
    const Camera c = camera({1312, 760, -184}, 270, -5);
    Culler culler(*zone_, &*zone_->baked_pvs);
    std::vector<uint32_t> visible;
    culler.cull(c, {CullMode::PvsFrustum, false}, visible);
    SoftwareRenderer renderer(320, 240);
    const Image textured = renderer.render(*zone_, c, visible, RenderMode::Textured);
    const Image flags = renderer.render(*zone_, c, visible, RenderMode::Flags);
    size_t magenta = 0, changed = 0;
    for (uint32_t y = 0; y < flags.height; ++y)
        for (uint32_t x = 0; x < flags.width; ++x) {
            if (same_pixel(flags, textured, x, y))
                continue;
            ++changed;
            const Rgb t = rgb_of(textured, x, y), f = rgb_of(flags, x, y);
            // Magenta (0xFF00FF) raises red and blue and lowers green (or keeps a channel already at
            // the tint's value).
            ASSERT_TRUE(f.r >= t.r && f.g <= t.g && f.b >= t.b) << "at " << x << "," << y;
            magenta += f.r > t.r && f.g < t.g && f.b > t.b;
        }
    EXPECT_GT(changed, 2000u);
    EXPECT_GT(magenta, changed * 9 / 10);
}

// ---- The locked culling camera -----------------------------------------------------------------

TEST_F(FlagsE1m1, LockedCullingGivesTheLockedCamerasVisibleSetAndStats)
{
    const Camera a = camera({480, -352, 88}, 90, 0);     // the player start
    const Camera b = camera({480, -600, 200}, 90, -15);  // behind and above it, looking the same way
    Culler culler(*zone_, &*zone_->baked_pvs);
    const CullOptions options{CullMode::PvsFrustum, true};
    std::vector<uint32_t> visible_a, visible_b;
    const CullStats alone_a = culler.cull(a, options, visible_a);
    const CullStats alone_b = culler.cull(b, options, visible_b);
    ASSERT_NE(visible_a, visible_b) << "the lock would not show";

    SoftwareRenderer renderer(320, 240);
    const ui::CulledFrame locked = ui::render_culled(renderer, culler, b, a, options, RenderMode::Textured);
    EXPECT_EQ(locked.visible, visible_a);
    EXPECT_EQ(locked.cull.camera, alone_a.camera);
    EXPECT_EQ(locked.cull.region, alone_a.region);
    EXPECT_EQ(locked.cull.pvs_used, alone_a.pvs_used);
    EXPECT_EQ(locked.cull.regions_total, alone_a.regions_total);
    EXPECT_EQ(locked.cull.regions_after_pvs, alone_a.regions_after_pvs);
    EXPECT_EQ(locked.cull.regions_after_frustum, alone_a.regions_after_frustum);
    EXPECT_EQ(locked.cull.triangles_total, alone_a.triangles_total);
    EXPECT_EQ(locked.cull.triangles_after_pvs, alone_a.triangles_after_pvs);
    EXPECT_EQ(locked.cull.triangles_after_frustum, alone_a.triangles_after_frustum);
    EXPECT_NE(locked.cull.region, alone_b.region);

    // Drawn from B: A's regions seen from B, with A's view volume in yellow over them.
    Image expected = renderer.render(*zone_, b, visible_a, RenderMode::Textured);
    size_t yellow = 0;
    for (uint32_t y = 0; y < locked.image.height; ++y)
        for (uint32_t x = 0; x < locked.image.width; ++x) {
            if (same_pixel(locked.image, expected, x, y))
                continue;
            ASSERT_TRUE(is_set(locked.image, x, y, ui::kLockedFrustumColor)) << "at " << x << "," << y;
            ++yellow;
        }
    EXPECT_GT(yellow, 300u);
    ui::draw_frustum(expected, b, a, ui::kLockedFrustumColor);
    EXPECT_EQ(expected.rgba, locked.image.rgba);

    // Not locked: B's own culling, and no lines.
    const ui::CulledFrame unlocked =
        ui::render_culled(renderer, culler, b, std::nullopt, options, RenderMode::Textured);
    EXPECT_EQ(unlocked.visible, visible_b);
    EXPECT_EQ(unlocked.cull.region, alone_b.region);
    EXPECT_EQ(unlocked.image.rgba, renderer.render(*zone_, b, visible_b, RenderMode::Textured).rgba);

    // The ID buffer stays exact: no lines in it.
    const ui::CulledFrame ids = ui::render_culled(renderer, culler, b, a, options, RenderMode::IdBuffer);
    EXPECT_EQ(ids.image.rgba, renderer.render(*zone_, b, visible_a, RenderMode::IdBuffer).rgba);
}

// Region tints (the PVS membership overlay): given tints replace the flags' in Textured and
// Flags modes — a PVS-culled (red) region is redder, a drawn (green) one greener, a region with
// kNoTint exactly the Textured pixels even where its flags would tint it — and are ignored in
// RegionColors and IdBuffer modes.
TEST_F(FlagsOnAWall, RegionTintsReplaceTheFlagTints)
{
    const std::vector<uint32_t> tints = {ui::kMembershipTintBase + 3, ui::kMembershipTintBase + 1, ui::kNoTint};
    const Image tinted = renderer_.render(zone_, wall_camera(), {0, 1, 2}, RenderMode::Textured, tints);
    for (const auto& [x, y] : interior_[1]) { // region 0 (no flags), culled by the PVS: red
        const Rgb t = rgb_of(textured_, x, y), m = rgb_of(tinted, x, y);
        ASSERT_GT(m.r, t.r) << x << "," << y;
        ASSERT_LT(m.b, t.b) << x << "," << y;
    }
    for (const auto& [x, y] : interior_[3]) { // region 1 (water), drawn: green, not blue
        const Rgb t = rgb_of(textured_, x, y), m = rgb_of(tinted, x, y);
        ASSERT_GT(m.g, t.g) << x << "," << y;
        ASSERT_LT(m.b, rgb_of(flags_, x, y).b) << x << "," << y;
    }
    for (uint32_t face : {4u, 5u}) // region 2 (water + zone line) with kNoTint: untinted
        for (const auto& [x, y] : interior_[face])
            ASSERT_TRUE(same_pixel(tinted, textured_, x, y)) << face << " at " << x << "," << y;
    const Image regions = renderer_.render(zone_, wall_camera(), {0, 1, 2}, RenderMode::RegionColors);
    const Image regions_tinted = renderer_.render(zone_, wall_camera(), {0, 1, 2}, RenderMode::RegionColors, tints);
    EXPECT_EQ(regions.rgba, regions_tinted.rgba);
    const Image ids_tinted = renderer_.render(zone_, wall_camera(), {0, 1, 2}, RenderMode::IdBuffer, tints);
    EXPECT_EQ(ids_.rgba, ids_tinted.rgba);
}

} // namespace
} // namespace pvs
