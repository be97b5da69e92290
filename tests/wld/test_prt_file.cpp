// Quake PRT1 portal files (../shared/formats/quake-doom-hepvs.md §2): reading vis.py's example.prt,
// orientation (§2.5), exact write/read round trips, and refusal of bad or hostile text.
#include "wld/quake/prt_file.h"

#include "tests/support/test_data.h"
#include "visibility/file_error.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace pvs {
namespace {

using quake::PrtFile;

std::string example_text(const std::string& path)
{
    const std::vector<uint8_t> bytes = test::read_bytes(path);
    return std::string(bytes.begin(), bytes.end());
}

// Exact equality, bit for bit (so -0 and 0 differ).
void expect_same(const PrtFile& a, const PrtFile& b)
{
    EXPECT_EQ(a.leaf_count, b.leaf_count);
    ASSERT_EQ(a.portals.portals.size(), b.portals.portals.size());
    for (size_t i = 0; i < a.portals.portals.size(); ++i) {
        const Portal& pa = a.portals.portals[i];
        const Portal& pb = b.portals.portals[i];
        EXPECT_EQ(pa.regions[0], pb.regions[0]) << "portal " << i;
        EXPECT_EQ(pa.regions[1], pb.regions[1]) << "portal " << i;
        EXPECT_EQ(pa.first_point, pb.first_point) << "portal " << i;
        EXPECT_EQ(pa.point_count, pb.point_count) << "portal " << i;
    }
    ASSERT_EQ(a.portals.points.size(), b.portals.points.size());
    for (size_t i = 0; i < a.portals.points.size(); ++i)
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_EQ(std::bit_cast<uint32_t>(a.portals.points[i][axis]), std::bit_cast<uint32_t>(b.portals.points[i][axis]))
                << "point " << i << " axis " << axis << ": " << a.portals.points[i][axis] << " vs "
                << b.portals.points[i][axis];
}

struct ParseError {
    bool thrown = false;
    std::string reason;
    uint64_t offset = 0;
};

ParseError error_of(std::string_view text)
{
    try {
        quake::parse_prt(text, "test.prt");
    } catch (const FileError& e) {
        EXPECT_EQ(e.file(), "test.prt");
        return {true, e.reason(), e.offset()};
    }
    return {};
}

#define EXPECT_PRT_ERROR(text, fragment)                                                                     \
    do {                                                                                                     \
        const ParseError error_ = error_of(text);                                                            \
        EXPECT_TRUE(error_.thrown) << "parsed without error";                                                \
        EXPECT_NE(error_.reason.find(fragment), std::string::npos) << "reason: " << error_.reason;            \
    } while (0)

// A small valid file: 3 leaves, portals 0-1 (a square in x = 0) and 1-2 (a triangle in y = 5).
const std::string kSmall = "PRT1\n3\n2\n"
                           "4 0 1 (0 0 0 ) (0 4 0 ) (0 4 4 ) (0 0 4 ) \n"
                           "3 1 2 (0 5 0 ) (2 5 0 ) (2 5 2 ) \n";

TEST(PrtFile, ExampleHasElevenLeavesAndTwelveFourPointPortals)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.prt");
    const PrtFile prt = quake::load_prt(path);
    EXPECT_EQ(prt.leaf_count, 11u);
    ASSERT_EQ(prt.portals.portals.size(), 12u);
    EXPECT_EQ(prt.portals.points.size(), 48u);
    for (size_t i = 0; i < prt.portals.portals.size(); ++i) {
        EXPECT_EQ(prt.portals.portals[i].point_count, 4u) << "portal " << i;
        EXPECT_EQ(prt.portals.portals[i].first_point, 4 * i) << "portal " << i;
    }

    // "4 0 1 (880 -224 -8 ) (880 -272 -8 ) (880 -272 72 ) (880 -224 72 )"
    const Portal& first = prt.portals.portals[0];
    EXPECT_EQ(first.regions[0], 0);
    EXPECT_EQ(first.regions[1], 1);
    EXPECT_EQ(prt.portals.points[0], glm::vec3(880, -224, -8));
    EXPECT_EQ(prt.portals.points[1], glm::vec3(880, -272, -8));
    EXPECT_EQ(prt.portals.points[2], glm::vec3(880, -272, 72));
    EXPECT_EQ(prt.portals.points[3], glm::vec3(880, -224, 72));
    // "4 7 10 ..." keeps the file's leaf order.
    EXPECT_EQ(prt.portals.portals[8].regions[0], 7);
    EXPECT_EQ(prt.portals.portals[8].regions[1], 10);
}

