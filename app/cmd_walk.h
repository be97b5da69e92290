// `pvscope walk FILE [--cameras N | --path regions|FILE] --csv out.csv`: culling speed and
// image-space accuracy over a reproducible set of cameras (seeded cameras inside regions looking
// anywhere, or a path that visits every region), one CSV row per camera and a summary.
#pragma once

#include <CLI/App.hpp>

namespace pvs::app {

void register_walk_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
