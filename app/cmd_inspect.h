// `pvscope inspect [FILE] [--screenshot out.png --frames N] [--size WxH] [--camera x,y,z,yaw,pitch]
// [--cull MODE] ...`: the inspector window (ui/gui). `pvscope` with no subcommand opens it too: on
// FILE when one is given, else on the built-in demo zone.
//
// The command's options and their checks live here, free of any GUI library, so that both
// executables register the same command: `pvscope` (every command; it links no GUI, no
// Irrlicht, no Embree, so a bake or an `info` starts small) checks the arguments and hands the
// process over to `pvscope-inspector` (inspector_launch.h), which parses them again and opens
// the window (inspector_main.cpp).
#pragma once

#include "app/zone_load_args.h"
#include "render/zone_overlays.h"

#include <CLI/App.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pvs::app {

// The inspect command's arguments as given (checked by the command's validators).
struct InspectArguments {
    std::string path; // empty: the built-in demo zone
    ZoneLoadOptions load; // --map, --gwa (Doom WADs)
    std::string screenshot;
    int frames = 5;
    std::string size = "1280x800";
    std::string camera;
    std::string cull = "pvs+frustum";
    float far = 0.0f; // > 0: far clip and the culler's distance stage
    bool report_fps = false;
    uint32_t cameras = 0; // --report-fps over this many seeded cameras, one a frame
    uint64_t seed = 1;    // their seed
    std::string overlays = "zonelines,frustum,areaportals";
    bool pick_centre = false;
    int bsp_node = -1;
    std::string bake;
    bool compare = false;
    std::string stability_case;
    std::string hidden_lines = "faint";
    std::string why; // "A,B": explain the pair at start
};

// Registers the subcommand; when it runs, `exit_code` receives run(arguments).
void register_inspect_command(CLI::App& app, int& exit_code, std::function<int(const InspectArguments&)> run);

// `pvscope FILE [OPTIONS]` means `pvscope inspect FILE [OPTIONS]` (--map, --camera, ... then work
// in the short form too): `arguments` (argv after the program name) with "inspect" put in front
// when the first is neither an option nor one of `app`'s subcommands.
std::vector<std::string> with_implied_inspect(const CLI::App& app, std::vector<std::string> arguments);

// "membership,membership-boxes,planes,portals,bounds,zonelines,frustum,cell,areaportals" (any subset, or
// "none") -> the overlay toggles; nullopt for an unknown name.
std::optional<ui::OverlaySettings> parse_overlays(const std::string& text);

} // namespace pvs::app
