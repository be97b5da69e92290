// `pvscope check` as a script uses it: its exit code (0 healthy, 1 unhealthy, 2 unreadable) and
// its JSON, on a real map and on zones built to fail.
#include "app/cmd_check.h"

#include "tests/support/test_data.h"
#include "visibility/eval/zone_check.h"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace pvs::test {
namespace {

int check(const std::string& arguments)
{
    CLI::App app;
    int code = -1;
    app::register_check_command(app, code);
    app.parse("check " + arguments, false);
    return code;
}

TEST(CheckCommand, ExitCodesForScripts)
{
    SHARED_DATA_OR_SKIP(e1m1, "quake/e1m1.bsp");
    testing::internal::CaptureStdout();
    EXPECT_EQ(check(e1m1 + " --json"), 0);
    const nlohmann::json j = nlohmann::json::parse(testing::internal::GetCapturedStdout());
    EXPECT_EQ(j["regions"], 1206);
    EXPECT_TRUE(j["healthy"].get<bool>());
    EXPECT_EQ(j["crossings"]["tree"]["blocked"], 0);
    EXPECT_GT(j["crossings"]["tree"]["traced"].get<int>(), 3000);
    EXPECT_TRUE(j["blocked_crossings"].empty());
    testing::internal::CaptureStderr();
    EXPECT_EQ(check(e1m1 + ".missing"), 2);
    EXPECT_NE(testing::internal::GetCapturedStderr().find(".missing"), std::string::npos);
}

TEST(CheckCommand, ErrorsFailAndWarningsFailOnlyWhenStrict)
{
    ZoneHealth health;
    CheckItem warning;
    warning.name = "leaks";
    warning.severity = CheckSeverity::Warning;
    warning.failed = 1;
    health.items.push_back(warning);
    EXPECT_EQ(app::check_exit_code(health, false), 0);
    EXPECT_EQ(app::check_exit_code(health, true), 1);
    CheckItem error = warning;
    error.name = "portal_crossings";
    error.severity = CheckSeverity::Error;
    health.items.push_back(error);
    EXPECT_EQ(app::check_exit_code(health, false), 1);
    health.items.back().failed = 0;
    health.items.front().failed = 0;
    EXPECT_EQ(app::check_exit_code(health, true), 0);
}

} // namespace
} // namespace pvs::test
