// `compare`'s engine (ui/method_compare.h) on a generated zone: the relations that must hold
// whatever the numbers — conservative methods miss no reference bit and pop no pixel, the
// reference's last round is the reference, `none` exceeds it by exactly the pairs it lacks —
// and the chart module (ui/chart/) on known inputs.
#include "ui/chart/chart_png.h"
#include "ui/chart/compare_points.h"
#include "ui/chart/speed_accuracy_chart.h"
#include "ui/chart/svg_canvas.h"
#include "ui/method_compare.h"

#include "wld/gen/generate_zone.h"

#include <gtest/gtest.h>

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

TEST(Chart, SvgHoldsEveryLabelAndHitTestsFindThePoints)
{
    chart::SvgCanvas svg(800, 400);
    const auto points = two_points();
    const chart::PointPositions at = chart::draw_speed_accuracy_chart(points, "a & b", svg, {0, 0}, {800, 400});
    const std::string text = svg.svg();
    EXPECT_EQ(text.rfind("<svg", 0), 0u);
    EXPECT_NE(text.find("slow exact"), std::string::npos);
    EXPECT_NE(text.find("fast loose"), std::string::npos);
    EXPECT_NE(text.find("a &amp; b"), std::string::npos);
    ASSERT_EQ(at.size(), 2u);
    EXPECT_LT(at[1][0].y, at[0][0].y) << "more missing bits is higher";
    EXPECT_LT(at[1][0].x, at[0][0].x) << "faster is further left";
    EXPECT_EQ(chart::point_near(at, at[1][1] + glm::vec2(2, 1), 6.0f), 1);
    EXPECT_EQ(chart::point_near(at, {1, 1}, 6.0f), -1);
}

TEST(Chart, PngShowsThePointsInTheirColoursAndText)
{
    const auto points = two_points();
    const Image image = chart::render_chart_image(points, "title", 800, 400);
    ASSERT_EQ(image.rgba.size(), 800u * 400u * 4u);
    size_t dark = 0, blue = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        const uint8_t r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
        dark += (r < 60 && g < 60 && b < 60) ? 1 : 0;        // text and axes
        blue += (r < 60 && g > 100 && g < 140 && b > 160) ? 1 : 0; // the first method's colour (31,119,180)
    }
    EXPECT_GT(dark, 500u);
    EXPECT_GT(blue, 40u);
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
    const std::vector<chart::ChartPoint> points = chart::compare_chart_points(result);
    ASSERT_EQ(points.size(), 4u);
    EXPECT_EQ(points[0].label, "reference 1024");
    EXPECT_EQ(points[1].label, "portal-full L4 -passages");
    EXPECT_EQ(points[2].label, "clustered L2 -checks");
    EXPECT_EQ(points[3].label, "file");
    EXPECT_EQ(points[3].seconds, 0.0) << "nothing baked: the stored column";
    EXPECT_EQ(points[0].missing_bits, 3.0);
    EXPECT_EQ(points[0].excess_bits, 4.0);
}

} // namespace
} // namespace pvs::ui
