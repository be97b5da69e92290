// LineBatch (ui/line_batch.h): box edges and segments of one colour on the same axis-parallel
// line joined where they overlap or touch, worked out by hand on small boxes; colours kept apart
// and in first-added order; gaps, slanted segments, empty and non-finite input; and drawing the
// joined lines sets the pixels drawing every box on its own sets.
#include "render/line_batch.h"
#include "render/overlay_fill.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace pvs {
namespace {

using ui::ColoredSegment;
using ui::LineBatch;

Aabb box(glm::vec3 lo, glm::vec3 hi)
{
    Aabb b;
    b.grow(lo);
    b.grow(hi);
    return b;
}

// The segments along x (a.y == b.y, a.z == b.z, a.x != b.x).
std::vector<ColoredSegment> along_x(std::span<const ColoredSegment> segments)
{
    std::vector<ColoredSegment> out;
    for (const ColoredSegment& s : segments)
        if (s.a.y == s.b.y && s.a.z == s.b.z && s.a.x != s.b.x)
            out.push_back(s);
    return out;
}

TEST(LineBatch, TwoBoxesSharingAFaceAreSixteenLines)
{
    // [0,1]^3 and [1,2]x[0,1]^2: the four x edges of each join into four lines from 0 to 2; the
    // y and z edges stand at x = 0, 1, 2 (those at x = 1 shared): 6 + 6.
    LineBatch batch;
    batch.add_box(box({0, 0, 0}, {1, 1, 1}), 0xFF0000);
    batch.add_box(box({1, 0, 0}, {2, 1, 1}), 0xFF0000);
    const auto segments = batch.segments();
    EXPECT_EQ(segments.size(), 16u);
    const auto x_lines = along_x(segments);
    ASSERT_EQ(x_lines.size(), 4u);
    for (const ColoredSegment& s : x_lines) {
        EXPECT_EQ(std::min(s.a.x, s.b.x), 0.0f);
        EXPECT_EQ(std::max(s.a.x, s.b.x), 2.0f);
        EXPECT_EQ(s.rgb, 0xFF0000u);
    }
}

TEST(LineBatch, AGridOfCellsIsItsGridLines)
{
    // 4 x 3 x 2 unit cells: lines along x = (3+1)(2+1) = 12, along y = 5 * 3 = 15, along z = 5 * 4 = 20.
    LineBatch batch;
    for (int x = 0; x < 4; ++x)
        for (int y = 0; y < 3; ++y)
            for (int z = 0; z < 2; ++z)
                batch.add_box(box({x, y, z}, {x + 1, y + 1, z + 1}), 0x00FF00);
    EXPECT_EQ(batch.segments().size(), 12u + 15u + 20u);
    for (const ColoredSegment& s : along_x(batch.segments()))
        EXPECT_EQ(std::abs(s.b.x - s.a.x), 4.0f);
}

TEST(LineBatch, TheSameBoxTwiceIsTwelveLines)
{
    LineBatch batch;
    batch.add_box(box({-3, 2, 5}, {7, 4, 6}), 0x123456);
    batch.add_box(box({-3, 2, 5}, {7, 4, 6}), 0x123456);
    EXPECT_EQ(batch.segments().size(), 12u);
}

TEST(LineBatch, ColoursStayApartInTheOrderFirstAdded)
{
    LineBatch batch;
    batch.add_box(box({1, 0, 0}, {2, 1, 1}), 0x00FF00);
    batch.add_box(box({0, 0, 0}, {1, 1, 1}), 0xFF0000);
    batch.add_box(box({2, 0, 0}, {3, 1, 1}), 0x00FF00); // joins the first green one
    const auto segments = batch.segments();
    ASSERT_EQ(segments.size(), 16u + 12u);
    for (size_t i = 0; i < 16; ++i)
        EXPECT_EQ(segments[i].rgb, 0x00FF00u) << i;
    for (size_t i = 16; i < segments.size(); ++i)
        EXPECT_EQ(segments[i].rgb, 0xFF0000u) << i;
}

TEST(LineBatch, TouchingSegmentsJoinAndAGapDoesNot)
{
    LineBatch batch;
    batch.add_segment({0, 5, 5}, {1, 5, 5}, 0xFFFFFF);
    batch.add_segment({2, 5, 5}, {1, 5, 5}, 0xFFFFFF);   // touches, given backwards
    batch.add_segment({2.5f, 5, 5}, {3, 5, 5}, 0xFFFFFF); // a gap of 0.5
    batch.add_segment({0.25f, 5, 5}, {0.5f, 5, 5}, 0xFFFFFF); // inside the first
    const auto segments = batch.segments();
    ASSERT_EQ(segments.size(), 2u);
    EXPECT_EQ(segments[0].a, glm::vec3(0, 5, 5));
    EXPECT_EQ(segments[0].b, glm::vec3(2, 5, 5));
    EXPECT_EQ(segments[1].a, glm::vec3(2.5f, 5, 5));
    EXPECT_EQ(segments[1].b, glm::vec3(3, 5, 5));
}

TEST(LineBatch, NearlyMeetingLinesStayAsGiven)
{
    // y differs in the last bit: two lines, not one.
    LineBatch batch;
    const float y = 1.0f, y_next = std::nextafter(1.0f, 2.0f);
    batch.add_segment({0, y, 0}, {1, y, 0}, 0xFFFFFF);
    batch.add_segment({1, y_next, 0}, {2, y_next, 0}, 0xFFFFFF);
    EXPECT_EQ(batch.segments().size(), 2u);
}

TEST(LineBatch, SlantedSegmentsAreKeptInTheirColoursPlace)
{
    LineBatch batch;
    batch.add_segment({0, 0, 0}, {1, 1, 0}, 0xFF0000);  // slanted, red first
    batch.add_segment({0, 0, 1}, {1, 0, 1}, 0x0000FF);  // along x, blue
    batch.add_outline(std::vector<glm::vec3>{{0, 0, 2}, {1, 0, 2}, {0, 1, 2}}, 0xFF0000); // 2 axis, 1 slanted
    const auto segments = batch.segments();
    ASSERT_EQ(segments.size(), 5u);
    for (size_t i = 0; i < 4; ++i)
        EXPECT_EQ(segments[i].rgb, 0xFF0000u) << i;
    EXPECT_EQ(segments[4].rgb, 0x0000FFu);
}

TEST(LineBatch, EmptyNonFiniteAndZeroLengthInputIsSkipped)
{
    LineBatch batch;
    batch.add_box(Aabb{}, 0xFFFFFF);
    Aabb infinite, not_a_number;
    infinite.min = not_a_number.min = {0, 0, 0};
    infinite.max = {std::numeric_limits<float>::infinity(), 1, 1};
    not_a_number.max = {std::numeric_limits<float>::quiet_NaN(), 1, 1};
    batch.add_box(infinite, 0xFFFFFF);
    batch.add_box(not_a_number, 0xFFFFFF);
    batch.add_segment({1, 1, 1}, {1, 1, 1}, 0xFFFFFF);
    batch.add_segment({0, 0, 0}, {std::numeric_limits<float>::quiet_NaN(), 0, 0}, 0xFFFFFF);
    batch.add_outline(std::vector<glm::vec3>{{0, 0, 0}}, 0xFFFFFF);
    EXPECT_TRUE(batch.segments().empty());
    batch.add_box(box({0, 0, 0}, {1, 1, 1}), 0xFFFFFF);
    EXPECT_EQ(batch.segments().size(), 12u);
    batch.clear();
    EXPECT_TRUE(batch.segments().empty());
}

TEST(LineBatch, ManyCellsSortLikeFewAndDrawTheSamePixelsAsEachBox)
{
    // A 24 x 24 x 3 grid of 64-unit cells seen from above at an angle (enough edges for the
    // radix sort), drawn joined and box by box: the same lines, so the same pixels but for
    // rounding (a joined line rounds its pixels once, not at each cell corner).
    Camera view;
    view.position = {-200, -300, 900};
    view.yaw_degrees = 45;
    view.pitch_degrees = -45;
    view.aspect = 4.0f / 3.0f;
    const ui::LineProjection projection(view);
    ui::Image joined, each;
    joined.width = each.width = 320;
    joined.height = each.height = 240;
    joined.rgba.assign(320 * 240 * 4, 0);
    for (size_t i = 3; i < joined.rgba.size(); i += 4)
        joined.rgba[i] = 255;
    each.rgba = joined.rgba;
    LineBatch batch;
    for (int x = 0; x < 24; ++x)
        for (int y = 0; y < 24; ++y)
            for (int z = 0; z < 3; ++z) {
                const Aabb cell = box(glm::vec3(x, y, z) * 64.0f, glm::vec3(x + 1, y + 1, z + 1) * 64.0f);
                batch.add_box(cell, 0xFFFFFF);
                ui::draw_box_3d(each, projection, cell, 0xFFFFFF);
            }
    EXPECT_EQ(batch.segments().size(), 25u * 4 + 25u * 4 + 25u * 25); // along x, y, z
    batch.draw(joined, projection);
    // Every pixel either sets lies on or next to one the other sets.
    const auto near_set = [](const ui::Image& image, int32_t x, int32_t y) {
        for (int32_t dy = -1; dy <= 1; ++dy)
            for (int32_t dx = -1; dx <= 1; ++dx) {
                const int32_t nx = x + dx, ny = y + dy;
                if (nx >= 0 && ny >= 0 && nx < int32_t(image.width) && ny < int32_t(image.height) &&
                    image.pixel(uint32_t(nx), uint32_t(ny))[0] != 0)
                    return true;
            }
        return false;
    };
    size_t set_each = 0, stray = 0;
    for (uint32_t y = 0; y < each.height; ++y)
        for (uint32_t x = 0; x < each.width; ++x) {
            const bool in_each = each.pixel(x, y)[0] != 0, in_joined = joined.pixel(x, y)[0] != 0;
            set_each += in_each;
            stray += (in_each && !near_set(joined, int32_t(x), int32_t(y))) ||
                     (in_joined && !near_set(each, int32_t(x), int32_t(y)));
        }
    EXPECT_GT(set_each, 5000u);
    EXPECT_EQ(stray, 0u);
}

} // namespace
} // namespace pvs
