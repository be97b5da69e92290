// `pvscope walk FILE [--cameras N | --path regions|portals|FILE] [--region-cache D] --csv out.csv`: culling speed and
// image-space accuracy over a reproducible set of cameras (seeded cameras inside regions looking
// anywhere, a path that visits every region, or a player's walk through the portals), one CSV row
// per camera and a summary. --region-cache D culls from a stale camera -> region cache (walked
// again only after a move of D units, as an EverQuest client does) to measure the popping it causes.
#pragma once

#include <CLI/App.hpp>

namespace pvs::app {

void register_walk_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
