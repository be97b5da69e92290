#include "app/cmd_compare.h"

#include "app/argument_parsers.h"
#include "app/error_path.h"
#include "app/exit_codes.h"
#include "app/output_files.h"
#include "app/cli_validators.h"
#include "app/process_memory.h"
#include "app/progress_bar.h"
#include "app/sigint_scope.h"
#include "app/zone_load_args.h"
#include "ui/chart/chart_file.h"
#include "ui/chart/compare_points.h"
#include "render/method_compare.h"
#include "visibility/file_error.h"
#include "wld/common/read_file.h"
#include "wld/zone_file.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>
#include <sstream>

namespace pvs::app {

namespace {

// [[row, region, triangles], ...]: the excess pairs that draw the most for nothing.
nlohmann::json worst_pairs_json(const std::vector<CostlyPair>& pairs)
{
    nlohmann::json out = nlohmann::json::array();
    for (const CostlyPair& p : pairs)
        out.push_back({p.row, p.region, p.cost});
    return out;
}


std::string csv_text(const ui::CompareResult& result)
{
    std::ostringstream out;
    out << "method,params,bound,wall_s,cpu_s,peak_mib,estimate_mib,pvs_bytes,mean_visible,missing_bits,excess_bits,"
           "rows_missing_bits,popping_pixels,crack_pixels,unknown_pixels,grazing_pixels,unfaced_pixels,triangle_overdraw\n";
    for (const ui::CompareRow& r : result.rows)
        out << r.method << ',' << r.params << ',' << bound_name(r.bound) << ',' << r.wall_s << ',' << r.cpu_s << ','
            << r.peak_mib << ',' << r.estimate_mib << ',' << r.pvs_bytes << ',' << r.mean_visible << ','
            << r.missing_bits << ',' << r.excess_bits << ',' << r.rows_missing_bits << ',' << r.popping_pixels << ','
            << r.crack_pixels << ',' << r.unknown_pixels << ',' << r.grazing_pixels << ',' << r.unfaced_pixels << ',' << r.triangle_overdraw << '\n';
    return out.str();
}

nlohmann::json json_report(const CompareCommandOptions& o, const Zone& zone, const ui::CompareResult& result)
{
    nlohmann::json rows = nlohmann::json::array();
    for (const ui::CompareRow& r : result.rows)
        rows.push_back({{"method", r.method},
                        {"params", r.params},
                        {"bound", bound_name(r.bound)},
                        {"wall_s", r.wall_s},
                        {"cpu_s", r.cpu_s},
                        {"peak_mib", r.peak_mib},
                        {"estimate_mib", r.estimate_mib},
                        {"pvs_bytes", r.pvs_bytes},
                        {"mean_visible", r.mean_visible},
                        {"missing_bits", r.missing_bits},
                        {"excess_bits", r.excess_bits},
                        {"rows_missing_bits", r.rows_missing_bits},
                        {"popping_pixels", r.popping_pixels},
                        {"crack_pixels", r.crack_pixels},
                        {"unknown_pixels", r.unknown_pixels},
                        {"missing_pairs", r.missing_pairs},
                        {"worst_overdraw_pairs", worst_pairs_json(r.worst_overdraw_pairs)},
                        {"grazing_pixels", r.grazing_pixels},
                        {"unfaced_pixels", r.unfaced_pixels},
                        {"triangle_overdraw", r.triangle_overdraw},
                        {"summary", r.summary}});
    return {{"input", o.input},
            {"regions", zone.region_count()},
            {"reference", {{"params", result.reference_params}, {"bits", result.reference_bits}}},
            {"cameras", result.cameras},
            {"size", o.size},
            {"sky", o.sky},
            {"methods", rows}};
}


void write_chart(const std::string& path, const std::string& title, const ui::CompareResult& result)
{
    const std::vector<ui::chart::ChartPoint> points = ui::chart::compare_chart_points(result);
    constexpr uint32_t kWidth = 1200, kHeight = 560;
    ui::chart::write_chart_file(points, title, kWidth, kHeight, path);
}

void print_table(std::FILE* out, const ui::CompareResult& result)
{
    std::fprintf(out, "%-12s %-42s %8s %8s %8s %9s %10s %10s %9s %9s\n", "method", "params", "wall_s", "cpu_s",
                 "peak_MiB", "mean_vis", "missing", "excess", "popping", "overdraw");
    for (const ui::CompareRow& r : result.rows)
        std::fprintf(out, "%-12s %-42s %8.3f %8.3f %8.1f %9.1f %10llu %10llu %9llu %9.2f\n", r.method.c_str(),
                     r.params.c_str(), r.wall_s, r.cpu_s, r.peak_mib, r.mean_visible,
                     static_cast<unsigned long long>(r.missing_bits), static_cast<unsigned long long>(r.excess_bits),
                     static_cast<unsigned long long>(r.popping_pixels), r.triangle_overdraw);
    std::fprintf(out, "reference: %s, %llu bits; walk: %zu cameras. missing = reference bits the method lacks "
                      "(would pop), excess = bits beyond the reference\n",
                 result.reference_params.c_str(), static_cast<unsigned long long>(result.reference_bits),
                 result.cameras);
}

int run_checked(const CompareCommandOptions& o, std::FILE* out, std::FILE* err)
{
    const auto size = parse_size_argument(o.size);
    if (!size) {
        std::fprintf(err, "pvscope: error: --size must be WIDTHxHEIGHT, not '%s'\n", o.size.c_str());
        return kExitBadArguments;
    }
    ui::CompareOptions options;
    options.methods = split_comma_list(o.methods);
    for (const std::string& name : options.methods)
        if (!find_vis_method(name)) {
            std::fprintf(err, "pvscope: error: --methods: unknown method '%s' (%s)\n", name.c_str(),
                         vis_method_names().c_str());
            return kExitBadArguments;
        }
    options.reference_samples = o.samples;
    options.seed = o.seed;
    options.cameras = o.cameras;
    options.width = (*size)[0];
    options.height = (*size)[1];
    options.sky = sky_mode_from_name(o.sky);
    options.threads = o.threads;
    options.memory_probe = peak_memory_probe();
    const Zone zone = load_zone(o.input, o.load);
    StagedProgress progress(err, &SigintScope::interrupted());
    options.progress = std::ref(progress);
    const ui::CompareResult result = ui::run_compare(zone, options);
    progress.finish();
    if (result.cancelled) {
        std::fprintf(err, "pvscope: compare cancelled: nothing was written\n");
        return kExitCancelled;
    }
    print_table(out, result);
    if (!o.csv.empty())
        write_text_file(o.csv, csv_text(result));
    if (!o.json.empty())
        write_text_file(o.json, json_report(o, zone, result).dump(2) + "\n");
    if (!o.chart.empty())
        write_chart(o.chart, std::filesystem::path(o.input).filename().string() + ": speed against accuracy", result);
    return 0;
}

} // namespace

int run_compare_command(const CompareCommandOptions& options, std::FILE* out, std::FILE* err)
{
    return run_reporting_errors(options.input, err, [&] { return run_checked(options, out, err); });
}

void register_compare_command(CLI::App& app, int& exit_code)
{
    auto o = std::make_shared<CompareCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "compare", "Every visibility method on one zone against the sampled reference: time, memory, missing and "
                   "excess bits, exact popping and overdraw; table, CSV, JSON and a speed-vs-accuracy chart");
    cmd->add_option("file", o->input, "Zone file")->required()->check(CLI::ExistingFile);
    add_zone_load_options(cmd, o->load);
    cmd->add_option("--methods", o->methods, "Comma-separated methods (default: all): " + vis_method_names() +
                                                 "; portal-full runs at levels 1-4 and without passages / target "
                                                 "checks. The reference always runs.");
    cmd->add_option("--samples", o->samples, "Reference: volume lines per region at most, with an eye walked "
                                             "through the portals per 8 lines (0: until a doubling adds under 0.1% "
                                             "of the bits, up to 8192); each doubling is a point")
        ->capture_default_str();
    cmd->add_option("--seed", o->seed, "Seed of the reference and the cameras")->capture_default_str();
    cmd->add_option("--cameras", o->cameras, "Seeded cameras for popping and overdraw (0: no walk)")
        ->capture_default_str();
    cmd->add_option("--size", o->size, "Size of each camera's ID buffer")->capture_default_str();
    cmd->add_option("--sky", o->sky, "Portals and sight lines at sky leaves: sky-to-sky, all, none")
        ->check(CLI::IsMember({"sky-to-sky", "all", "none"}))
        ->capture_default_str();
    cmd->add_option("--threads", o->threads, "Worker threads (0 = all cores)")->check(threads_validator())
        ->capture_default_str();
    cmd->add_option("--csv", o->csv, "Write one CSV row per method and parameter");
    cmd->add_option("--json", o->json, "Write the results as JSON");
    cmd->add_option("--chart", o->chart, "Write the speed-vs-accuracy chart: .png, .svg or .pdf, by the extension")
        ->check(CLI::Validator(
            [](std::string& path) {
                try {
                    ui::chart::chart_format_for(path);
                } catch (const std::invalid_argument& e) {
                    return std::string(e.what());
                }
                return std::string();
            },
            "PATH.png|.svg|.pdf"));
    cmd->callback([o, &exit_code] {
        const SigintScope sigint;
        exit_code = run_compare_command(*o);
    });
}

} // namespace pvs::app
