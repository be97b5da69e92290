// `pvscope render FILE --camera x,y,z,yaw,pitch -o out.png`: the zone as the culler leaves it,
// drawn headless with Irrlicht's software renderer (textured, region colours or face-id buffer).
#pragma once

#include <CLI/App.hpp>

#include <array>
#include <optional>
#include <string>

namespace pvs::app {

// Registers the subcommand; `exit_code` receives the command's result when it runs.
void register_render_command(CLI::App& app, int& exit_code);

// Argument parsers (exposed for tests): nullopt when the text is not exactly what is expected.
std::optional<std::array<float, 5>> parse_camera_argument(const std::string& text); // "x,y,z,yaw,pitch"
std::optional<std::array<uint32_t, 2>> parse_size_argument(const std::string& text); // "800x600", 1..8192 each

} // namespace pvs::app
