// `pvscope gen --rooms N --seed S [--json]`: make a procedural demo zone and report on it.
// Writing it as an EverQuest .s3d comes with the WLD zone writer.
#pragma once

#include <CLI/App.hpp>

namespace pvs::app {

void register_gen_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
