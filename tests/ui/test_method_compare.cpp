// `compare`'s engine (ui/method_compare.h) on a generated zone: the relations that must hold
// whatever the numbers — conservative methods miss no reference bit and pop no pixel, the
// reference's last round is the reference, `none` exceeds it by exactly the pairs it lacks —
// and the chart module (ui/chart/) on known inputs.
#include "ui/chart/chart_file.h"
#include "ui/chart/compare_points.h"
#include "ui/chart/speed_accuracy_chart.h"
#include "render/method_compare.h"

#include "gen/generate_zone.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <stdexcept>

namespace pvs::ui {
namespace {

TEST(MethodCompare, ConservativeMethodsMissNothingTheReferenceFinds)
{
    const Zone zone = gen::generate_zone({20, 3});
    CompareOptions options;
    options.reference_samples = 128;
    options.cameras = 12;
    options.threads = 2;
    const CompareResult result = run_compare(zone, options);
    ASSERT_FALSE(result.cancelled);
    EXPECT_EQ(result.cameras, 12u);
    size_t reference_rounds = 0, full_variants = 0;
    const uint64_t n = zone.region_count();
    for (const CompareRow& row : result.rows) {
        SCOPED_TRACE(row.method + " " + row.params);
        if (row.method == "reference")
            ++reference_rounds;
        if (row.method == "portal-full")
            ++full_variants;
        if (row.bound == Bound::Upper) {
            EXPECT_EQ(row.missing_bits, 0u);
            EXPECT_EQ(row.popping_pixels, 0u);
            EXPECT_GT(row.wall_s, 0.0);
            EXPECT_GT(row.pvs_bytes, 0u);
        }
        if (row.method == "none" || row.method == "file") { // the generated zone carries no PVS
            EXPECT_EQ(row.missing_bits, 0u);
            EXPECT_EQ(row.excess_bits, n * n - result.reference_bits);
            EXPECT_DOUBLE_EQ(row.mean_visible, double(n));
        }
    }
    EXPECT_EQ(reference_rounds, 2u); // 64 and 128 lines per region
    EXPECT_EQ(full_variants, 6u);    // levels 1-4, without passages, without target checks
    const CompareRow& final_reference = result.rows[reference_rounds - 1];
    EXPECT_EQ(final_reference.missing_bits, 0u);
    EXPECT_EQ(final_reference.excess_bits, 0u);
    EXPECT_GE(result.rows[0].missing_bits, final_reference.missing_bits) << "fewer lines find fewer pairs";
    EXPECT_EQ(result.rows[0].excess_bits, 0u) << "a lower bound within a lower bound of more lines";
}

TEST(MethodCompare, UnknownMethodIsRefused)
{
    const Zone zone = gen::generate_zone({5, 1});
    CompareOptions options;
    options.methods = {"portal-medium"};
    EXPECT_THROW(run_compare(zone, options), std::invalid_argument);
}

TEST(Chart, ParetoFrontKeepsPointsNoFasterPointBeats)
{
    const std::vector<double> seconds{1, 2, 3, 4, 0.5};
    const std::vector<double> values{5, 3, 4, 1, 9};
    EXPECT_EQ(chart::pareto_front(seconds, values), (std::vector<size_t>{4, 0, 1, 3}));
}

std::vector<chart::ChartPoint> two_points()
{
    return {{"slow exact", "portal-full", 2.0, 0.0, 10.0}, {"fast loose", "reference", 0.1, 1000.0, 0.0}};
}

// A canvas that only records where things go: the layout's hit positions and labels without a
// renderer.
class RecordingCanvas final : public chart::Canvas {
public:
    std::vector<std::string> texts;
    void line(glm::vec2, glm::vec2, chart::Color, float) override {}
    void rect(glm::vec2, glm::vec2, chart::Color) override {}
    void circle(glm::vec2, float, chart::Color, chart::Color) override {}
    void text(glm::vec2, std::string_view text, chart::Color, chart::Align) override { texts.emplace_back(text); }
    float text_height() const override { return 13.0f; }
    float text_width(std::string_view text) const override { return 7.0f * float(text.size()); }
};

TEST(Chart, LayoutLabelsEveryPointAndHitTestsFindThem)
{
    RecordingCanvas canvas;
    const auto points = two_points();
    const chart::PointPositions at = chart::draw_speed_accuracy_chart(points, "a & b", canvas, {0, 0}, {800, 400});
    auto drawn = [&](const std::string& text) {
        return std::find(canvas.texts.begin(), canvas.texts.end(), text) != canvas.texts.end();
    };
    EXPECT_TRUE(drawn("slow exact"));
    EXPECT_TRUE(drawn("fast loose"));
    EXPECT_TRUE(drawn("a & b"));
    ASSERT_EQ(at.size(), 2u);
    EXPECT_LT(at[1][0].y, at[0][0].y) << "more missing bits is higher";
    EXPECT_LT(at[1][0].x, at[0][0].x) << "faster is further left";
    EXPECT_EQ(chart::point_near(at, at[1][1] + glm::vec2(2, 1), 6.0f), 1);
    EXPECT_EQ(chart::point_near(at, {1, 1}, 6.0f), -1);
}

struct PixelCounts {
    size_t dark = 0, blue = 0, grey_edge = 0;
};

// Dark (text, axes), the first method's blue (31,119,180), and the grey steps antialiasing leaves
// between white and the dark axis colour.
PixelCounts count_pixels(const Image& image, uint32_t y0 = 0, uint32_t y1 = UINT32_MAX)
{
    PixelCounts counts;
    for (uint32_t y = y0; y < std::min(y1, image.height); ++y)
        for (uint32_t x = 0; x < image.width; ++x) {
            const uint8_t* p = image.pixel(x, y);
            const uint8_t r = p[0], g = p[1], b = p[2];
            counts.dark += (r < 60 && g < 60 && b < 60) ? 1 : 0;
            counts.blue += (r < 60 && g > 100 && g < 140 && b > 160) ? 1 : 0;
            counts.grey_edge += (r == g && g == b && r > 90 && r < 200) ? 1 : 0;
        }
    return counts;
}

TEST(Chart, PngShowsThePointsInTheirColoursAntialiased)
{
    const auto points = two_points();
    const Image image = chart::render_chart_image(points, "title", 800, 400);
    ASSERT_EQ(image.rgba.size(), 800u * 400u * 4u);
    const PixelCounts counts = count_pixels(image);
    EXPECT_GT(counts.dark, 500u);
    EXPECT_GT(counts.blue, 40u);
    EXPECT_GT(counts.grey_edge, 100u) << "antialiased edges and glyphs leave intermediate greys";
}

TEST(Chart, TitleIsRealTextItsLengthShows)
{
    // The title sits in the top band; a longer title inks more of it, by about its extra glyphs.
    const auto points = two_points();
    const size_t short_ink = count_pixels(chart::render_chart_image(points, "A", 800, 400), 0, 24).dark;
    const size_t long_ink =
        count_pixels(chart::render_chart_image(points, "AAAAAAAAAA", 800, 400), 0, 24).dark;
    EXPECT_GT(short_ink, 0u);
    EXPECT_GT(long_ink, 5 * short_ink);
}

TEST(Chart, FileFormatFollowsTheExtensionAndUnknownOnesAreRefused)
{
    EXPECT_EQ(chart::chart_format_for("a/b.png"), chart::ChartFormat::Png);
    EXPECT_EQ(chart::chart_format_for("b.SVG"), chart::ChartFormat::Svg);
    EXPECT_EQ(chart::chart_format_for("b.pdf"), chart::ChartFormat::Pdf);
    EXPECT_THROW(chart::chart_format_for("b.jpg"), std::invalid_argument);
    EXPECT_THROW(chart::chart_format_for("b"), std::invalid_argument);
    const auto points = two_points();
    EXPECT_THROW(chart::write_chart_file(points, "t", 800, 400, "/nonexistent-folder/c.svg"), std::runtime_error);
    EXPECT_THROW(chart::render_chart_image(points, "t", 0, 400), std::invalid_argument);
}

TEST(Chart, CompareRowsBecomeShortLabelledPoints)
{
    CompareResult result;
    auto row = [&](std::string method, std::string params, bool baked, double seconds) {
        CompareRow r;
        r.method = std::move(method);
        r.params = std::move(params);
        r.baked = baked;
        r.wall_s = seconds;
        r.missing_bits = 3;
        r.excess_bits = 4;
        result.rows.push_back(std::move(r));
    };
    row("reference", "samples=1024 seed=1", true, 2.0);
    row("portal-full", "level=4 passages=off target-checks=on", true, 1.0);
    row("clustered", "level=2 passages=on target-checks=off", true, 1.0);
    row("file", "", false, 5.0);
    row("raster", "res=64 points=8 step=0 lattice=open", true, 3.0);
    const std::vector<chart::ChartPoint> points = chart::compare_chart_points(result);
    ASSERT_EQ(points.size(), 5u);
    EXPECT_EQ(points[0].label, "reference 1024");
    EXPECT_EQ(points[1].label, "portal-full L4 -passages");
    EXPECT_EQ(points[2].label, "clustered L2 -checks");
    EXPECT_EQ(points[3].label, "file");
    EXPECT_EQ(points[4].label, "raster 64px 8pt");
    EXPECT_EQ(points[3].seconds, 0.0) << "nothing baked: the stored column";
    EXPECT_EQ(points[0].missing_bits, 3.0);
    EXPECT_EQ(points[0].excess_bits, 4.0);
}

} // namespace
} // namespace pvs::ui
