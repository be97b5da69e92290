#include "app/cmd_stability.h"

#include "app/argument_parsers.h"
#include "app/error_path.h"
#include "app/exit_codes.h"
#include "app/output_files.h"
#include "app/cli_validators.h"
#include "app/progress_bar.h"
#include "app/sigint_scope.h"
#include "app/zone_load_args.h"
#include "visibility/eval/stability.h"
#include "visibility/file_error.h"
#include "wld/common/read_file.h"
#include "gen/case_table.h"
#include "gen/stability_cases.h"
#include "wld/zone_file.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <memory>
#include <sstream>

namespace pvs::app {

namespace {

nlohmann::json json_case_rows(const gen::CaseTable& table)
{
    nlohmann::json rows = nlohmann::json::array();
    for (const gen::CaseTableRow& r : table.rows)
        rows.push_back({{"case", r.case_name},
                        {"method", r.method},
                        {"params", r.params},
                        {"bound", bound_name(r.bound)},
                        {"regions", r.regions},
                        {"truth_bits", r.truth_bits},
                        {"bits", r.bits},
                        {"missing_bits", r.missing_bits},
                        {"excess_bits", r.excess_bits},
                        {"broken", r.broken()},
                        {"seconds", r.seconds}});
    return rows;
}

std::string csv_case_text(const gen::CaseTable& table)
{
    std::ostringstream out;
    out << "case,method,params,bound,regions,truth_bits,bits,missing_bits,excess_bits,broken,seconds\n";
    for (const gen::CaseTableRow& r : table.rows)
        out << r.case_name << ',' << r.method << ',' << r.params << ',' << bound_name(r.bound) << ',' << r.regions
            << ',' << r.truth_bits << ',' << r.bits << ',' << r.missing_bits << ',' << r.excess_bits << ','
            << (r.broken() ? "true" : "false") << ',' << r.seconds << '\n';
    return out.str();
}

void print_case_table(std::FILE* out, const gen::CaseTable& table)
{
    std::fprintf(out, "%-14s %-12s %8s %8s %8s %8s %8s %8s\n", "case", "method", "regions", "truth", "bits",
                 "missing", "excess", "s");
    for (const gen::CaseTableRow& r : table.rows)
        std::fprintf(out, "%-14s %-12s %8u %8llu %8llu %8llu %8llu %8.3f%s\n", r.case_name.c_str(), r.method.c_str(),
                     r.regions, static_cast<unsigned long long>(r.truth_bits), static_cast<unsigned long long>(r.bits),
                     static_cast<unsigned long long>(r.missing_bits), static_cast<unsigned long long>(r.excess_bits),
                     r.seconds, r.broken() ? "  BROKEN: breaks its bound" : "");
    std::fprintf(out, "missing = truth bits the method lacks (popping); excess = bits beyond the truth (overdraw). "
                      "The truth is known by construction (pvscope gen --case NAME shows a case)\n");
}

int run_cases(const StabilityCommandOptions& o, std::FILE* out, std::FILE* err)
{
    gen::CaseTableOptions options;
    if (!o.methods.empty())
        options.methods = split_comma_list(o.methods);
    if (o.cases != "all")
        options.cases = split_comma_list(o.cases);
    options.reference_samples = o.samples;
    options.threads = o.threads;
    StagedProgress progress(err, &SigintScope::interrupted());
    options.progress = std::ref(progress);
    gen::CaseTable table;
    try {
        table = gen::run_case_table(options);
    } catch (const std::invalid_argument& e) {
        progress.finish();
        std::fprintf(err, "pvscope: error: %s\n", e.what());
        return kExitBadArguments;
    }
    progress.finish();
    if (table.cancelled) {
        std::fprintf(err, "pvscope: stability cancelled: nothing was written\n");
        return kExitCancelled;
    }
    print_case_table(out, table);
    if (!o.json.empty())
        write_text_file(o.json, nlohmann::json{{"cases", o.cases},
                                          {"reference", {{"samples", o.samples}}},
                                          {"rows", json_case_rows(table)}}
                                   .dump(2) +
                               "\n");
    if (!o.csv.empty())
        write_text_file(o.csv, csv_case_text(table));
    return 0;
}

nlohmann::json json_rows(const StabilityResult& result)
{
    nlohmann::json rows = nlohmann::json::array();
    for (const StabilityRow& r : result.rows)
        rows.push_back({{"method", r.method},
                        {"params", r.params},
                        {"transform", r.transform},
                        {"exact", r.exact},
                        {"changed_bits", r.changed_bits()},
                        {"gained_bits", r.gained_bits},
                        {"lost_bits", r.lost_bits},
                        {"changed_rows", r.changed_rows},
                        {"missing_bits", r.missing_bits},
                        {"seconds", r.seconds}});
    return rows;
}

std::string csv_text(const StabilityResult& result)
{
    std::ostringstream out;
    out << "method,params,transform,exact,changed_bits,gained_bits,lost_bits,changed_rows,missing_bits,seconds\n";
    for (const StabilityRow& r : result.rows)
        out << r.method << ',' << r.params << ',' << r.transform << ',' << (r.exact ? "true" : "false") << ','
            << r.changed_bits() << ',' << r.gained_bits << ',' << r.lost_bits << ',' << r.changed_rows << ','
            << r.missing_bits << ',' << r.seconds << '\n';
    return out.str();
}

void print_table(std::FILE* out, const StabilityResult& result)
{
    std::fprintf(out, "%-12s %-16s %6s %10s %10s %10s %8s %10s %8s\n", "method", "transform", "exact", "changed",
                 "gained", "lost", "rows", "missing", "s");
    for (const StabilityRow& r : result.rows)
        std::fprintf(out, "%-12s %-16s %6s %10llu %10llu %10llu %8u %10llu %8.2f\n", r.method.c_str(),
                     r.transform.c_str(), r.exact ? "yes" : "no", static_cast<unsigned long long>(r.changed_bits()),
                     static_cast<unsigned long long>(r.gained_bits), static_cast<unsigned long long>(r.lost_bits),
                     r.changed_rows, static_cast<unsigned long long>(r.missing_bits), r.seconds);
    std::fprintf(out, "changed = bits that differ from the method's own bake of the untransformed zone; missing = "
                      "bits of the untransformed zone's reference (%llu bits) the transformed bake lacks\n",
                 static_cast<unsigned long long>(result.reference_bits));
}

int run_checked(const StabilityCommandOptions& o, std::FILE* out, std::FILE* err)
{
    StabilityOptions options;
    if (!o.methods.empty())
        options.methods = split_comma_list(o.methods);
    for (const std::string& name : options.methods)
        if (const VisMethod* m = find_vis_method(name); !m || !m->bakes) {
            std::fprintf(err, "pvscope: error: --methods: '%s' is not a method that bakes (%s)\n", name.c_str(),
                         baking_method_names().c_str());
            return kExitBadArguments;
        }
    options.reference_samples = o.samples;
    options.sky = sky_mode_from_name(o.sky);
    options.threads = o.threads;
    const Zone zone = load_zone(o.input, o.load);
    StagedProgress progress(err, &SigintScope::interrupted());
    options.progress = std::ref(progress);
    const StabilityResult result = run_stability(zone, options);
    progress.finish();
    if (result.cancelled) {
        std::fprintf(err, "pvscope: stability cancelled: nothing was written\n");
        return kExitCancelled;
    }
    print_table(out, result);
    if (!o.json.empty())
        write_text_file(o.json, nlohmann::json{{"input", o.input},
                                          {"sky", o.sky},
                                          {"reference", {{"samples", o.samples}, {"bits", result.reference_bits}}},
                                          {"rows", json_rows(result)}}
                                   .dump(2) +
                               "\n");
    if (!o.csv.empty())
        write_text_file(o.csv, csv_text(result));
    return 0;
}

} // namespace

int run_stability_command(const StabilityCommandOptions& options, std::FILE* out, std::FILE* err)
{
    if (options.input.empty() == options.cases.empty()) {
        std::fprintf(err, "pvscope: error: stability needs a zone file or --cases (not both)\n");
        return kExitBadArguments;
    }
    if (!options.cases.empty())
        return run_reporting_errors("--cases", err, [&] { return run_cases(options, out, err); });
    return run_reporting_errors(options.input, err, [&] { return run_checked(options, out, err); });
}

void register_stability_command(CLI::App& app, int& exit_code)
{
    auto o = std::make_shared<StabilityCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "stability", "Bake each method on the zone as given and under transforms that change nothing a player could "
                     "see (translations by 2^k, quarter turns, mirror, 1e-3 jitter): bits changed, and bits missing "
                     "against the reference of the untransformed zone; or, with --cases, each method on crafted zones whose "
                     "truth is known");
    cmd->add_option("file", o->input, "Zone file")->check(CLI::ExistingFile);
    add_zone_load_options(cmd, o->load);
    std::string case_list;
    for (std::string_view name : gen::stability_case_names())
        case_list += (case_list.empty() ? "" : ", ") + std::string(name);
    cmd->add_option("--cases", o->cases, "Instead of a file: 'all' or comma-separated crafted cases with a known "
                                         "truth (" + case_list + "); missing and excess bits per method and case");
    cmd->add_option("--methods", o->methods, "Comma-separated methods that bake (" + baking_method_names() +
                                             "; default: portal-fast, portal-full, clustered, reference, and raster "
                                             "with --cases)");
    cmd->add_option("--samples", o->samples, "Reference: sight lines per region (the untransformed zone's reference "
                                             "and the reference method's bakes)")
        ->capture_default_str();
    cmd->add_option("--sky", o->sky, "Portals and sight lines at sky leaves: sky-to-sky, all, none")
        ->check(CLI::IsMember({"sky-to-sky", "all", "none"}))
        ->capture_default_str();
    cmd->add_option("--threads", o->threads, "Worker threads (0 = all cores)")->check(threads_validator())
        ->capture_default_str();
    cmd->add_option("--json", o->json, "Write the rows as JSON");
    cmd->add_option("--csv", o->csv, "Write the rows as CSV");
    cmd->callback([o, &exit_code] {
        const SigintScope sigint;
        exit_code = run_stability_command(*o);
    });
}

} // namespace pvs::app
