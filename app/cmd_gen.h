// `pvscope gen --rooms N --seed S [--no-bake] [--json] [-o zone.s3d|zone.obj]`: make a procedural demo
// zone (baked with portal-full unless --no-bake), report on it, and write it if asked.
#pragma once

#include <CLI/App.hpp>

namespace pvs::app {

void register_gen_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
