// The Zone panel's Health section, headless: `check` on the open zone through the inspector's job
// gives the command line's report, and a failure's place takes the camera there. The zone is a
// generated one whose PVS row 0 was made to lack a portal neighbour (a known failure).
#include "gen/generate_zone.h"
#include "tests/support/test_data.h"
#include "ui/gui/inspector_state.h"
#include "visibility/bit_row.h"
#include "visibility/portal/portalize.h"
#include "wld/convert.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <thread>
#include <unistd.h>

namespace pvs {
namespace {

using gui::InspectorState;
using gui::JobStatus;

// A generated zone whose region 0 no longer sees `hidden`, one of its portal neighbours.
Zone zone_missing_a_neighbour(uint32_t& hidden)
{
    gen::GenParams params;
    params.rooms = 8;
    params.seed = 11;
    params.bake = true;
    Zone zone = gen::generate_zone(params);
    hidden = UINT32_MAX;
    if (!zone.baked_pvs)
        return zone; // no PVS to take a bit from: the caller's assertion fails
    const PortalSet portals = build_zone_portals(zone);
    for (const Portal& p : portals.portals)
        if (p.regions[0] == 0 || p.regions[1] == 0)
            hidden = uint32_t(p.regions[0] == 0 ? p.regions[1] : p.regions[0]);
    const Pvs old = *zone.baked_pvs;
    const uint32_t dropped = hidden;
    zone.baked_pvs = Pvs::build(old.region_count(), [&](uint32_t r, std::span<uint64_t> row) {
        old.decode_row(r, row);
        if (r == 0)
            row[dropped / 64] &= ~(uint64_t{1} << (dropped % 64));
        return true;
    });
    return zone;
}

TEST(HealthSection, ChecksTheOpenZoneAndGoesToAFailure)
{
    uint32_t hidden = 0;
    const Zone made = zone_missing_a_neighbour(hidden);
    ASSERT_NE(hidden, UINT32_MAX) << "region 0 has a portal neighbour";
    const std::string path =
        (std::filesystem::temp_directory_path() / ("pvscope-health-" + std::to_string(::getpid()) + ".s3d")).string();
    write_zone(made, path, ZoneOutput::S3d);
    InspectorState state;
    state.set_viewport_size(160, 120);
    const bool opened = state.open_zone(path);
    std::filesystem::remove(path);
    ASSERT_TRUE(opened) << state.error();

    ASSERT_TRUE(state.start_check());
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    while (state.check_job().poll() == JobStatus::Running && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_EQ(state.check_job().status(), JobStatus::Done) << state.check_job().error();
    const ZoneHealth& health = *state.check_job().output();
    const ZoneHealth direct = check_zone(state.zone());
    ASSERT_EQ(health.items.size(), direct.items.size());
    for (size_t i = 0; i < direct.items.size(); ++i)
        EXPECT_EQ(health.items[i].failed, direct.items[i].failed) << direct.items[i].name;

    const CheckItem* neighbours = health.item("pvs_neighbours");
    ASSERT_NE(neighbours, nullptr);
    ASSERT_GE(neighbours->failed, 1u);
    size_t at = neighbours->places.size();
    for (size_t i = 0; i < neighbours->places.size(); ++i)
        if (neighbours->places[i].region == 0 && neighbours->places[i].other == int32_t(hidden))
            at = i;
    ASSERT_LT(at, neighbours->places.size()) << "the pair 0 -> " << hidden << " is among the failures";

    state.go_to_check_place(neighbours->places[at]);
    EXPECT_EQ(state.selection().region, 0);
    EXPECT_EQ(state.frame().region, 0) << "the camera went into region 0";

    CheckPlace point;
    point.has_point = true;
    point.point = state.zone().regions[hidden].bounds.center();
    state.go_to_check_place(point);
    EXPECT_EQ(state.view_camera().position, point.point);
}

} // namespace
} // namespace pvs
