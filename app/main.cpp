// pvscope: inspector and command-line tool for visibility culling in classic 3-D worlds.
// Each subcommand lives in its own cmd_*.cpp; this file only wires them together. The inspector
// window is the pvscope-inspector executable (inspector_main.cpp), which this one starts.
#include "app/cmd_bake.h"
#include "app/cmd_check.h"
#include "app/cmd_compare.h"
#include "app/cmd_convert.h"
#include "app/cmd_gen.h"
#include "app/cmd_info.h"
#include "app/cmd_inspect.h"
#include "app/cmd_merge.h"
#include "app/cmd_render.h"
#include "app/cmd_stability.h"
#include "app/cmd_stats.h"
#include "app/cmd_vis.h"
#include "app/cmd_walk.h"
#include "app/cmd_why.h"
#include "app/exit_codes.h"
#include "app/inspector_launch.h"
#include "app/process_memory.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
    CLI::App app{"pvscope — inspect, cull and bake potentially visible sets of EverQuest, Quake and Doom zones"};
    app.set_version_flag("--version", "pvscope 0.1.0");
    app.require_subcommand(0, 1);
    int exit_code = 0;
    pvs::app::register_info_command(app, exit_code);
    pvs::app::register_stats_command(app, exit_code);
    pvs::app::register_render_command(app, exit_code);
    pvs::app::register_gen_command(app, exit_code);
    pvs::app::register_walk_command(app, exit_code);
    pvs::app::register_convert_command(app, exit_code);
    pvs::app::register_bake_command(app, exit_code);
    pvs::app::register_merge_command(app, exit_code);
    pvs::app::register_compare_command(app, exit_code);
    pvs::app::register_stability_command(app, exit_code);
    pvs::app::register_check_command(app, exit_code);
    pvs::app::register_why_command(app, exit_code);
    pvs::app::register_vis_command(app, exit_code);
    // The inspector is another executable (inspector_launch.h): checked here, opened there.
    pvs::app::register_inspect_command(app, exit_code,
                                       [argv](const pvs::app::InspectArguments&) { return pvs::app::launch_inspector(argv); });
    // Process-wide heap tuning lives here, not in the libraries (process_memory.h): one malloc
    // arena unless asked otherwise; the option, when given, changes it as it is parsed, before
    // any subcommand runs.
    pvs::app::use_malloc_arenas(1);
    app.add_option_function<int>(
           "--malloc-arenas", [](const int& arenas) { pvs::app::use_malloc_arenas(arenas); },
           "glibc malloc arenas for the whole run (default 1: the bakes' threads then touch no heap pages of "
           "their own; 0: glibc's own limit). Give it before the subcommand")
        ->check(CLI::Range(0, 1024));
    std::string zone_path; // `pvscope FILE`: the inspector on FILE
    app.add_option("file", zone_path, "Zone file to open in the inspector when no subcommand is given");

    // `pvscope vis` takes vis's one-dash spellings (-threads 2 -noambientsky) as well.
    std::vector<std::string> arguments = pvs::app::with_implied_inspect(
        app, pvs::app::normalize_vis_arguments(std::vector<std::string>(argv + 1, argv + argc)));
    std::reverse(arguments.begin(), arguments.end()); // CLI11 parses a vector from its back
    try {
        app.parse(arguments);
    } catch (const CLI::ParseError& e) {
        // CLI11 prints the message (or the help) and gives its own codes (105, 109, ...): every
        // bad command line exits 2, as the docs and each command's own refusals do.
        return app.exit(e) == 0 ? 0 : pvs::app::kExitBadArguments;
    }
    if (app.get_subcommands().empty())
        exit_code = pvs::app::launch_inspector(argv);
    return exit_code;
}
