// pvscope-inspector: the inspector window (ui/gui). `pvscope` starts it (inspector_launch.h)
// with its own arguments -- `inspect [options]`, `FILE`, or nothing -- so this parses the same
// command line, with the same options (cmd_inspect.h), and shows the same help.
#include "app/argument_parsers.h"
#include "app/cmd_inspect.h"
#include "app/process_memory.h"
#include "ui/gui/inspector_app.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <string>
#include <vector>

namespace {

// The command's arguments (already checked by its validators) as the inspector's options.
pvs::gui::InspectorOptions inspector_options(const pvs::app::InspectArguments& a)
{
    using namespace pvs;
    const auto size = app::parse_size_argument(a.size); // the validator accepted it
    gui::InspectorOptions options;
    options.zone_path = a.path;
    options.zone_load = a.load;
    options.screenshot = a.screenshot;
    options.frames = a.frames;
    options.width = (*size)[0];
    options.height = (*size)[1];
    if (!a.camera.empty())
        options.camera = app::parse_camera_argument(a.camera);
    options.cull_mode = parse_cull_mode(a.cull).value_or(CullMode::PvsFrustum);
    options.far_clip = a.far;
    options.report_fps = a.report_fps;
    options.cameras = a.cameras;
    options.camera_seed = a.seed;
    options.overlays = app::parse_overlays(a.overlays).value_or(ui::OverlaySettings{});
    options.overlays.hidden_lines = a.hidden_lines == "hidden"  ? ui::HiddenLines::Hidden
                                    : a.hidden_lines == "shown" ? ui::HiddenLines::Shown
                                                                : ui::HiddenLines::Faint;
    options.pick_centre = a.pick_centre;
    options.bsp_node = a.bsp_node;
    options.memory_probe = app::peak_memory_probe();
    if (!a.why.empty()) {
        const size_t comma = a.why.find(',');
        options.why = std::array<uint32_t, 2>{uint32_t(std::stoul(a.why.substr(0, comma))),
                                              uint32_t(std::stoul(a.why.substr(comma + 1)))};
    }
    options.compare = a.compare;
    options.stability_case = a.stability_case;
    if (!a.bake.empty()) {
        gui::BakeRequest request;
        request.method = a.bake;
        options.bake = request;
    }
    return options;
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"pvscope inspector — the window of `pvscope inspect`", "pvscope"};
    app.require_subcommand(0, 1);
    int exit_code = 0;
    pvs::app::register_inspect_command(app, exit_code, [](const pvs::app::InspectArguments& arguments) {
        return pvs::gui::run_inspector(inspector_options(arguments));
    });
    std::string zone_path; // `pvscope FILE`: the inspector on FILE
    app.add_option("file", zone_path, "Zone file to open in the inspector when no subcommand is given");

    std::vector<std::string> arguments =
        pvs::app::with_implied_inspect(app, std::vector<std::string>(argv + 1, argv + argc));
    std::reverse(arguments.begin(), arguments.end()); // CLI11 parses a vector from its back
    try {
        app.parse(arguments);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    if (app.get_subcommands().empty()) {
        pvs::gui::InspectorOptions options;
        options.zone_path = zone_path;
        exit_code = pvs::gui::run_inspector(options);
    }
    return exit_code;
}