TEST(PrtFile, ExampleFirstPortalNormalIsPlusXIntoLeafZero)
{
    // §2.5: PRT leaf 0 is BSP leaf 1, whose x range 880..976 lies on the +X side of the portal.
    SHARED_DATA_OR_SKIP(path, "visdemo/example.prt");
    const PrtFile prt = quake::load_prt(path);
    const Plane plane = quake::portal_plane(prt.portals, prt.portals.portals[0]);
    EXPECT_FLOAT_EQ(plane.normal.x, 1.0f);
    EXPECT_FLOAT_EQ(plane.normal.y, 0.0f);
    EXPECT_FLOAT_EQ(plane.normal.z, 0.0f);
    EXPECT_FLOAT_EQ(plane.dist, 880.0f);
    EXPECT_GT(plane.distance(glm::vec3(928, -248, 32)), 0.0f); // a point inside BSP leaf 1
}

TEST(PrtFile, ExamplePortalPointsLieOnTheirPlanes)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.prt");
    const PrtFile prt = quake::load_prt(path);
    for (size_t i = 0; i < prt.portals.portals.size(); ++i) {
        const Portal& portal = prt.portals.portals[i];
        const Plane plane = quake::portal_plane(prt.portals, portal);
        EXPECT_NEAR(glm::length(plane.normal), 1.0f, 1e-6f) << "portal " << i;
        for (uint32_t p = 0; p < portal.point_count; ++p)
            EXPECT_NEAR(plane.distance(prt.portals.points[portal.first_point + p]), 0.0f, 0.01f)
                << "portal " << i << " point " << p;
    }
}

TEST(PrtFile, ExampleIsWrittenBackByteForByte)
{
    // example.prt uses the id-style layout format_prt writes, so the text comes back unchanged.
    SHARED_DATA_OR_SKIP(path, "visdemo/example.prt");
    const std::string text = example_text(path);
    EXPECT_EQ(quake::format_prt(quake::parse_prt(text, path)), text);
}

TEST(PrtFile, ExampleRoundTripsThroughAFileExactly)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.prt");
    const PrtFile original = quake::load_prt(path);
    const std::string copy =
        (std::filesystem::temp_directory_path() / ("pvscope_test_prt_" + std::to_string(getpid()) + ".prt")).string();
    quake::save_prt(copy, original);
    const PrtFile reread = quake::load_prt(copy);
    std::remove(copy.c_str());
    expect_same(original, reread);
}

TEST(PrtFile, FormattingIsStable)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.prt");
    const std::string once = quake::format_prt(quake::load_prt(path));
    const std::string twice = quake::format_prt(quake::parse_prt(once, "once"));
    EXPECT_EQ(once, twice);
    EXPECT_EQ(quake::format_prt(quake::parse_prt(kSmall, "small")), kSmall);
}

TEST(PrtFile, NonIntegralAndExtremeCoordinatesRoundTripExactly)
{
    const float values[] = {0.1f,
                            -1e-7f,
                            123456.789f,
                            -0.0f,
                            1.0f / 3.0f,
                            -2.5f,
                            1e20f,
                            123456792.0f,
                            std::numeric_limits<float>::max(),
                            -std::numeric_limits<float>::max(),
                            std::numeric_limits<float>::min(),
                            std::numeric_limits<float>::denorm_min(),
                            std::nextafter(880.0f, 1000.0f)};
    PrtFile prt;
    prt.leaf_count = 5;
    const size_t n = std::size(values);
    for (size_t i = 0; i < n; ++i) {
        Portal portal;
        portal.regions[0] = static_cast<int32_t>(i % 5);
        portal.regions[1] = static_cast<int32_t>((i + 3) % 5);
        portal.first_point = static_cast<uint32_t>(prt.portals.points.size());
        portal.point_count = 3;
        for (uint32_t p = 0; p < 3; ++p)
            prt.portals.points.emplace_back(values[i], values[(i + p + 1) % n], values[(i + 2 * p + 5) % n]);
        prt.portals.portals.push_back(portal);
    }
    const std::string text = quake::format_prt(prt);
    expect_same(prt, quake::parse_prt(text, "extreme"));
    EXPECT_EQ(quake::format_prt(quake::parse_prt(text, "extreme")), text);
    EXPECT_NE(text.find("(0.1 -1e-07 "), std::string::npos) << text;
    EXPECT_NE(text.find(" 123456.79 "), std::string::npos) << text;
    // Integral values are written as their exact integer, never with a decimal point or exponent.
    EXPECT_NE(text.find("(100000002004087734272 "), std::string::npos) << text;
    EXPECT_NE(text.find(" 123456792 "), std::string::npos) << text;
}

