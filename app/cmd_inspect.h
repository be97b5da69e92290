// `pvscope inspect [FILE] [--screenshot out.png --frames N] [--size WxH] [--camera x,y,z,yaw,pitch]
// [--cull MODE]`: the inspector window
// (ui/gui). `pvscope` with no subcommand opens it too: on FILE when one is given, else on the
// built-in demo zone. Linked into the pvscope executable only (not pvscope_cli), because it
// brings GLFW, OpenGL and Dear ImGui.
#pragma once

#include <CLI/App.hpp>

#include <string>

namespace pvs::app {

// Registers the subcommand; `exit_code` receives the command's result when it runs.
void register_inspect_command(CLI::App& app, int& exit_code);

// The inspector on `path` (empty: the demo zone) in a 1280x800 window, until it is closed.
int run_inspect(const std::string& path);

} // namespace pvs::app
