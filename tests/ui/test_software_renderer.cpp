// The headless software renderer (Irrlicht's Burning's Video): the ID buffer against faces
// worked out by hand from a synthetic two-room zone, the region-colour picture against the ID
// buffer on e1m1, and determinism.
#include "tests/support/test_data.h"
#include "render/software_renderer.h"
#include "visibility/culler.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <map>
#include <set>

namespace pvs {
namespace {

using ui::Image;
using ui::RenderMode;
using ui::SoftwareRenderer;

// A quad (a, b, c, d in order around it) as one face of two triangles, wound counter-clockwise
// seen from the side `front` points to (the model's convention), with material 0.
void add_quad(Zone& zone, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 front)
{
    if (glm::dot(glm::cross(b - a, c - a), front) < 0.0f)
        std::swap(b, d);
    Mesh& mesh = zone.mesh;
    const auto base = uint32_t(mesh.positions.size());
    for (const glm::vec3& p : {a, b, c, d}) {
        mesh.positions.push_back(p);
        mesh.uvs.push_back({p.x / 8.0f + p.z / 8.0f, p.y / 8.0f});
    }
    mesh.faces.push_back({uint32_t(mesh.triangle_count()), 2, 0});
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
        mesh.indices.push_back(base + i);
}

// Two 10-unit rooms side by side, joined by a doorway in the wall x = 10 (y 4..6, z 0..6):
// room A (region 0) is x 0..10, room B (region 1) is x 10..20; every face faces into its room.
//   A:  0 floor z=0       1 ceiling z=10     2 wall y=0       3 wall y=10      4 back wall x=0
//       5 door wall x=10, y 0..4             6 door wall y 6..10               7 lintel y 4..6, z 6..10
//   B:  8 floor           9 ceiling         10 wall y=0      11 wall y=10     12 far wall x=20
//      13, 14, 15: B's side of the door wall (same rectangles as 5, 6, 7, facing +x)
Zone two_rooms()
{
    Zone zone;
    for (float x0 : {0.0f, 10.0f}) {
        const float x1 = x0 + 10.0f;
        const bool a = x0 == 0.0f;
        add_quad(zone, {x0, 0, 0}, {x1, 0, 0}, {x1, 10, 0}, {x0, 10, 0}, {0, 0, 1});     // floor
        add_quad(zone, {x0, 0, 10}, {x1, 0, 10}, {x1, 10, 10}, {x0, 10, 10}, {0, 0, -1}); // ceiling
        add_quad(zone, {x0, 0, 0}, {x1, 0, 0}, {x1, 0, 10}, {x0, 0, 10}, {0, 1, 0});      // wall y=0
        add_quad(zone, {x0, 10, 0}, {x1, 10, 0}, {x1, 10, 10}, {x0, 10, 10}, {0, -1, 0}); // wall y=10
        const float outer = a ? 0.0f : 20.0f;                                               // back / far wall
        add_quad(zone, {outer, 0, 0}, {outer, 10, 0}, {outer, 10, 10}, {outer, 0, 10}, {a ? 1.0f : -1.0f, 0, 0});
        const glm::vec3 into{a ? -1.0f : 1.0f, 0, 0};                                       // door wall x=10
        add_quad(zone, {10, 0, 0}, {10, 4, 0}, {10, 4, 10}, {10, 0, 10}, into);
        add_quad(zone, {10, 6, 0}, {10, 10, 0}, {10, 10, 10}, {10, 6, 10}, into);
        add_quad(zone, {10, 4, 6}, {10, 6, 6}, {10, 6, 10}, {10, 4, 10}, into);
    }
    // A one-node tree (x = 10) and the rows, so the zone is a complete one.
    zone.tree.nodes.push_back({{1.0f, 0.0f, 0.0f}, 10.0f, {~2, ~1}});
    zone.tree.leaf_region = {kLeafSolid, 0, 1};
    zone.tree.root = 0;
    zone.regions.resize(2);
    zone.regions[0].bounds.grow({0, 0, 0});
    zone.regions[0].bounds.grow({10, 10, 10});
    zone.regions[1].bounds.grow({10, 0, 0});
    zone.regions[1].bounds.grow({20, 10, 10});
    zone.region_face_offsets = {0, 8, 16};
    for (uint32_t f = 0; f < 16; ++f)
        zone.region_faces.push_back(f);
    zone.materials.push_back({"plain", 0, 0, {}, 0}); // no pixels: a flat colour
    return zone;
}

// Camera in room A at (2, 5, 3) looking along +x (at the door), fov 70 (vertical), 4:3.
// Worked out from the geometry (tan 35 deg = 0.70 vertically, 0.93 horizontally):
//  - the door wall (x = 10, 8 units ahead) spans y -2.5..12.5 and z -2.6..8.6 of the view, so 5,
//    6, 7 are seen; the floor (0) meets the bottom of the view at x = 6.3 and the side walls (2,
//    3) meet its edges at x = 7.4, so all three are seen;
//  - A's ceiling (1) would need a ray rising 7 in 8 (0.875 > 0.70): off screen; the back wall (4)
//    is behind the camera;
//  - through the doorway (rays within 1/8 sideways and 3/8 up/down): B's far wall (12) between
//    z -3.75 and 9.75, and B's floor (8); not B's ceiling (9, the rays reach z 9.75 < 10 at x=20),
//    nor B's side walls (10, 11, reached at y 2.75..7.25 only); B's side of the door wall
//    (13, 14, 15) faces away from the camera and is culled.
const std::set<uint32_t> kSeenFromA{0, 2, 3, 5, 6, 7, 8, 12};
const std::set<uint32_t> kSeenFromAWithOnlyA{0, 2, 3, 5, 6, 7};

Camera camera_in_room_a()
{
    Camera camera;
    camera.position = {2, 5, 3};
    camera.aspect = 4.0f / 3.0f;
    return camera;
}

std::map<uint32_t, size_t> face_pixels(const Image& ids, size_t& background)
{
    std::map<uint32_t, size_t> count;
    background = 0;
    for (uint32_t y = 0; y < ids.height; ++y)
        for (uint32_t x = 0; x < ids.width; ++x) {
            const uint32_t face = ui::face_at(ids, x, y);
            if (face == ui::kNoFace)
                ++background;
            else
                ++count[face];
        }
    return count;
}

std::set<uint32_t> keys(const std::map<uint32_t, size_t>& m)
{
    std::set<uint32_t> out;
    for (const auto& [k, v] : m)
        out.insert(k);
    return out;
}

uint32_t rgb_at(const Image& image, uint32_t x, uint32_t y)
{
    const uint8_t* p = image.pixel(x, y);
    return uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2];
}

TEST(IdColours, RoundTripEvenWhenEveryChannelComesBackOneLess)
{
    for (uint32_t value : {1u, 2u, 127u, 128u, 129u, 16383u, 16384u, 999999u, ui::kMaxIdValue}) {
        const uint32_t c = ui::encode_id(value);
        const uint8_t r = uint8_t(c >> 16), g = uint8_t(c >> 8), b = uint8_t(c);
        EXPECT_EQ(ui::decode_id(r, g, b), value);
        EXPECT_EQ(ui::decode_id(uint8_t(r - 1), uint8_t(g - 1), uint8_t(b - 1)), value);
        EXPECT_EQ(ui::decode_id(r, uint8_t(g - 1), b), value);
        EXPECT_NE(c & 0xFFFFFFu, 0u);
    }
    EXPECT_EQ(ui::decode_id(0, 0, 0), 0u);
}

TEST(IdColours, RegionColoursAreOddNeverBackgroundAndMostlyDistinct)
{
    std::set<uint32_t> seen;
    for (uint32_t r = 0; r < 2000; ++r) {
        const uint32_t c = ui::region_color(r);
        EXPECT_EQ(c & 0x010101u, 0x010101u);
        EXPECT_GE(c >> 16, 49u);
        EXPECT_GE((c >> 8) & 0xFF, 49u);
        EXPECT_GE(c & 0xFF, 49u);
        EXPECT_EQ(c, ui::region_color(r));
        seen.insert(c);
    }
    EXPECT_GE(seen.size(), 1995u);
}

// A material of one colour (or none: two_rooms' "plain") carries no cue but its light, so the
// textured picture shades it strongly by the face's normal: the floor (facing up) against the door
// wall (facing -x) and the two side walls (facing +y and -y) stand well apart. The fake light that
// textured materials get (0.62..1) left these at 1.32 and 1.15.
TEST(SoftwareRenderer, OneColourFacesAreShadedApartByTheirNormal)
{
    const Zone zone = two_rooms();
    SoftwareRenderer renderer(160, 120);
    const Image ids = renderer.render(zone, camera_in_room_a(), {0, 1}, RenderMode::IdBuffer);
    const Image picture = renderer.render(zone, camera_in_room_a(), {0, 1}, RenderMode::Textured);
    std::map<uint32_t, std::pair<double, size_t>> brightness; // face -> (sum of r+g+b, pixels)
    for (uint32_t y = 0; y < ids.height; ++y)
        for (uint32_t x = 0; x < ids.width; ++x) {
            const uint32_t face = ui::face_at(ids, x, y);
            const uint8_t* p = picture.pixel(x, y);
            brightness[face].first += double(p[0]) + p[1] + p[2];
            ++brightness[face].second;
        }
    const auto mean = [&](uint32_t face) {
        const auto& [sum, n] = brightness.at(face);
        return sum / double(n);
    };
    EXPECT_GE(mean(0) / mean(5), 1.6) << "floor against the door wall";
    EXPECT_GE(mean(2) / mean(3), 1.2) << "the wall facing +y against the one facing -y";
}

TEST(RenderModes, NamesRoundTrip)
{
    for (RenderMode m : {RenderMode::Textured, RenderMode::RegionColors, RenderMode::IdBuffer})
        EXPECT_EQ(ui::parse_render_mode(ui::render_mode_name(m)), m);
    EXPECT_FALSE(ui::parse_render_mode("wireframe").has_value());
}

TEST(SoftwareRenderer, RejectsSizesOutOfRange)
{
    EXPECT_THROW(SoftwareRenderer(0, 100), std::runtime_error);
    EXPECT_THROW(SoftwareRenderer(100, 9000), std::runtime_error);
}

TEST(SoftwareRenderer, TwoRoomsIdBufferSeesExactlyTheExpectedFaces)
{
    const Zone zone = two_rooms();
    SoftwareRenderer renderer(160, 120);
    const Image ids = renderer.render(zone, camera_in_room_a(), {0, 1}, RenderMode::IdBuffer);
    ASSERT_EQ(ids.width, 160u);
    ASSERT_EQ(ids.height, 120u);
    ASSERT_EQ(ids.rgba.size(), 160u * 120u * 4u);
    size_t background = 0;
    const auto count = face_pixels(ids, background);
    for (const auto& [face, pixels] : count)
        ASSERT_LT(face, zone.mesh.faces.size()) << "a pixel decodes to no face";
    EXPECT_EQ(keys(count), kSeenFromA);
    EXPECT_EQ(background, 0u) << "the room is closed: every pixel shows a face";
    for (uint32_t face : kSeenFromA)
        EXPECT_GE(count.at(face), 20u) << "face " << face;
    EXPECT_EQ(renderer.last_stats().faces_drawn, 16u);
    EXPECT_EQ(renderer.last_stats().triangles_drawn, 32u);

    // The far wall of B is straight ahead through the doorway; A's door wall is left and right of it.
    EXPECT_EQ(ui::face_at(ids, 80, 60), 12u);
    EXPECT_EQ(ui::face_at(ids, 40, 60), 6u);  // left of the view is +y (z up, looking along +x)
    EXPECT_EQ(ui::face_at(ids, 120, 60), 5u);
    EXPECT_EQ(ui::face_at(ids, 80, 119), 0u); // A's floor at the bottom
}

TEST(SoftwareRenderer, TwoRoomsDrawingOnlyRoomAShowsNothingOfRoomB)
{
    const Zone zone = two_rooms();
    SoftwareRenderer renderer(160, 120);
    const Image ids = renderer.render(zone, camera_in_room_a(), {0}, RenderMode::IdBuffer);
    size_t background = 0;
    const auto count = face_pixels(ids, background);
    EXPECT_EQ(keys(count), kSeenFromAWithOnlyA);
    for (const auto& [face, pixels] : count)
        EXPECT_LT(face, 8u) << "a pixel of room B's face " << face;
    EXPECT_GT(background, 100u) << "the doorway shows the background";
    EXPECT_EQ(ui::face_at(ids, 80, 60), ui::kNoFace);
    EXPECT_EQ(renderer.last_stats().faces_drawn, 8u);

    // Out-of-range region ids are ignored; no regions = an empty frame.
    const Image none = renderer.render(zone, camera_in_room_a(), {7, 99}, RenderMode::IdBuffer);
    face_pixels(none, background);
    EXPECT_EQ(background, size_t(160) * 120);
}

TEST(SoftwareRenderer, AFaceListedByTwoVisibleRegionsIsDrawnOnceInTheFirstRegionsColour)
{
    Zone zone = two_rooms();
    // Region A also lists B's far wall (face 12), as Quake leaves list faces they touch.
    zone.region_faces.insert(zone.region_faces.begin() + 8, 12u);
    zone.region_face_offsets = {0, 9, 17};
    SoftwareRenderer renderer(160, 120);
    const Image regions = renderer.render(zone, camera_in_room_a(), {0, 1}, RenderMode::RegionColors);
    EXPECT_EQ(renderer.last_stats().faces_drawn, 16u);
    EXPECT_EQ(rgb_at(regions, 80, 60), ui::region_color(0)); // face 12, owned by region 0 (listed first)
    EXPECT_EQ(rgb_at(regions, 80, 119), ui::region_color(0)); // A's floor
    EXPECT_EQ(rgb_at(regions, 80, 75), ui::region_color(1));  // B's floor, seen through the doorway
    const Image only_b = renderer.render(zone, camera_in_room_a(), {1}, RenderMode::RegionColors);
    EXPECT_EQ(rgb_at(only_b, 80, 60), ui::region_color(1));
    EXPECT_EQ(rgb_at(only_b, 80, 119), 0u); // A is not drawn: background
}

TEST(SoftwareRenderer, RenderingTwiceGivesIdenticalImages)
{
    const Zone zone = two_rooms();
    Camera camera = camera_in_room_a();
    camera.yaw_degrees = 17.0f;
    camera.pitch_degrees = -11.0f;
    SoftwareRenderer first(200, 150), second(200, 150);
    for (RenderMode mode : {RenderMode::Textured, RenderMode::RegionColors, RenderMode::IdBuffer}) {
        const Image a = first.render(zone, camera, {0, 1}, mode);
        const Image b = first.render(zone, camera, {0, 1}, mode);
        const Image c = second.render(zone, camera, {0, 1}, mode);
        EXPECT_EQ(a.rgba, b.rgba) << ui::render_mode_name(mode);
        EXPECT_EQ(a.rgba, c.rgba) << ui::render_mode_name(mode);
    }
}

class RenderE1m1 : public ::testing::Test {
protected:
    void SetUp() override
    {
        SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
        zone_ = test::shared_zone("quake/e1m1.bsp");
        ASSERT_NE(zone_, nullptr);
        ASSERT_TRUE(zone_->baked_pvs.has_value());
        camera_.position = {480, -352, 88}; // the player start
        camera_.yaw_degrees = 90.0f;
        camera_.aspect = 4.0f / 3.0f;
        Culler culler(*zone_, &*zone_->baked_pvs);
        culler.cull(camera_, {CullMode::PvsFrustum, false}, visible_);
        ASSERT_FALSE(visible_.empty());
    }
    const Zone* zone_ = nullptr;
    Camera camera_;
    std::vector<uint32_t> visible_;
};

TEST_F(RenderE1m1, TexturedPictureFromThePlayerStartIsNotBlank)
{
    SoftwareRenderer renderer(320, 240);
    const Image image = renderer.render(*zone_, camera_, visible_, RenderMode::Textured);
    std::set<uint32_t> colours;
    size_t black = 0;
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x) {
            const uint32_t c = rgb_at(image, x, y);
            colours.insert(c);
            black += c == 0;
        }
    EXPECT_GE(colours.size(), 500u);
    EXPECT_LT(black, image.width * image.height / 20) << "the corridor fills the view";
    EXPECT_GT(renderer.last_stats().faces_drawn, 100u);
}