TEST(PrtFile, LayoutIsReadTolerantly)
{
    // One line, tabs, CRLF, no space before ')', spaces inside '(', '+' signs, exponent and
    // decimal forms (ericw writes shortest round-trip doubles).
    const std::string text = "  PRT1\r\n3\t2 4 0 1(0 0 0)( 0 +4 0 )\t(0 4e0 4.)(0 0 .4e1)\r\n"
                             "3\n1\n2\n(0 5 0)\n(2 5 0)\n(2 5 2)\r\n\r\n";
    const PrtFile tolerant = quake::parse_prt(text, "tolerant");
    expect_same(tolerant, quake::parse_prt(kSmall, "small"));
}

TEST(PrtFile, EmptyOrWrongMagicIsRefused)
{
    EXPECT_PRT_ERROR("", "empty file");
    EXPECT_PRT_ERROR(" \n\t ", "empty file");
    // PRT2 and PRT1-AM are read (tests/wld/test_prt2_file.cpp): these headers lack their portals.
    EXPECT_PRT_ERROR("PRT2\n3\n2\n2\n", "portal 0 of 2 is missing");
    EXPECT_PRT_ERROR("PRT1-AM\n2\n1\n3\n", "portal 0 of 1 is missing");
    EXPECT_PRT_ERROR("PRT3\n3\n1\n", "unknown portal file version 'PRT3'");
    EXPECT_PRT_ERROR(std::string("\x1d\x00\x00\x00\xff\xfe", 6), "binary data");
    EXPECT_PRT_ERROR("prt1\n3\n1\n", "expected a PRT1, PRT2 or PRT1-AM header, found 'prt1'");
}

TEST(PrtFile, TruncatedHeaderAndPortalsAreRefused)
{
    EXPECT_PRT_ERROR("PRT1\n", "file ends early: expected the leaf count");
    EXPECT_PRT_ERROR("PRT1\n3\n", "file ends early: expected the portal count");
    EXPECT_PRT_ERROR("PRT1\n3\n2\n", "file ends early: portal 0 of 2 is missing");
    EXPECT_PRT_ERROR(kSmall.substr(0, kSmall.find("3 1 2")), "file ends early: portal 1 of 2 is missing");

    const std::string mid = "PRT1\n3\n1\n4 0 1 (0 0 0 ) (0 4 0 ) (0 4";
    const ParseError error = error_of(mid);
    EXPECT_TRUE(error.thrown);
    EXPECT_EQ(error.offset, mid.size());
    EXPECT_EQ(error.reason, "line 4: file ends early in portal 0 point 3 of 4: expected 3 coordinates in a point");
    EXPECT_PRT_ERROR("PRT1\n3\n1\n4 0", "file ends early in portal 0: expected the second leaf number");
    EXPECT_PRT_ERROR("PRT1\n3\n1\n4 0 1 ", "file ends early in portal 0: expected '('");
    EXPECT_PRT_ERROR("PRT1\n3\n1\n3 0 1 (0 0 0 ) (0 4 0 ) (0 4 4 ", "expected ')'");
}

