#include "app/cmd_why.h"
#include "app/error_path.h"

#include "app/argument_parsers.h"
#include "app/cli_validators.h"
#include "app/cli_validators.h"
#include "app/progress_bar.h"
#include "app/pvs_source.h"
#include "app/zone_load_args.h"
#include "report/pair_explanation_json.h"
#include "visibility/eval/pair_explanation.h"
#include "visibility/file_error.h"
#include "wld/zone_file.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>

namespace pvs::app {

struct WhyCommandOptions {
    std::string path;
    uint32_t a = 0, b = 0;
    std::string pvs = "file";
    bool json = false;
    uint64_t budget = 200000;
    uint64_t seed = 1;
    int level = 4;
    bool heights = false;
    unsigned threads = 0;
    std::string sky = "sky-to-sky";
    bool no_chain = false;
    ZoneLoadOptions load;
};

namespace {

void print_point(const char* label, const glm::dvec3& p) { std::printf("  %-12s (%.3f, %.3f, %.3f)\n", label, p.x, p.y, p.z); }

void print_text(const Zone& zone, const std::string& pvs_name, const PairExplanation& e)
{
    if (e.grid)
        std::printf("%s: view cell %u -> object %u (PVS: %s)\n", zone.source.path.c_str(), e.a, e.b, pvs_name.c_str());
    else
        std::printf("%s: region %u -> region %u (PVS: %s)\n", zone.source.path.c_str(), e.a, e.b, pvs_name.c_str());
    std::printf("  %s\n\n", e.summary.c_str());
    std::printf("  in PVS       %s\n", e.has_pvs ? (e.in_pvs ? "yes" : "no") : "no PVS (everything drawn)");
    if (e.witness) {
        std::printf("  sight line   yes, found after %llu lines\n", static_cast<unsigned long long>(e.witness->tries));
        print_point("from", e.witness->from);
        print_point("to", e.witness->to);
        std::printf("  camera       --camera %s\n", camera_argument(*e.camera).c_str());
        std::printf("  crosses      %zu regions", e.witness_regions.size());
        if (e.flow_cut)
            std::printf("; portal-full's row of A lacks region %u, the %zu-th", e.witness_regions[*e.flow_cut],
                        *e.flow_cut + 1);
        std::printf("\n");
    } else {
        std::printf("  sight line   none found in %llu lines\n", static_cast<unsigned long long>(e.witness_tries));
    }
    if (e.grid)
        return; // no portal flow on a grid of cells
    const char* method = e.chain_2d ? "portal-full (2-D)" : "portal-full";
    if (!e.flow_run) {
        std::printf("  chain        not searched (--no-chain)\n");
        return;
    }
    if (!e.chain) {
        std::printf("  chain        %s %s\n", method, e.flow_holds ? "holds B (no chain recorded)" : "does not hold B");
        return;
    }
    std::printf("  %s chain, %zu portals: %u", method, e.chain->steps.size(), e.a);
    for (const ChainStep& s : e.chain->steps)
        std::printf(" -> %u", s.region);
    std::printf("\n\n  %4s %8s %8s %12s %12s %7s %10s\n", "step", "region", "portal", e.chain_2d ? "width" : "area",
                e.chain_2d ? "seen width" : "seen area", "kept", "separators");
    for (size_t k = 0; k < e.chain->steps.size(); ++k) {
        const ChainStep& s = e.chain->steps[k];
        std::printf("  %4zu %8u %8u %12.3f %12.3f %6.1f%% %10u\n", k + 1, s.region, s.portal, s.portal_size,
                    s.window_size, s.portal_size > 0 ? 100.0 * s.window_size / s.portal_size : 0.0, s.separators);
    }
}

int run_why(const WhyCommandOptions& o)
{
    return run_reporting_errors(o.path, stderr, [&] {
        const Zone zone = load_zone(o.path, o.load);
        // Explaining portal-full's own PVS: the flow run for the chain is that PVS (one bake, not two).
        const bool flow_is_the_pvs = o.pvs == "portal-full" && !zone.view_grid && !o.no_chain;
        const PvsSource source = flow_is_the_pvs ? PvsSource{} : make_pvs_source(zone, o.pvs);
        if ((o.pvs == "file" || o.pvs == "baked") && source.pvs == nullptr)
            throw std::invalid_argument(zone.source.path + " carries no PVS: name one with --pvs (" +
                                        vis_method_names() + ")");
        ExplainOptions options;
        options.flow.sky = sky_mode_from_name(o.sky);
        options.flow.level = o.level;
        options.flow.heights = o.heights;
        options.flow.threads = o.threads;
        options.witness_budget = o.budget;
        options.seed = o.seed;
        options.want_chain = !o.no_chain;
        options.explain_the_flow = flow_is_the_pvs;
        std::optional<ProgressBar> bar; // the portal flow's (a grid zone has none)
        if (!zone.view_grid && !o.no_chain) {
            bar.emplace(stderr, "why: portal-full");
            options.flow.progress = [&bar](double f) {
                bar->update(f);
                return true;
            };
        }
        const PairExplanation e = explain_pair(zone, source.pvs, o.a, o.b, options);
        if (bar)
            bar->finish();
        if (o.json)
            std::cout << pair_explanation_json(zone.source.path, o.pvs, e).dump(2) << "\n";
        else
            print_text(zone, o.pvs, e);
        return kExitOk;
    }, {}, kExitBadArguments); // a bad region id, a zone it cannot explain on, Embree failing: 2 (cmd_why.h)
}

} // namespace

void register_why_command(CLI::App& app, int& exit_code)
{
    auto o = std::make_shared<WhyCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "why", "Why region A's PVS row holds region B, or not: the bit, a sight line found for the pair (and a camera "
               "along it), portal-full's chain of portals from A to B, and a verdict (sees, overdraw, would pop)");
    cmd->add_option("file", o->path, "Zone file (.bsp, .s3d, .wad, or an .obj with its .hepvs grid)")->required();
    cmd->add_option("a", o->a, "Region A (the viewer), as `check` and the inspector number them; an OBJ level: a view cell")
        ->required();
    cmd->add_option("b", o->b, "Region B (the one seen or not); an OBJ level: an object")->required();
    cmd->add_option("--obj", o->load.obj, "A .hepvs's OBJ level (default: the .obj of the same name beside it)");
    cmd->add_option("--hepvs", o->load.hepvs, "An OBJ's .hepvs PVS (default: the .hepvs of the same name, if any)");
    cmd->add_option("--pvs", o->pvs, "The PVS to explain: file (the file's), or a method baked now (" +
                                         vis_method_names() + ")")
        ->check(CLI::IsMember(pvs_source_names()))
        ->capture_default_str();
    cmd->add_flag("--json", o->json, "Print the explanation as JSON (stable field names, for scripts)");
    cmd->add_option("--budget", o->budget, "Sight lines tried at most before \"none found\"")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--seed", o->seed, "Seed of the sight-line search")->capture_default_str();
    cmd->add_option("--level", o->level, "portal-full's separator test level, 0..4")
        ->check(CLI::Range(0, 4))
        ->capture_default_str();
    cmd->add_flag("--no-chain", o->no_chain,
                  "Skip portal-full's chain: the bit, the sight line and the verdict only (the chain needs a flow "
                  "over the whole zone: minutes on large open zones)");
    cmd->add_flag("--heights", o->heights, "Doom: floors and ceilings block sight (the 3-D flow), as bake --heights");
    cmd->add_option("--threads", o->threads, "Worker threads of the flow (0 = all cores)")
        ->check(threads_validator())
        ->capture_default_str();
    cmd->add_option("--sky", o->sky, "Portals and sight lines at sky leaves: sky-to-sky, all, none")
        ->check(CLI::IsMember({"sky-to-sky", "all", "none"}))
        ->capture_default_str();
    add_zone_load_options(cmd, o->load);
    cmd->callback([o, &exit_code] { exit_code = run_why(*o); });
}

} // namespace pvs::app
