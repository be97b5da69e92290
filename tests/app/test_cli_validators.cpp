// The shared --camera and --size validators: CLI11 refuses a bad value before the command runs,
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

} // namespace

} // namespace pvs::app
