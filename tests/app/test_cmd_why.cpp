// `pvscope why` as a script uses it: its JSON fields and exit codes, on the visdemo example whose
// pairs are known by hand (tests/support/visdemo_rows.h).
#include "app/cmd_why.h"

#include "tests/support/test_data.h"
#include "tests/support/visdemo_rows.h"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>

namespace pvs::test {
namespace {

int why(const std::string& arguments)
{
    CLI::App app;
    int code = -1;
    app::register_why_command(app, code);
    app.parse("why " + arguments, false);
    return code;
}

nlohmann::json why_json(const std::string& arguments)
{
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    const int code = why(arguments + " --json --threads 2 --budget 20000");
    testing::internal::GetCapturedStderr();
    const std::string out = testing::internal::GetCapturedStdout();
    EXPECT_EQ(code, 0) << arguments;
    return code == 0 ? nlohmann::json::parse(out) : nlohmann::json();
}

TEST(WhyCommand, JsonOfASeenPairAndAHiddenOne)
{
    SHARED_DATA_OR_SKIP(example, "visdemo/example.bsp");
    // 0 sees 10 by a line of slope 0.08 with about a unit to spare (the hand derivation).
    const nlohmann::json seen = why_json(example + " 0 10 --pvs portal-full");
    ASSERT_FALSE(seen.is_null());
    EXPECT_EQ(seen["verdict"], "sees");
    EXPECT_TRUE(seen["in_pvs"].get<bool>());
    EXPECT_TRUE(seen["in_reference"].get<bool>());
    EXPECT_EQ(seen["portal_chain"].front(), 0);
    EXPECT_EQ(seen["portal_chain"].back(), 10);
    EXPECT_EQ(seen["portal_chain"].size(), seen["chain_steps"].size() + 1);
    EXPECT_EQ(seen["witness"]["from"].size(), 3u);
    const std::string camera = seen["camera"]["argument"].get<std::string>();
    EXPECT_EQ(std::count(camera.begin(), camera.end(), ','), 4) << camera; // x,y,z,yaw,pitch
    // 0 does not see 8 (a line would have to rise both ways from the south door).
    const nlohmann::json hidden = why_json(example + " 0 8 --pvs portal-full");
    ASSERT_FALSE(hidden.is_null());
    EXPECT_FALSE(hidden["in_reference"].get<bool>());
    EXPECT_TRUE(hidden["witness"].is_null());
    EXPECT_TRUE(hidden["camera"].is_null());
    EXPECT_EQ(hidden["verdict"], hidden["in_pvs"].get<bool>() ? "overdraw" : "hidden");
    EXPECT_EQ(hidden["portal_chain"].is_null(), !hidden["flow_holds"].get<bool>());
}

TEST(WhyCommand, BadRegionOrFileIsExitTwoWithTheReason)
{
    SHARED_DATA_OR_SKIP(example, "visdemo/example.bsp");
    testing::internal::CaptureStderr();
    EXPECT_EQ(why(example + " 0 99 --pvs none"), 2);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("region 99 is out of range"), std::string::npos) << err;
    testing::internal::CaptureStderr();
    EXPECT_EQ(why(example + ".missing 0 1"), 2);
    EXPECT_NE(testing::internal::GetCapturedStderr().find(".missing"), std::string::npos);
}

} // namespace
} // namespace pvs::test
