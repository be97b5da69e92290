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

// --pvs portal-full explains the flow it runs for the chain (one bake): its bits are the hand-
// derived rows'. --no-chain runs no flow: the bit, the sight line and the verdict as with it,
// no chain, and "flow_holds" unknown (null), not false.
TEST(WhyCommand, PortalFullIsItsOwnFlowAndNoChainSkipsIt)
{
    SHARED_DATA_OR_SKIP(example, "visdemo/example.bsp");
    for (const uint32_t b : {3u, 8u, 10u}) {
        const std::string pair = example + " 0 " + std::to_string(b);
        const bool expected = std::count(kExampleExpected[0].begin(), kExampleExpected[0].end(), b) > 0;
        const nlohmann::json with_chain = why_json(pair + " --pvs portal-full");
        ASSERT_FALSE(with_chain.is_null());
        EXPECT_EQ(with_chain["in_pvs"].get<bool>(), expected) << "0 -> " << b;
        EXPECT_TRUE(with_chain["flow_run"].get<bool>());
        EXPECT_EQ(with_chain["flow_holds"].get<bool>(), expected) << "the flow is the PVS explained";
        const nlohmann::json without = why_json(pair + " --pvs file --no-chain");
        ASSERT_FALSE(without.is_null());
        EXPECT_EQ(without["in_reference"], with_chain["in_reference"]) << "0 -> " << b;
        EXPECT_FALSE(without["flow_run"].get<bool>());
        EXPECT_TRUE(without["flow_holds"].is_null());
        EXPECT_TRUE(without["portal_chain"].is_null());
        EXPECT_NE(without["verdict"], "unexplained");
    }
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
