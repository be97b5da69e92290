#include "app/cmd_stability.h"

#include "app/arguments.h"
#include "app/progress_bar.h"
#include "app/sigint_scope.h"
#include "visibility/eval/stability.h"
#include "visibility/file_error.h"
#include "wld/common/read_file.h"
#include "wld/zone_file.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <memory>
#include <sstream>

namespace pvs::app {

namespace {



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
    options.methods = split_comma_list(o.methods);
    for (const std::string& name : options.methods)
        if (const VisMethod* m = find_vis_method(name); !m || !m->bakes) {
            std::fprintf(err, "pvscope: error: --methods: '%s' is not a method that bakes (%s)\n", name.c_str(),
                         vis_method_names().c_str());
            return kExitBadArguments;
        }
    options.reference_samples = o.samples;
    options.sky = sky_mode_from_name(o.sky);
    options.threads = o.threads;
    const Zone zone = load_zone(o.input);
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
    return run_reporting_errors(options.input, err, [&] { return run_checked(options, out, err); });
}

void register_stability_command(CLI::App& app, int& exit_code)
{
    auto o = std::make_shared<StabilityCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "stability", "Bake each method on the zone as given and under transforms that change nothing a player could "
                     "see (translations by 2^k, quarter turns, mirror, 1e-3 jitter): bits changed, and bits missing "
                     "against the reference of the untransformed zone");
    cmd->add_option("file", o->input, "Zone file")->required()->check(CLI::ExistingFile);
    cmd->add_option("--methods", o->methods, "Comma-separated methods that bake: portal-fast, portal-full, clustered, "
                                             "reference")
        ->capture_default_str();
    cmd->add_option("--samples", o->samples, "Reference: sight lines per region (the untransformed zone's reference "
                                             "and the reference method's bakes)")
        ->capture_default_str();
    cmd->add_option("--sky", o->sky, "Portals and sight lines at sky leaves: sky-to-sky, all, none")
        ->check(CLI::IsMember({"sky-to-sky", "all", "none"}))
        ->capture_default_str();
    cmd->add_option("--threads", o->threads, "Worker threads (0 = all cores)")->capture_default_str();
    cmd->add_option("--json", o->json, "Write the rows as JSON");
    cmd->add_option("--csv", o->csv, "Write the rows as CSV");
    cmd->callback([o, &exit_code] {
        const SigintScope sigint;
        exit_code = run_stability_command(*o);
    });
}

} // namespace pvs::app
