// The shared --camera, --size, --fov and distance validators: CLI11 refuses a bad value before the command runs,
// with a message naming what was expected and what was given; good values pass unchanged.
#include "app/cli_validators.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace pvs::app {
namespace {

// Parses `argv` into an app with --camera and --size; returns CLI11's error text, or "" on success.
std::string parse(std::vector<std::string> args, std::string& camera, std::string& size)
{
    CLI::App app{"test"};
    app.add_option("--camera", camera)->check(camera_validator());
    app.add_option("--size", size)->check(size_validator());
    std::reverse(args.begin(), args.end()); // CLI11 takes the arguments last-first
    try {
        app.parse(args);
        return "";
    } catch (const CLI::ParseError& e) {
        return e.what();
    }
}

TEST(CliValidators, GoodValuesPass)
{
    std::string camera, size;
    EXPECT_EQ(parse({"--camera", "1,2.5,-3,90,-10", "--size", "800x600"}, camera, size), "");
    EXPECT_EQ(camera, "1,2.5,-3,90,-10");
    EXPECT_EQ(size, "800x600");
}

TEST(CliValidators, BadValuesAreRefusedWithWhatWasExpected)
{
    std::string camera, size;
    const std::string bad_camera = parse({"--camera", "1,2,3"}, camera, size);
    EXPECT_NE(bad_camera.find("x,y,z,yaw,pitch"), std::string::npos) << bad_camera;
    EXPECT_NE(bad_camera.find("'1,2,3'"), std::string::npos) << bad_camera;
    for (const char* s : {"0x600", "800x9000", "800", "800x600x2", "axb"}) {
        const std::string bad_size = parse({"--size", s}, camera, size);
        EXPECT_NE(bad_size.find("WIDTHxHEIGHT"), std::string::npos) << s << ": " << bad_size;
    }
}

// --threads: 0 (all cores) to 1024 pass; a typo of a million is refused before anything runs (a
// million threads asked of the raster baker once aborted the process).
TEST(CliValidators, ThreadCountsInRangeOnly)
{
    const auto parse_threads = [](const std::string& value) {
        CLI::App app{"test"};
        unsigned threads = 0;
        app.add_option("--threads", threads)->check(threads_validator());
        try {
            app.parse(std::vector<std::string>{value, "--threads"});
            return std::string();
        } catch (const CLI::ParseError& e) {
            return std::string(e.what());
        }
    };
    EXPECT_EQ(parse_threads("0"), "");
    EXPECT_EQ(parse_threads("1024"), "");
    EXPECT_NE(parse_threads("1025"), "");
    EXPECT_NE(parse_threads("1000000").find("not in range"), std::string::npos) << parse_threads("1000000");
}

// --fov, --far and --step: NaN, infinities and text are refused (CLI11's own Range and
// NonNegativeNumber let NaN through: every comparison with it is false), as are values out of range.
TEST(CliValidators, FovAndDistancesMustBeFiniteAndInRange)
{
    const auto refused = [](const CLI::Validator& v, std::string text) { return !v(text).empty(); };
    for (const char* bad : {"nan", "NaN", "inf", "-inf", "0", "0.5", "179.5", "500", "-10", "70x", "", "seventy"})
        EXPECT_TRUE(refused(fov_validator(), bad)) << "--fov " << bad;
    for (const char* good : {"1", "70", "90.5", "179"})
        EXPECT_FALSE(refused(fov_validator(), good)) << "--fov " << good;
    for (const char* bad : {"nan", "inf", "1e999", "-1", "-0.5", "far"})
        EXPECT_TRUE(refused(distance_validator(false), bad)) << "--far " << bad;
    for (const char* good : {"0", "1024", "2.5e3"})
        EXPECT_FALSE(refused(distance_validator(false), good)) << "--far " << good;
    EXPECT_TRUE(refused(distance_validator(true), "0")) << "--step 0";
    EXPECT_TRUE(refused(distance_validator(true), "nan")) << "--step nan";
    EXPECT_FALSE(refused(distance_validator(true), "4")) << "--step 4";
}

} // namespace

} // namespace pvs::app
