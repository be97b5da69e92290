// `pvscope bake FILE --method portal-fast|portal-full|clustered|reference [--level L] [--samples N] [--seed S] [--threads N] [--sky MODE]
//  [--clusters none|auto] [--passages B] [--target-checks B] [--prt IN.prt] [--write-prt OUT.prt]
//  [--report REPORT.json] -o OUT`: compute a PVS with one of the registry's bakers
// (visibility/methods/vis_method.h) and write the zone back in its own format. portal-fast and
// portal-full take the options below; clustered and reference run as the registry defines them
// (no --prt / --clusters; the reference reads --samples and --seed and warns that a lower bound
// can pop).
//
//  - Input: a Quake BSP 29 or an EverQuest .s3d, recognised from the bytes. Portals come from
//    --prt (PRT1, PRT2 or PRT1-AM, whose leaf k must be region k: the file must name exactly the
//    zone's region count) or else are built from the zone's BSP tree (build_zone_portals). A sibling .prt
//    next to a .bsp is NOT used unless named with --prt, so the source is always explicit.
//  - Output: the input's format only. A .bsp gets a new VISIBILITY lump and leaf visofs, all
//    other lumps byte-identical (wld/quake/bsp29_vis_writer.h); an .s3d is re-written with the
//    baked rows as 0x22 VISLISTs (write_zone). OUT must end in the input format's extension
//    (.bsp / .s3d), otherwise the command refuses and says so (use `pvscope convert` after).
//  - --write-prt writes the portals the bake used as PRT1 (leaf k = region k), or as PRT2 (the
//    cluster portals and the cluster map, §2.2) when the bake ran over clusters. --prt reads
//    PRT2 and PRT1-AM too: the bake then runs over the file's clusters (whatever --clusters says).
//  - --clusters auto bakes over clusters of regions (visibility/portal/cluster_vis.h) when the
//    zone's regions are boxes (regions_are_boxes: generated zones), grouped by
//    box_merge_clusters: much faster and lighter on big zones, a looser PVS (every region of a
//    cluster gets the cluster's row). A Quake map, or a zone whose regions are not boxes, is
//    baked per region and a note says so (a Quake map's PVS is per leaf). none (the default)
//    always bakes per region.
//  - --report writes a JSON report (fields documented in docs/baking.md; "-" = stdout).
//  - Progress on stderr: a bar on a terminal, "bake: 40%" lines otherwise. Ctrl-C (SIGINT)
//    cancels: nothing is written and the exit code is 130.
// Exit codes: 0 done, 1 a file could not be read or written, 2 bad arguments, 130 cancelled.
#pragma once

#include "wld/quake/ambient_sounds.h"

#include <CLI/App.hpp>

#include <atomic>
#include <cstdio>
#include <nlohmann/json_fwd.hpp>
#include <string>

namespace pvs::app {

struct BakeOptions {
    std::string input;
    std::string output;
    std::string output_name; // how messages and the report name the output when not `output` (vis: the map it replaces)
    std::string method = "portal-full"; // portal-fast | portal-full
    int level = 4;                      // portal-full's separator test level, 0..4
    unsigned threads = 0;               // 0 = all cores
    std::string sky = "sky-to-sky";     // sky-to-sky | all | none (PortalOptions::sky)
    std::string clusters = "none";      // none | auto (see above)
    bool passages = true;               // portal-full: prune the flow with passages (VisParams)
    bool target_checks = true;          // portal-full: target checks before re-entering a seen leaf (VisParams)
    std::string prt_in;                 // portals from this PRT1/PRT2/PRT1-AM file instead of the tree
    std::string prt_out;                // also write the portals used (PRT1, or PRT2 over clusters)
    std::string report;                 // JSON report path, "-" for stdout
    uint64_t samples = 0;               // reference: lines per region at most (0: until converged)
    uint64_t seed = 1;                  // reference and raster: sampling seed
    // raster: pixels per cube face side, points per region (region cells), lattice step in grid
    // units (grid cells; 0 = centre only), back faces drawn or not.
    uint32_t resolution = 64;
    uint32_t points = 16;
    float step = 0.0f;
    std::string lattice = "open"; // grid cells: open (random points in open space), centred, hateengine
    std::string raster_engine = "rays"; // rays (Embree packets) or rasteriser
    bool cull_back_faces = true;
    // OBJ levels: the view grid's cell in grid units (0: the .hepvs's grid, else 8) and the OBJ
    // units per grid unit; the input's .hepvs when not beside it.
    float cell = 0.0f;
    float grid_size = 16.0f;
    std::string hepvs;
    // Doom WADs: the map and its GL nodes (ZoneLoadOptions), floors and ceilings as built
    // blocking sight (MethodSettings::heights), REJECT rebuilt from the PVS, and writing into
    // the GL file itself (with glVIS's backup, .~gw / .~wa) instead of -o.
    std::string map;
    std::string gwa;
    bool heights = false;
    bool reject = false;
    bool in_place = false;
    // Quake maps: ambient sound levels computed from the new rows, as vis writes them (false: the
    // file's levels are kept).
    bool ambient = true;
    quake::AmbientOptions ambient_classes; // which texture classes count (vis's -noambient* switches)
    std::string phs_rule = "quake2"; // Quake 2 maps: the PHS written with the PVS, quake2 | ericw
    // A PVS edit list (wld/pvs_edit_list.h) applied to the bake before it is written: hand fixes
    // that survive a re-vis.
    std::string apply_edits;
};

// Runs the bake; messages and progress go to `err`. `cancel`, when given, is polled while the
// bake runs (the command passes its SIGINT flag): true cancels. Returns the exit code.
int run_bake(const BakeOptions& options, std::FILE* err = stderr, const std::atomic<bool>* cancel = nullptr);

// The folder a file is to be written into when it does not exist ("" when it does, for a bare
// name and for "-", stdout): checked before a bake, not after its minutes of work.
std::string missing_folder(const std::string& path);

// Writes a --report JSON to `path` ("-": standard output); throws when the file cannot be written.
void write_report(const std::string& path, const nlohmann::json& report);

// Registers the subcommand; `exit_code` receives the command's result when it runs. While the
// command runs, SIGINT sets a flag that cancels the bake (the previous handler is restored).
void register_bake_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
