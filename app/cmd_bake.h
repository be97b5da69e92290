// `pvscope bake FILE --method M [options] -o OUT`: compute a PVS with one of the registry's baking
// methods (visibility/methods/vis_method.h: portal-fast, portal-full, clustered, terrain,
// reference, raster) and write the zone back in its own format. Every method runs through the
// registry; this command parses, loads, writes and reports.
//
//  - Input: a Quake BSP 29 / BSP2 / 2PSB or Quake 2 IBSP 38 map, an EverQuest .s3d, a Doom WAD
//    with GL nodes (--map, --gwa) or an OBJ level with its .hepvs, recognised from the bytes
//    (bake_input.h). The portal methods' portals come from --prt (PRT1, PRT2 or PRT1-AM, whose
//    leaf k must be region k) or else are built from the zone's BSP tree. A sibling .prt next
//    to a .bsp is NOT used unless named with --prt, so the source is always explicit.
//  - Output: the input's format only (bake_output.h). OUT must end in the input format's
//    extension, otherwise the command refuses and says so (use `pvscope convert` after).
//  - --write-prt writes the portals the bake used as PRT1 (leaf k = region k), or as PRT2 (the
//    cluster portals and the cluster map) when the bake ran over clusters. --prt reads PRT2 and
//    PRT1-AM too: the bake then runs over the file's clusters (whatever --clusters says).
//  - --clusters auto bakes over box clusters (visibility/portal/box_clusters.h) when the zone's
//    regions are boxes (generated zones): faster and lighter on big zones, a looser PVS. A Quake
//    map, or a zone whose regions are not boxes, is baked per region and a note says so.
//  - --report writes a JSON report (report/bake_report_json.h, fields in docs/baking.md; "-" =
//    stdout).
//  - Progress on stderr: a bar on a terminal, "bake: 40%" lines otherwise. Ctrl-C (SIGINT)
//    cancels: nothing is written and the exit code is 130.
// Exit codes: 0 done, 1 a file could not be read or written, 2 bad arguments, 130 cancelled.
#pragma once

#include "app/bake_options.h"

#include <CLI/App.hpp>

#include <atomic>
#include <cstdio>
#include <string>

namespace pvs::app {

// Runs the bake; messages and progress go to `err`. `cancel`, when given, is polled while the
// bake runs (the command passes its SIGINT flag): true cancels. Returns the exit code.
int run_bake(const BakeOptions& options, std::FILE* err = stderr, const std::atomic<bool>* cancel = nullptr);

// Registers the subcommand; `exit_code` receives the command's result when it runs. While the
// command runs, SIGINT sets a flag that cancels the bake (the previous handler is restored).
void register_bake_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