TEST_F(RenderE1m1, EveryRegionColourPixelBelongsToARegionListingTheIdBuffersFace)
{
    SoftwareRenderer renderer(320, 240);
    const Image ids = renderer.render(*zone_, camera_, visible_, RenderMode::IdBuffer);
    const Image regions = renderer.render(*zone_, camera_, visible_, RenderMode::RegionColors);
    // Face -> colours of the visible regions that list it.
    std::map<uint32_t, std::set<uint32_t>> colours_of_face;
    for (uint32_t r : visible_)
        for (uint32_t f : zone_->faces_of_region(r))
            colours_of_face[f].insert(ui::region_color(r));

    size_t background = 0, mismatched = 0;
    std::set<uint32_t> faces_seen;
    for (uint32_t y = 0; y < ids.height; ++y)
        for (uint32_t x = 0; x < ids.width; ++x) {
            const uint32_t face = ui::face_at(ids, x, y);
            const uint32_t colour = rgb_at(regions, x, y);
            if (face == ui::kNoFace) {
                ++background;
                EXPECT_EQ(colour, 0u) << "at " << x << "," << y;
                continue;
            }
            ASSERT_LT(face, zone_->mesh.faces.size()) << "at " << x << "," << y;
            const auto it = colours_of_face.find(face);
            ASSERT_NE(it, colours_of_face.end()) << "face " << face << " is not listed by a visible region";
            faces_seen.insert(face);
            if (!it->second.count(colour) && ++mismatched <= 10)
                ADD_FAILURE() << "at " << x << "," << y << ": face " << face << " has colour " << std::hex << colour;
        }
    EXPECT_EQ(mismatched, 0u);
    EXPECT_LT(background, ids.width * ids.height / 20);
    EXPECT_GT(faces_seen.size(), 50u);
}

