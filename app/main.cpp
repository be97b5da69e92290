// pvscope: inspector and command-line tool for visibility culling in classic 3-D worlds.
// Each subcommand lives in its own cmd_*.cpp; this file only wires them together.
#include "app/cmd_convert.h"
#include "app/cmd_gen.h"
#include "app/cmd_info.h"
#include "app/cmd_render.h"
#include "app/cmd_walk.h"

#include <CLI/CLI.hpp>
#include <cstdio>

int main(int argc, char** argv)
{
    CLI::App app{"pvscope — inspect, cull and bake potentially visible sets of EverQuest, Quake and Doom zones"};
    app.set_version_flag("--version", "pvscope 0.1.0");
    app.require_subcommand(0, 1);
    int exit_code = 0;
    pvs::app::register_info_command(app, exit_code);
    pvs::app::register_render_command(app, exit_code);
    pvs::app::register_gen_command(app, exit_code);
    pvs::app::register_walk_command(app, exit_code);
    pvs::app::register_convert_command(app, exit_code);

    CLI11_PARSE(app, argc, argv);
    if (app.get_subcommands().empty()) {
        std::printf("%s\nThe inspector window is not built yet; use a subcommand, e.g. `pvscope info FILE.bsp`.\n",
                    app.help().c_str());
    }
    return exit_code;
}