TEST(PrtFile, LeafNumbersOutOfRangeAreRefusedAtTheirToken)
{
    const std::string text = "PRT1\n3\n2\n4 0 1 (0 0 0 ) (0 4 0 ) (0 4 4 ) (0 0 4 )\n3 1 3 (0 5 0 ) (2 5 0 ) (2 5 2 )\n";
    const ParseError error = error_of(text);
    EXPECT_TRUE(error.thrown);
    EXPECT_EQ(error.offset, text.find("3 (0 5"));
    EXPECT_EQ(error.reason, "line 5: portal 1: leaf number 3 is out of range (the header declares 3 leaves, "
                            "numbered 0..2)");
    EXPECT_PRT_ERROR("PRT1\n3\n1\n3 -1 1 (0 0 0 ) (0 4 0 ) (0 4 4 )\n", "leaf number -1 is out of range");
    EXPECT_PRT_ERROR("PRT1\n3\n1\n3 0.5 1 (0 0 0 ) (0 4 0 ) (0 4 4 )\n",
                     "expected the first leaf number (an integer), found '0.5'");
}

TEST(PrtFile, BadCountsAreRefused)
{
    EXPECT_PRT_ERROR("PRT1\n-1\n0\n", "negative leaf count '-1'");
    EXPECT_PRT_ERROR("PRT1\n3\n-2\n", "negative portal count '-2'");
    EXPECT_PRT_ERROR("PRT1\n3\n-99999999999999999999999\n", "negative portal count");
    EXPECT_PRT_ERROR("PRT1\n3000000000\n0\n", "leaf count '3000000000' is too large");
    EXPECT_PRT_ERROR("PRT1\nlots\n0\n", "expected the leaf count (an integer), found 'lots'");
}

TEST(PrtFile, HugePortalCountInATinyFileFailsWithoutAllocating)
{
    // A hostile count must neither reserve gigabytes (ASan would report it) nor loop.
    EXPECT_PRT_ERROR("PRT1\n3\n2000000000\n3 0 1 (0 0 0 ) (0 4 0 ) (0 4 4 )\n",
                     "file ends early: portal 1 of 2000000000 is missing");
    EXPECT_PRT_ERROR("PRT1\n2147483647\n2147483647\n", "portal 0 of 2147483647 is missing");
}

TEST(PrtFile, PointCountsOutside3To64AreRefused)
{
    EXPECT_PRT_ERROR("PRT1\n3\n1\n2 0 1 (0 0 0 ) (0 4 0 )\n", "portal 0 has 2 points; a portal needs 3 to 64");
    // Appended piece by piece: GCC 12 at -O3 warns falsely (-Wrestrict) on "(" + to_string(i).
    const auto append_point = [](std::string& text, int i) {
        text.append("(");
        text.append(std::to_string(i));
        text.append(" 0 0 ) ");
    };
    std::string many = "PRT1\n3\n1\n65 0 1 ";
    for (int i = 0; i < 65; ++i)
        append_point(many, i);
    EXPECT_PRT_ERROR(many, "portal 0 has 65 points; a portal needs 3 to 64");
    std::string sixty_four = "PRT1\n3\n1\n64 0 1 ";
    for (int i = 0; i < 64; ++i)
        append_point(sixty_four, i);
    EXPECT_EQ(quake::parse_prt(sixty_four, "64").portals.points.size(), 64u);
}

TEST(PrtFile, NonFiniteAndMalformedCoordinatesAreRefused)
{
    const auto with_point = [](const std::string& point) {
        return "PRT1\n3\n1\n3 0 1 (0 0 0 ) " + point + " (0 4 4 )\n";
    };
    EXPECT_PRT_ERROR(with_point("(0 nan 0 )"), "coordinate 'nan' is not a finite number");
    EXPECT_PRT_ERROR(with_point("(0 inf 0 )"), "coordinate 'inf' is not a finite number");
    EXPECT_PRT_ERROR(with_point("(0 -infinity 0 )"), "is not a finite number");
    EXPECT_PRT_ERROR(with_point("(0 1e39 0 )"), "coordinate '1e39' is outside the float range");
    EXPECT_PRT_ERROR(with_point("(0 4x 0 )"), "expected a coordinate (a number), found '4x'");
    EXPECT_PRT_ERROR(with_point("(0 4 )"), "expected 3 coordinates in a point, found ')' after 2");
    EXPECT_PRT_ERROR(with_point("(0 4 0 (0 4 4 )"), "expected ')' after 3 coordinates, found '('");
    EXPECT_PRT_ERROR(with_point("(0 4 0 1 )"), "expected ')' after 3 coordinates, found '1'");
    EXPECT_PRT_ERROR(with_point("0 4 0 )"), "point 2 of 3: expected '(', found '0'");
    // Tiny values below the float range become 0 rather than failing (ericw prints doubles).
    EXPECT_EQ(quake::parse_prt(with_point("(0 1e-60 0 )"), "tiny").portals.points[1].y, 0.0f);
}

