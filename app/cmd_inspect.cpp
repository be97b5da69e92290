// The inspect command's options (cmd_inspect.h); the window itself is inspector_main.cpp's.
#include "app/cmd_inspect.h"

#include "app/cli_validators.h"

#include <memory>
#include <sstream>
#include <string>

namespace pvs::app {

std::optional<ui::OverlaySettings> parse_overlays(const std::string& text)
{
    ui::OverlaySettings o;
    o.zone_lines = o.locked_frustum = o.view_cell = o.area_portals = false;
    if (text == "none")
        return o;
    std::stringstream list(text);
    std::string name;
    while (std::getline(list, name, ',')) {
        if (name == "membership")
            o.pvs_membership = true;
        else if (name == "membership-boxes")
            o.pvs_membership_boxes = true;
        else if (name == "planes")
            o.split_planes = true;
        else if (name == "portals")
            o.portals = true;
        else if (name == "bounds")
            o.region_bounds = true;
        else if (name == "zonelines")
            o.zone_lines = true;
        else if (name == "frustum")
            o.locked_frustum = true;
        else if (name == "cell")
            o.view_cell = true;
        else if (name == "areaportals")
            o.area_portals = true;
        else
            return std::nullopt;
    }
    return o;
}

std::vector<std::string> with_implied_inspect(const CLI::App& app, std::vector<std::string> arguments)
{
    if (arguments.empty() || arguments.front().empty() || arguments.front().front() == '-')
        return arguments;
    const auto named = app.get_subcommands([&](const CLI::App* sub) { return sub->check_name(arguments.front()); });
    if (named.empty())
        arguments.insert(arguments.begin(), "inspect");
    return arguments;
}

void register_inspect_command(CLI::App& app, int& exit_code, std::function<int(const InspectArguments&)> run)
{
    auto o = std::make_shared<InspectArguments>();
    CLI::App* cmd = app.add_subcommand("inspect", "Open the inspector window (the default when no subcommand is given)");
    cmd->add_option("file", o->path, "Zone file; the built-in demo zone when absent");
    add_zone_load_options(cmd, o->load);
    cmd->add_option("--screenshot", o->screenshot,
                    "Draw --frames frames, write the whole window to this PNG and exit (needs a display; "
                    "xvfb-run works)");
    cmd->add_option("--frames", o->frames, "Frames drawn before the screenshot")
        ->capture_default_str()
        ->check(CLI::Range(1, 100000));
    cmd->add_option("--size", o->size, "Window size WIDTHxHEIGHT")
        ->capture_default_str()
        ->check(size_validator());
    cmd->add_option("--camera", o->camera, "Start camera x,y,z,yaw,pitch (zone units, degrees; z up, yaw 0 = +x); "
                                           "default: a view down the longest open line from a large region")
        ->check(camera_validator());
    cmd->add_option("--cull", o->cull, "Culling stages at start")
        ->capture_default_str()
        ->check(CLI::IsMember({"none", "frustum", "pvs", "pvs+frustum"}));
    cmd->add_option("--far", o->far, "Far clip distance at start, zone units (EverQuest clips at the zone's far plane / fog distance): the view camera's far plane and the culler's distance stage. 0: none")
        ->capture_default_str()
        ->check(distance_validator(false));
    CLI::Option* report_fps =
        cmd->add_flag("--report-fps", o->report_fps,
                      "Draw 10 warm-up frames and --frames timed frames without vsync, print the frame times (mean, "
                      "median, p95, fps) and where they go (cull, picture, overlays, panels, GL, swap), and exit");
    cmd->add_option("--cameras", o->cameras,
                    "--report-fps: time one frame from each of N seeded cameras in the zone's open regions (as "
                    "`walk`), instead of --frames from one, and name the slowest")
        ->needs(report_fps)
        ->check(CLI::Range(1u, 100000u));
    cmd->add_option("--seed", o->seed, "--cameras: their seed")->needs(report_fps)->capture_default_str();
    cmd->add_option("--overlays", o->overlays,
                    "Overlays at start: a comma list of membership (tinted faces), membership-boxes, planes, portals, bounds, zonelines, frustum, cell, "
                    "areaportals (Quake 2); or none")
        ->capture_default_str()
        ->check(CLI::Validator(
            [](std::string& text) {
                return parse_overlays(text) ? std::string()
                                            : "expects a comma list of membership, membership-boxes, planes, portals, bounds, "
                                              "zonelines, frustum, cell, areaportals (or none), got '" + text + "'";
            },
            "LIST"));
    cmd->add_option("--hidden-lines", o->hidden_lines,
                    "Overlay lines behind the picture's walls: faint, hidden, or shown (no depth test)")
        ->capture_default_str()
        ->check(CLI::IsMember({"faint", "hidden", "shown"}));
    cmd->add_flag("--pick-centre", o->pick_centre, "Pick the face at the viewport's centre (as a click would)");
    cmd->add_option("--bsp-node", o->bsp_node, "Select this BSP node in the BSP panel (its plane is highlighted)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--bake", o->bake, "Bake a PVS at start with this method (on a background thread, one thread), as "
                                       "the Bake panel does")
        ->check(CLI::IsMember(baking_method_choices()));
    cmd->add_flag("--compare", o->compare, "Run the Compare panel's compare of every method at start, its window open");
    cmd->add_option("--case", o->stability_case,
                    "Open crafted stability case NAME[:METHOD] at its camera, culling with METHOD's PVS (default "
                    "portal-full), the Stability panel open (instead of a file; pvscope stability --cases lists them)");
    cmd->add_option("--why", o->why,
                    "A,B: explain why region A sees region B at start (as pvscope why): region A selected, its "
                    "Region panel showing the verdict and chain, the viewport drawing the sight line and the "
                    "numbered portal chain")
        ->check(CLI::Validator(
            [](std::string& text) {
                const size_t comma = text.find(',');
                const bool ok = comma != std::string::npos && comma > 0 && comma + 1 < text.size() &&
                                text.find_first_not_of("0123456789,") == std::string::npos &&
                                text.find(',', comma + 1) == std::string::npos;
                return ok ? std::string() : "expects two region ids A,B, got '" + text + "'";
            },
            "A,B"));
    cmd->callback([o, &exit_code, run] { exit_code = run(*o); });
}

} // namespace pvs::app
