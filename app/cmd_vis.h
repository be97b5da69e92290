// `pvscope vis [OPTIONS] MAP[.bsp]`: a drop-in for Quake's vis in a build script (qbsp -> vis ->
// light). Reads MAP.prt beside the map (PRT1, PRT2 with detail clusters, PRT1-AM), bakes the PVS,
// computes the leaves' ambient sound levels from it, and writes both into MAP.bsp in place, as
// vis does: into a temporary file in the map's folder, renamed over the map only when complete,
// so a crash, Ctrl-C or a full disk never leaves a half-written map. BSP 29, BSP2 and 2PSB.
//
// ericw vis's spellings are accepted with one dash or two: -threads N, -fast, -level N,
// -noambient, -noambientsky, -noambientwater, -noambientslime, -noambientlava, -nostate (no
// effect: pvscope keeps no state file); -visdist N is refused as not supported. pvscope's own:
// --method portal-full|portal-fast, --portals file|tree (tree: portals built from the
// BSP tree per leaf, detail brushes blocking sight, when there is no .prt or to ignore it),
// --ambient-only (keep the map's PVS, compute only the ambient levels from it), --report R.json.
//
// A Quake 2 map (IBSP 38) gets Quake 2's vis instead (wld/quake2/quake2_vis.h): the PVS over its
// clusters from the PRT1 beside it and the PHS made from it, both into the visibility lump;
// -phsonly / --phs-only keeps the PVS and makes the PHS again; --phs-rule quake2 (default: the
// engine's, id's qvis3) or ericw (what ericw-tools vis writes, byte for byte); --portals tree
// bakes per leaf from the map's tree and writes the leaves' rows ORed per cluster (as bake). No
// ambient sounds there (Quake 2 has none in the map).
// Unknown options are an error and nothing is written.
// Exit codes: 0 done, 1 a file could not be read or written, 2 bad arguments, 130 cancelled.
#pragma once

#include "app/vis_options.h"

#include <CLI/App.hpp>

#include <atomic>
#include <cstdio>
#include <string>
#include <vector>

namespace pvs::app {

int run_vis_command(const VisCommandOptions& options, std::FILE* err, const std::atomic<bool>* cancel = nullptr);

void register_vis_command(CLI::App& app, int& exit_code);

// vis's one-dash long options (-threads, -noambientsky) as two-dash ones, for the arguments after
// a `vis` subcommand; every other argument as it was.
std::vector<std::string> normalize_vis_arguments(const std::vector<std::string>& arguments);

} // namespace pvs::app
