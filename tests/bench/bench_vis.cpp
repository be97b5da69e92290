// Portal-vis bake time (visibility/portal/portal_vis.h), 1 and 2 worker threads:
//  - BM_Vis/<method>/<map>/<threads>: portal-fast and portal-full on e1m1, e1m2 and start, the
//    portals built by pvscope from each map's tree with SkyPortals::None (as the accuracy tests);
//  - the baseline, measured in the same run: "plain-full", the same baker with passages and
//    target checks off (VisParams::passage_budget_bytes = 0, target_checks = false): ericw's flow
//    as written, same input; the summary counts the bits in which the rows differ (target checks
//    may only remove some, portal_vis.h). The baker from before the speed work, which was
//    the baseline until then, is in git (tests/bench/reference/ at commit a3773cf);
//  - BM_VisScaling/<method>/rooms:<n>: generated zones (wld/gen, GenParams::bake off, seed 1) of
//    50, 150, 500, 1500 and 5000 rooms, 2 threads, with their regions and portals as counters:
//    portal-fast and portal-full over single regions up to 1500 rooms (5000 with
//    --vis_max_rooms=5000: 90-210 CPU-s and 0.35-0.8 GB each, docs/performance.md), and
//    clustered-fast and clustered-full over box clusters (box_clusters.h, cluster_vis.h) at
//    every size (--vis_cluster_max_rooms=N lowers the largest), with clusters and
//    cluster_portals as counters. Each scaling bake runs once: its figures come from that run.
// Counters: peak_MB_est (VisReport::peak_bytes_estimate), rss_peak_MB (the process's real peak
// resident set during the bake: VmHWM, reset before it through /proc/self/clear_refs; it includes
// the loaded map, ~rss_before_MB), mean_visible, wait_s (threads waiting for an older portal),
// cpu_s (CPU seconds of all threads per bake: steadier than the wall clock when the machine is
// shared).
// After the run a summary prints the ratios (plain / new, same map and threads) and the
// growth exponents of the scaling runs (least squares of log time, wall and CPU, on log portals
// and log regions of the zone), and
// --vis_csv=FILE writes the scaling rows for tests/bench/tools/plot_vis_scaling.
//
//   build/tests/bench/bench_vis --benchmark_filter='BM_Vis/' --benchmark_counters_tabular=true
//   build/tests/bench/bench_vis --benchmark_filter='BM_VisScaling' --vis_csv=/tmp/vis_scaling.csv
//   build/tests/bench/plot_vis_scaling /tmp/vis_scaling.csv docs/images/vis_scaling.png
#include "tests/support/test_data.h"
#include "visibility/portal/box_clusters.h"
#include "visibility/portal/cluster_vis.h"
#include "visibility/portal/portal_vis.h"
#include "visibility/portal/portalize.h"
#include "gen/generate_zone.h"
#include "wld/zone_file.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace pvs {
namespace {

using Method = VisParams::Method;

struct VisInput {
    uint32_t regions = 0;
    PortalSet portals;
    RegionClusters clusters; // generated zones only: box_merge_clusters with its defaults
    double cluster_seconds = 0.0; // forming them (not part of the timed bake)
};

const VisInput* quake_input(const std::string& map)
{
    static std::map<std::string, std::unique_ptr<VisInput>> cache;
    auto& slot = cache[map];
    if (!slot) {
        const auto path = test::find_shared_data("quake/" + map + ".bsp");
        if (!path)
            return nullptr;
        const Zone zone = load_zone(*path);
        slot = std::make_unique<VisInput>();
        slot->regions = uint32_t(zone.region_count());
        PortalOptions options;
        options.sky = SkyPortals::None;
        slot->portals = build_zone_portals(zone, options);
    }
    return slot.get();
}

const VisInput& generated_input(int rooms)
{
    static std::map<int, std::unique_ptr<VisInput>> cache;
    auto& slot = cache[rooms];
    if (!slot) {
        gen::GenParams params;
        params.rooms = rooms;
        params.seed = 1;
        params.cell_size = 32.0f;
        params.bake = false; // the benchmark bakes, the generator must not
        const Zone zone = gen::generate_zone(params);
        slot = std::make_unique<VisInput>();
        slot->regions = uint32_t(zone.region_count());
        slot->portals = build_zone_portals(zone);
        const auto start = std::chrono::steady_clock::now();
        slot->clusters = box_merge_clusters(zone.regions, slot->portals);
        slot->cluster_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return *slot;
}

// Resident-set figures of this process from /proc/self/status, in MB (0 where unavailable).
double status_mb(const char* key)
{
    std::ifstream status("/proc/self/status");
    std::string line;
    const size_t key_length = std::strlen(key);
    while (std::getline(status, line))
        if (line.compare(0, key_length, key) == 0)
            return std::stod(line.substr(key_length + 1)) / 1024.0; // "VmHWM:  1234 kB"
    return 0.0;
}

// CPU seconds of the whole process (all threads): with other jobs on the machine this is a
// steadier measure of the bake's work than the wall clock.
double process_cpu_seconds()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

void reset_peak_rss()
{
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5"; // resets VmHWM to the current resident set (Linux 4.0+)
}

// Seconds per bake, by "method/input/threads", for the summary after the run.
std::map<std::string, double>& timings()
{
    static std::map<std::string, double> table;
    return table;
}

// CPU seconds (all threads) per bake, by the same key.
std::map<std::string, double>& cpu_timings()
{
    static std::map<std::string, double> table;
    return table;
}

// The last result of each Quake bake, by the same key: the summary counts the bits in which the
// baker and the plain flow differ.
std::map<std::string, Pvs>& results()
{
    static std::map<std::string, Pvs> table;
    return table;
}

// Bits set in a and not in b, over all rows (same region count).
size_t bits_only_in(const Pvs& a, const Pvs& b)
{
    std::vector<uint64_t> row_a(a.words_per_row()), row_b(b.words_per_row());
    size_t count = 0;
    for (uint32_t r = 0; r < a.region_count(); ++r) {
        a.decode_row(r, row_a);
        b.decode_row(r, row_b);
        for (size_t w = 0; w < row_a.size(); ++w)
            count += size_t(std::popcount(row_a[w] & ~row_b[w]));
    }
    return count;
}

struct ScalingRow {
    std::string method;
    int rooms = 0;
    uint32_t regions = 0, clusters = 0; // clusters: the regions for an unclustered bake
    size_t portals = 0, cluster_portals = 0;
    double seconds = 0.0, cpu_seconds = 0.0, mean_visible = 0.0, peak_mb = 0.0, rss_peak_mb = 0.0;
};

std::vector<ScalingRow>& scaling_rows()
{
    static std::vector<ScalingRow> rows;
    return rows;
}

// plain: passages and target checks off (the baseline).
Pvs bake(bool plain, const VisInput& in, Method method, unsigned threads, VisReport& report)
{
    VisParams params;
    params.method = method;
    params.threads = threads;
    if (plain) {
        params.passage_budget_bytes = 0;
        params.target_checks = false;
    }
    return bake_portal_vis(in.portals, in.regions, params, &report);
}

// Times `bake_once` (a bake of `in`, filling the report) with the counters below; returns the mean
// seconds per bake. `last`, when given, gets the last result; `last_report` its report.
double run_timed(benchmark::State& state, const VisInput& in, const std::function<Pvs(VisReport&)>& bake_once,
                 Pvs* last = nullptr, VisReport* last_report = nullptr)
{
    VisReport report;
    double total = 0.0, cpu_total = 0.0, rss_peak = 0.0, rss_before = 0.0;
    for (auto _ : state) {
        rss_before = status_mb("VmRSS:");
        reset_peak_rss();
        const auto start = std::chrono::steady_clock::now();
        const double cpu_start = process_cpu_seconds();
        Pvs pvs = bake_once(report);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        cpu_total += process_cpu_seconds() - cpu_start;
        state.SetIterationTime(seconds);
        total += seconds;
        rss_peak = std::max(rss_peak, status_mb("VmHWM:"));
        benchmark::DoNotOptimize(pvs);
        if (last)
            *last = std::move(pvs);
    }
    state.counters["regions"] = in.regions;
    state.counters["portals"] = double(in.portals.portals.size());
    state.counters["mean_visible"] = report.mean_visible;
    state.counters["peak_MB_est"] = double(report.peak_bytes_estimate) / (1024.0 * 1024.0);
    state.counters["rss_peak_MB"] = rss_peak;
    state.counters["rss_before_MB"] = rss_before;
    state.counters["wait_s"] = report.wait_seconds;
    const double iterations = double(std::max<benchmark::IterationCount>(state.iterations(), 1));
    state.counters["cpu_s"] = cpu_total / iterations;
    if (last_report)
        *last_report = report;
    return total / iterations;
}

// Times bakes of `in` by the baker or the plain flow; see run_timed.
double run_bakes(benchmark::State& state, bool plain, const VisInput& in, Method method, unsigned threads,
                 Pvs* last = nullptr)
{
    return run_timed(
        state, in, [&](VisReport& report) { return bake(plain, in, method, threads, report); }, last);
}

const char* method_name(bool plain, Method method)
{
    if (plain)
        return method == Method::Full ? "plain-full" : "plain-fast";
    return method == Method::Full ? "portal-full" : "portal-fast";
}

// Arguments: the map (index into kMaps), the threads; the method and baseline from the name.
const char* const kMaps[] = {"e1m1", "e1m2", "start"};

void BM_Vis(benchmark::State& state, bool plain, Method method)
{
    const std::string map = kMaps[state.range(0)];
    const VisInput* in = quake_input(map);
    if (in == nullptr) {
        state.SkipWithError(("SKIPPED: needs ../shared/data/quake/" + map + ".bsp").c_str());
        return;
    }
    const unsigned threads = unsigned(state.range(1));
    const std::string key = std::string(method_name(plain, method)) + "/" + map + "/" + std::to_string(threads);
    Pvs last;
    timings()[key] = run_bakes(state, plain, *in, method, threads, &last);
    cpu_timings()[key] = state.counters["cpu_s"].value;
    results()[key] = std::move(last);
    state.SetLabel(map);
}

void vis_args(benchmark::internal::Benchmark* b)
{
    b->ArgNames({"map", "threads"});
    for (int map = 0; map < 3; ++map)
        for (int threads : {1, 2})
            b->Args({map, threads});
    b->UseManualTime()->Unit(benchmark::kMillisecond);
}

// (portal-fast has no passages or target checks: its baseline would be itself.)
BENCHMARK_CAPTURE(BM_Vis, portal_fast, false, Method::Fast)->Apply(vis_args)->MinTime(0.3);
BENCHMARK_CAPTURE(BM_Vis, plain_full, true, Method::Full)->Apply(vis_args)->Iterations(1);
BENCHMARK_CAPTURE(BM_Vis, portal_full, false, Method::Full)->Apply(vis_args)->Iterations(1);

const char* scaling_name(bool clustered, Method method)
{
    if (clustered)
        return method == Method::Full ? "clustered-full" : "clustered-fast";
    return method_name(false, method);
}

// One bake of a generated zone, timed once; the row for the summary comes from that same bake.
void BM_VisScaling(benchmark::State& state, Method method, int rooms, bool clustered)
{
    const VisInput& in = generated_input(rooms);
    VisReport report;
    ClusterReport cluster_report;
    const double seconds =
        clustered ? run_timed(
                        state, in,
                        [&](VisReport& r) {
                            VisParams params;
                            params.method = method;
                            params.threads = 2;
                            return bake_clustered_portal_vis(in.portals, in.clusters.cluster_of_region,
                                                             in.clusters.cluster_count, params, &r, &cluster_report);
                        },
                        nullptr, &report)
                  : run_timed(
                        state, in, [&](VisReport& r) { return bake(false, in, method, 2, r); }, nullptr, &report);
    ScalingRow row{scaling_name(clustered, method), rooms, in.regions, in.regions, in.portals.portals.size(),
                   in.portals.portals.size(), seconds, state.counters["cpu_s"].value, report.mean_visible,
                   double(report.peak_bytes_estimate) / (1024.0 * 1024.0), state.counters["rss_peak_MB"].value};
    if (clustered) {
        row.clusters = cluster_report.clusters;
        row.cluster_portals = cluster_report.cluster_portals;
        state.counters["expand_s"] = cluster_report.expand_seconds;
        state.counters["clusters_s"] = in.cluster_seconds;
        state.counters["cluster_mean_visible"] = cluster_report.cluster_mean_visible;
    }
    state.counters["clusters"] = double(row.clusters);
    state.counters["cluster_portals"] = double(row.cluster_portals);
    scaling_rows().push_back(row);
}

// Registered from main: unclustered at 50, 150, 500 and 1500 rooms, and 5000 with
// --vis_max_rooms=5000 (minutes of CPU, and 0.35-0.8 GB of process memory even with the rows
// kept as runs: docs/performance.md); clustered at all five sizes (--vis_cluster_max_rooms).
void register_scaling(int max_rooms, int max_cluster_rooms)
{
    for (bool clustered : {false, true})
        for (Method method : {Method::Fast, Method::Full})
            for (int rooms : {50, 150, 500, 1500, 5000}) {
                if (rooms > (clustered ? max_cluster_rooms : max_rooms))
                    continue;
                const std::string name = std::string("BM_VisScaling/") + scaling_name(clustered, method) +
                                         "/rooms:" + std::to_string(rooms);
                benchmark::RegisterBenchmark(name.c_str(), [method, rooms, clustered](benchmark::State& state) {
                    BM_VisScaling(state, method, rooms, clustered);
                })->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);
            }
}

// Least-squares slope of log(y) on log(x).
double growth_exponent(const std::vector<double>& x, const std::vector<double>& y)
{
    const size_t n = x.size();
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (size_t i = 0; i < n; ++i) {
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    const double denominator = double(n) * sxx - sx * sx;
    return n < 2 || denominator == 0.0 ? 0.0 : (double(n) * sxy - sx * sy) / denominator;
}

void print_summary(const std::string& csv_path)
{
    std::printf("\nPortal vis: plain flow (no passages, no target checks) / baker, same run\n");
    for (const auto& [key, seconds] : timings()) {
        if (key.rfind("portal-", 0) != 0)
            continue;
        const std::string rest = key.substr(std::strlen("portal-"));
        const auto ref = timings().find("plain-" + rest);
        if (ref == timings().end())
            continue;
        const Pvs& ours = results()[key];
        const Pvs& theirs = results()["plain-" + rest];
        const double cpu = cpu_timings()[key], ref_cpu = cpu_timings()["plain-" + rest];
        std::printf("  %-22s wall %8.3f s (plain %8.3f s, x%.2f)  cpu %8.3f s (plain %8.3f s, x%.2f)  "
                    "bits only baker %zu, only plain %zu\n",
                    key.c_str(), seconds, ref->second, ref->second / seconds, cpu, ref_cpu, ref_cpu / cpu,
                    bits_only_in(ours, theirs), bits_only_in(theirs, ours));
    }
    if (scaling_rows().empty())
        return;
    std::printf("\nScaling (generated zones, 2 threads)\n  method           rooms regions clusters portals "
                "c_portals   seconds     cpu_s  mean_vis  peak_MB   rss_MB\n");
    std::map<std::string, std::vector<double>> by_portals, by_regions, times, cpu_times;
    for (const ScalingRow& r : scaling_rows()) {
        std::printf("  %-15s %6d %7u %8u %7zu %9zu %9.3f %9.3f %9.1f %8.1f %8.1f\n", r.method.c_str(), r.rooms,
                    r.regions, r.clusters, r.portals, r.cluster_portals, r.seconds, r.cpu_seconds, r.mean_visible,
                    r.peak_mb, r.rss_peak_mb);
        by_portals[r.method].push_back(double(r.portals));
        by_regions[r.method].push_back(double(r.regions));
        times[r.method].push_back(r.seconds);
        cpu_times[r.method].push_back(std::max(r.cpu_seconds, 1e-6));
    }
    for (const auto& [method, t] : times)
        std::printf("  %s: wall ~ portals^%.2f, ~ regions^%.2f; cpu ~ portals^%.2f, ~ regions^%.2f\n", method.c_str(),
                    growth_exponent(by_portals[method], t), growth_exponent(by_regions[method], t),
                    growth_exponent(by_portals[method], cpu_times[method]),
                    growth_exponent(by_regions[method], cpu_times[method]));
    if (!csv_path.empty()) {
        std::ofstream csv(csv_path);
        csv << "method,rooms,regions,clusters,portals,cluster_portals,seconds,cpu_seconds,mean_visible,peak_mb,"
               "rss_peak_mb\n";
        for (const ScalingRow& r : scaling_rows())
            csv << r.method << ',' << r.rooms << ',' << r.regions << ',' << r.clusters << ',' << r.portals << ','
                << r.cluster_portals << ',' << r.seconds << ',' << r.cpu_seconds << ',' << r.mean_visible << ','
                << r.peak_mb << ',' << r.rss_peak_mb << '\n';
        std::printf("  rows written to %s\n", csv_path.c_str());
    }
}

} // namespace
} // namespace pvs

int main(int argc, char** argv)
{
    std::string csv_path;
    int max_rooms = 1500, max_cluster_rooms = 5000;
    std::vector<char*> args;
    for (int i = 0; i < argc; ++i) {
        if (std::strncmp(argv[i], "--vis_csv=", 10) == 0)
            csv_path = argv[i] + 10;
        else if (std::strncmp(argv[i], "--vis_max_rooms=", 16) == 0)
            max_rooms = std::atoi(argv[i] + 16);
        else if (std::strncmp(argv[i], "--vis_cluster_max_rooms=", 24) == 0)
            max_cluster_rooms = std::atoi(argv[i] + 24);
        else
            args.push_back(argv[i]);
    }
    int count = int(args.size());
    benchmark::Initialize(&count, args.data());
    if (benchmark::ReportUnrecognizedArguments(count, args.data()))
        return 1;
    pvs::register_scaling(max_rooms, max_cluster_rooms);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    pvs::print_summary(csv_path);
    return 0;
}
