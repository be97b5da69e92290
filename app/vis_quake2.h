// `pvscope vis` on a Quake 2 map (IBSP 38) with its portal file (qbsp's PRT1 over the map's
// clusters, MAP.prt beside it), or --phs-only: the PVS over the clusters and the PHS, written
// over the map in place (replace_atomically: the map is whole before and after). --report
// writes the bake's figures, the work counters, the rows against the map's old PVS and under
// "clusters" what was written per cluster (quake2_written_fields).
#pragma once

#include "app/vis_options.h"

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>

namespace pvs::app {

// `bytes` are the map's; returns the exit code (0, 1 no portal file, 2 bad arguments, 130 cancelled).
int quake2_vis(const VisCommandOptions& options, const std::string& map, std::span<const uint8_t> bytes, std::FILE* err,
               const std::atomic<bool>* cancel);

} // namespace pvs::app