TEST(PrtFile, TrailingGarbageIsRefused)
{
    const ParseError error = error_of(kSmall + "junk\n");
    EXPECT_TRUE(error.thrown);
    EXPECT_EQ(error.offset, kSmall.size());
    EXPECT_EQ(error.reason, "line 6: unexpected 'junk' after the last of 2 portals; only whitespace may follow");
    EXPECT_PRT_ERROR(kSmall + ")", "unexpected ')'");
    EXPECT_NO_THROW(quake::parse_prt(kSmall + "\n\n  \t\r\n", "whitespace"));
}

TEST(PrtFile, Quake3PortalFilesAreRecognised)
{
    // q3map: a fourth header number (numfaces) and a hint flag after the two cluster numbers.
    EXPECT_PRT_ERROR("PRT1\n3\n1\n0\n4 0 1 0 (0 0 0 ) (0 4 0 ) (0 4 4 ) (0 0 4 )\n", "Quake 3");
    EXPECT_PRT_ERROR("PRT1\n3\n1\n4 0 1 0 (0 0 0 ) (0 4 0 ) (0 4 4 ) (0 0 4 )\n", "Quake 3");
    EXPECT_PRT_ERROR("PRT1\n3\n0\n2\n", "Quake 3");
}

TEST(PrtFile, FormatRefusesWhatCouldNotBeReadBack)
{
    PrtFile prt = quake::parse_prt(kSmall, "small");
    PrtFile bad = prt;
    bad.portals.portals[1].point_count = 4; // runs past the 7 points
    EXPECT_THROW(quake::format_prt(bad), std::invalid_argument);
    bad = prt;
    bad.portals.portals[0].regions[1] = 3;
    EXPECT_THROW(quake::format_prt(bad), std::invalid_argument);
    bad = prt;
    bad.portals.portals[0].point_count = 2;
    EXPECT_THROW(quake::format_prt(bad), std::invalid_argument);
    bad = prt;
    bad.portals.points[2].z = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(quake::format_prt(bad), std::invalid_argument);
}

TEST(PrtFile, DegeneratePortalHasAZeroNormal)
{
    const PrtFile prt = quake::parse_prt("PRT1\n2\n1\n3 0 1 (0 0 0 ) (1 1 1 ) (2 2 2 )\n", "collinear");
    const Plane plane = quake::portal_plane(prt.portals, prt.portals.portals[0]);
    EXPECT_EQ(plane.normal, glm::vec3(0.0f));
    EXPECT_EQ(plane.dist, 0.0f);
}

// Every damaged copy either parses or throws FileError: never another exception, a crash or
// (under the sanitizer build) an invalid access.
void expect_parses_or_file_error(std::string_view text, const std::string& what)
{
    try {
        quake::parse_prt(text, "damaged.prt");
    } catch (const FileError&) {
    } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": threw something other than FileError: " << e.what();
    }
}

TEST(PrtFile, EveryTruncationOfTheExampleParsesOrThrowsFileError)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.prt");
    const std::string text = example_text(path);
    size_t parsed = 0;
    for (size_t length = 0; length <= text.size(); ++length) {
        try {
            quake::parse_prt(std::string_view(text).substr(0, length), "truncated.prt");
            ++parsed;
        } catch (const FileError&) {
        } catch (const std::exception& e) {
            ADD_FAILURE() << "truncated to " << length << " bytes: " << e.what();
        }
    }
    // Only the whole file and the two cuts inside its final ") \n" hold all 12 portals.
    EXPECT_EQ(parsed, 3u);
}

TEST(PrtFile, RandomByteChangesToTheExampleParseOrThrowFileError)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.prt");
    const std::string text = example_text(path);
    std::mt19937 rng(20240611u);
    for (int round = 0; round < 300; ++round) {
        std::string damaged = text;
        const size_t at = rng() % damaged.size();
        damaged[at] = static_cast<char>(rng() & 0xFF);
        expect_parses_or_file_error(damaged, "round " + std::to_string(round) + " (byte " + std::to_string(at) + ")");
    }
}

} // namespace
} // namespace pvs
