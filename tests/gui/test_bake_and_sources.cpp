// The bake job's state machine (ui/gui/bake_job.h) driven headless on a tiny generated zone:
// start, a second start refused while running, completion with the same PVS as calling the
// baker directly, cancel at a known point (the first progress call), the zone replaced while a
// bake runs; then the inspector's PVS source switch and the PVS diff helpers.
#include "gen/generate_zone.h"
#include "tests/support/gpu_driver.h"
#include "ui/gui/bake_job.h"
#include "ui/gui/inspector_state.h"
#include "ui/gui/pvs_rows.h"
#include "visibility/methods/vis_method.h"
#include "visibility/portal/portalize.h"

#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <thread>

namespace pvs {
namespace {

using gui::BakeJob;
using gui::JobStatus;

Zone tiny_zone()
{
    gen::GenParams params;
    params.rooms = 5;
    params.seed = 7;
    Zone zone = gen::generate_zone(params);
    zone.baked_pvs.reset(); // whatever the generator does, these tests bake their own
    return zone;
}

// Polls until the job leaves Running (a minute at most: the tiny bakes take milliseconds).
JobStatus wait(BakeJob& job)
{
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (job.poll() == JobStatus::Running && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    return job.status();
}

std::vector<uint64_t> all_rows(const Pvs& pvs)
{
    std::vector<uint64_t> words(size_t(pvs.region_count()) * pvs.words_per_row());
    for (uint32_t r = 0; r < pvs.region_count(); ++r)
        pvs.decode_row(r, std::span(words).subspan(size_t(r) * pvs.words_per_row(), pvs.words_per_row()));
    return words;
}

TEST(BakeJob, CompletesWithTheBakersOwnResult)
{
    const Zone zone = tiny_zone();
    BakeJob job;
    EXPECT_EQ(job.status(), JobStatus::Idle);
    gui::BakeRequest request;
    request.method = "portal-full";
    request.settings.threads = 1;
    ASSERT_TRUE(job.start(zone, request));
    ASSERT_EQ(wait(job), JobStatus::Done) << job.error();
    ASSERT_TRUE(job.result());
    EXPECT_EQ(job.result()->region_count(), zone.region_count());
    EXPECT_GT(job.portal_count(), 0u);

    VisParams params;
    params.method = VisParams::Method::Full;
    params.threads = 1;
    const Pvs direct = bake_portal_vis(build_zone_portals(zone), uint32_t(zone.region_count()), params);
    EXPECT_EQ(all_rows(*job.result()), all_rows(direct));
    // Every region sees itself and its portal neighbours.
    const PortalSet portals = build_zone_portals(zone);
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        EXPECT_TRUE(job.result()->visible(r, r));
        for (uint32_t n : gui::portal_neighbours(portals, r))
            EXPECT_TRUE(job.result()->visible(r, n)) << r << " -> " << n;
    }
}

// The Bake panel offers every method of the registry that bakes: each runs as a job with the
// request's settings and gives the rows the command line's bake gives (the registry run with the
// same settings); a name the registry does not know fails the job with the names it has.
TEST(BakeJob, RunsEveryBakingMethodOfTheRegistry)
{
    const Zone zone = tiny_zone();
    size_t ran = 0;
    for (const VisMethod& m : vis_methods()) {
        if (!m.bakes)
            continue;
        gui::BakeRequest request;
        request.method = std::string(m.name);
        request.settings.samples = 64;
        request.settings.raster_points = 2;
        request.settings.raster_resolution = 16;
        BakeJob job;
        ASSERT_TRUE(job.start(zone, request)) << m.name;
        const JobStatus status = wait(job);
        MethodSettings settings = request.settings;
        std::optional<MethodRun> direct;
        try {
            direct = m.run(zone, settings);
        } catch (const std::exception& e) {
            EXPECT_EQ(status, JobStatus::Failed) << m.name << ": the command line refuses it (" << e.what() << ")";
            EXPECT_EQ(job.error(), e.what()) << m.name;
            continue;
        }
        ASSERT_EQ(status, JobStatus::Done) << m.name << ": " << job.error();
        ASSERT_TRUE(job.result() && direct->pvs) << m.name;
        EXPECT_EQ(all_rows(*job.result()), all_rows(*direct->pvs)) << m.name;
        ++ran;
    }
    EXPECT_GE(ran, 5u) << "portal-fast, portal-full, clustered, reference and raster bake a generated zone";
    gui::BakeRequest unknown;
    unknown.method = "no-such-method";
    BakeJob job;
    ASSERT_TRUE(job.start(zone, unknown));
    EXPECT_EQ(wait(job), JobStatus::Failed);
    EXPECT_NE(job.error().find("portal-full"), std::string::npos) << job.error();
}

// The panel's device choice: a raster bake on the GPU from the job's own thread (its own EGL
// context there) gives the rows the same bake gives on the calling thread, and says it ran on
// the GPU. Skips without a GPU driver unless PVSCOPE_REQUIRE_GPU_DRIVER=1 (CI: llvmpipe).
TEST(BakeJob, RasterOnTheGpuFromTheJobThread)
{
    GPU_DRIVER_OR_SKIP();
    const Zone zone = tiny_zone();
    gui::BakeRequest request;
    request.method = "raster";
    request.settings.raster_points = 2;
    request.settings.raster_resolution = 16;
    request.settings.raster_device = RasterDevice::Gpu;
    BakeJob job;
    ASSERT_TRUE(job.start(zone, request));
    ASSERT_EQ(wait(job), JobStatus::Done) << job.error();
    const MethodRun direct = find_vis_method("raster")->run(zone, request.settings);
    ASSERT_TRUE(job.result() && direct.pvs);
    EXPECT_EQ(all_rows(*job.result()), all_rows(*direct.pvs));
    EXPECT_NE(direct.summary.find("gpu: "), std::string::npos) << direct.summary;
}

TEST(BakeJob, RefusesASecondStartWhileRunning)
{
    const Zone zone = tiny_zone();
    BakeJob job;
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    job.on_progress = [released](double fraction) {
        if (fraction == 0.0)
            released.wait(); // hold the worker at its first progress call
    };
    ASSERT_TRUE(job.start(zone, {}));
    EXPECT_FALSE(job.start(zone, {}));
    EXPECT_EQ(job.poll(), JobStatus::Running);
    release.set_value();
    EXPECT_EQ(wait(job), JobStatus::Done);
    ASSERT_TRUE(job.take_result());
    EXPECT_FALSE(job.result()); // taken
    EXPECT_TRUE(job.start(zone, {})); // and again once finished
    EXPECT_EQ(wait(job), JobStatus::Done);
}

TEST(BakeJob, CancelAtTheFirstProgressKeepsNothing)
{
    const Zone zone = tiny_zone();
    BakeJob job;
    job.on_progress = [&job](double) { job.cancel(); };
    gui::BakeRequest request;
    request.method = "portal-full";
    request.settings.threads = 2;
    ASSERT_TRUE(job.start(zone, request));
    EXPECT_EQ(wait(job), JobStatus::Cancelled);
    EXPECT_FALSE(job.result());
    EXPECT_TRUE(job.report().cancelled);
}

TEST(BakeJob, StopWaitsForTheWorker)
{
    const Zone zone = tiny_zone();
    BakeJob job;
    job.on_progress = [](double) { std::this_thread::sleep_for(std::chrono::milliseconds(20)); };
    ASSERT_TRUE(job.start(zone, {}));
    job.stop();
    EXPECT_NE(job.status(), JobStatus::Running);
}

TEST(InspectorBake, BakedPvsBecomesASourceAndTheCullerUsesIt)
{
    gui::InspectorState state;
    state.set_viewport_size(64, 48);
    state.open_demo();
    EXPECT_EQ(state.has_pvs_source(gui::PvsSource::File), state.zone().baked_pvs.has_value());
    EXPECT_TRUE(state.has_pvs_source(gui::PvsSource::None));
    EXPECT_FALSE(state.has_pvs_source(gui::PvsSource::Baked));
    EXPECT_FALSE(state.set_pvs_source(gui::PvsSource::Baked));

    ASSERT_TRUE(state.set_pvs_source(gui::PvsSource::None));
    EXPECT_EQ(state.active_pvs(), nullptr);
    EXPECT_FALSE(state.frame().pvs_used);

    gui::BakeRequest request;
    request.method = "portal-fast";
    ASSERT_TRUE(state.start_bake(request));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (!state.baked_pvs() && std::chrono::steady_clock::now() < deadline) {
        state.poll_bake();
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ASSERT_TRUE(state.baked_pvs());
    EXPECT_EQ(state.pvs_source(), gui::PvsSource::None); // a bake does not switch by itself
    const uint64_t generation = state.pvs_generation();
    ASSERT_TRUE(state.set_pvs_source(gui::PvsSource::Baked));
    EXPECT_NE(state.pvs_generation(), generation);
    EXPECT_EQ(state.active_pvs(), &*state.baked_pvs());
    state.cull_mode = CullMode::Pvs;
    const CullStats s = state.frame();
    ASSERT_EQ(s.camera, CameraPlace::InRegion);
    EXPECT_TRUE(s.pvs_used);
    // The PVS stage kept exactly the camera region's row of the baked PVS.
    EXPECT_EQ(s.regions_after_pvs, gui::pvs_row_regions(*state.baked_pvs(), uint32_t(s.region)).size());

    // A new zone drops the bake and falls back to the file's PVS or none.
    state.open_demo();
    EXPECT_FALSE(state.baked_pvs());
    EXPECT_NE(state.pvs_source(), gui::PvsSource::Baked);
}

TEST(InspectorBake, OpeningAZoneWhileBakingStopsTheBake)
{
    gui::InspectorState state;
    state.set_viewport_size(64, 48);
    state.open_demo();
    state.bake_job().on_progress = [](double) { std::this_thread::sleep_for(std::chrono::milliseconds(5)); };
    gui::BakeRequest request;
    request.method = "portal-full";
    ASSERT_TRUE(state.start_bake(request));
    state.open_demo(); // must not leave the worker reading the old zone
    EXPECT_NE(state.bake_job().status(), JobStatus::Running);
    EXPECT_FALSE(state.baked_pvs());
}

TEST(PvsRows, RowColumnAndDiffMatchPairByPairLookups)
{
    const uint32_t n = 70; // two words per row
    const auto sees = [](uint32_t from, uint32_t to) { return from == 5 || (from + to) % 3 == 0 || from == to; };
    auto source = [&](uint32_t region, std::span<uint64_t> row) {
        for (uint32_t to = 0; to < 70; ++to)
            if (sees(region, to))
                row[to / 64] |= uint64_t(1) << (to % 64);
        return region != 5; // region 5's row is missing: all visible
    };
    for (const Pvs::StoragePolicy policy : {Pvs::StoragePolicy::Dense, Pvs::StoragePolicy::Compressed}) {
        const Pvs pvs = Pvs::build(n, source, policy);
        for (uint32_t r : {0u, 5u, 69u}) {
            std::vector<uint32_t> row, column;
            for (uint32_t t = 0; t < n; ++t) {
                if (sees(r, t))
                    row.push_back(t);
                if (sees(t, r))
                    column.push_back(t);
            }
            EXPECT_EQ(gui::pvs_row_regions(pvs, r), row);
            gui::PvsColumnScan whole; // every row in one call
            whole.restart(r);
            EXPECT_TRUE(whole.step(pvs, pvs.row_count()));
            EXPECT_EQ(whole.regions, column);
            // Read a few rows a frame, as the region panel does: the same column.
            gui::PvsColumnScan scan;
            scan.restart(r);
            int slices = 0;
            while (!scan.step(pvs, 16))
                ++slices;
            EXPECT_EQ(slices, 4); // 70 rows, 16 a slice: the fifth call ends it
            EXPECT_EQ(scan.regions, column);
        }
    }
    const Pvs pvs = Pvs::build(n, source);
    gui::PvsColumnScan past; // a region past the last: no column
    past.restart(n);
    EXPECT_TRUE(past.step(pvs, n));
    EXPECT_TRUE(past.regions.empty());
    EXPECT_EQ(gui::pvs_row_regions(pvs, 5).size(), n);
    EXPECT_TRUE(gui::pvs_row_regions(pvs, n).empty());

    const auto diff = gui::diff_regions({1, 2, 5, 9}, {2, 3, 9, 10});
    EXPECT_EQ(diff.only_a, (std::vector<uint32_t>{1, 5}));
    EXPECT_EQ(diff.only_b, (std::vector<uint32_t>{3, 10}));

    const Pvs all = Pvs::build(n, [](uint32_t, std::span<uint64_t>) { return false; });
    const gui::PvsDiffCounts counts = gui::diff_pvs(pvs, all);
    uint64_t missing_from_pvs = 0;
    for (uint32_t a = 0; a < n; ++a)
        for (uint32_t b = 0; b < n; ++b)
            missing_from_pvs += pvs.visible(a, b) ? 0 : 1;
    EXPECT_EQ(counts.only_a, 0u);
    EXPECT_EQ(counts.only_b, missing_from_pvs);
}

TEST(PvsRows, PortalNeighbours)
{
    PortalSet set;
    set.portals = {Portal{{0, 1}, 0, 0}, Portal{{2, 0}, 0, 0}, Portal{{1, 2}, 0, 0}, Portal{{0, 1}, 0, 0}};
    EXPECT_EQ(gui::portal_neighbours(set, 0), (std::vector<uint32_t>{1, 2}));
    EXPECT_EQ(gui::portal_neighbours(set, 2), (std::vector<uint32_t>{0, 1}));
    EXPECT_TRUE(gui::portal_neighbours(set, 3).empty());
}

} // namespace
} // namespace pvs