TEST_F(RenderE1m1, PvsPlusFrustumLosesNoPixelAgainstDrawingEveryRegion)
{
    // WVis's PVS is conservative and the frustum stage uses the same view volume as the
    // renderer's camera, so the culled ID buffer equals the one of the whole zone.
    SoftwareRenderer renderer(320, 240);
    std::vector<uint32_t> all(zone_->region_count());
    for (uint32_t r = 0; r < all.size(); ++r)
        all[r] = r;
    const Image everything = renderer.render(*zone_, camera_, all, RenderMode::IdBuffer);
    const uint32_t faces_everything = renderer.last_stats().faces_drawn;
    const Image culled = renderer.render(*zone_, camera_, visible_, RenderMode::IdBuffer);
    EXPECT_LT(renderer.last_stats().faces_drawn * 5, faces_everything);
    EXPECT_EQ(culled.rgba, everything.rgba);
}

TEST_F(RenderE1m1, RenderingTwiceGivesIdenticalImages)
{
    SoftwareRenderer renderer(320, 240);
    for (RenderMode mode : {RenderMode::Textured, RenderMode::IdBuffer}) {
        const Image a = renderer.render(*zone_, camera_, visible_, mode);
        const Image b = renderer.render(*zone_, camera_, visible_, mode);
        EXPECT_EQ(a.rgba, b.rgba) << ui::render_mode_name(mode);
    }
}

} // namespace
} // namespace pvs
