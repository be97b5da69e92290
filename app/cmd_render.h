// `pvscope render FILE --camera x,y,z,yaw,pitch -o out.png`: the zone as the culler leaves it,
// drawn headless with Irrlicht's software renderer (textured, region colours, face-id buffer or
// textured tinted by region flags). `--cull-camera x,y,z,yaw,pitch` culls from that camera
// while drawing from --camera (the locked culling camera, ui::render_culled) and draws its view
// volume over the picture; the printed stats are then the culling camera's.
#pragma once

#include <CLI/App.hpp>

#include <array>
#include <optional>
#include <string>

namespace pvs::app {

// Registers the subcommand; `exit_code` receives the command's result when it runs.
void register_render_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
