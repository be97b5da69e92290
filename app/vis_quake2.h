// `pvscope vis --phs-only` on a Quake 2 map (IBSP 38), as ericw's -phsonly: the map's own PVS kept
// and the PHS made again by --phs-rule, written over the map in place (replace_atomically: the map
// is whole before and after). --report writes what the map now holds per cluster
// (quake2_written_fields) and its rows against the map's old PVS. A Quake 2 bake (qbsp's portal
// file or --portals tree) goes through `bake`, as every other.
#pragma once

#include "app/vis_options.h"

#include <cstdint>
#include <cstdio>
#include <span>
#include <string>

namespace pvs::app {

// `bytes` are the map's; returns the exit code (0, 1 the map has no PVS, 2 bad arguments).
int quake2_phs_only(const VisCommandOptions& options, const std::string& map, std::span<const uint8_t> bytes,
                    std::FILE* err);

} // namespace pvs::app
