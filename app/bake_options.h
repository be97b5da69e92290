// `bake`'s options as parsed, checked before anything is read (check_bake_options), and the
// method settings they give (bake_method_settings). The command's help is in cmd_bake.h.
#pragma once

#include "visibility/methods/vis_method.h"
#include "wld/quake/ambient_sounds.h"

#include <cstdint>
#include <string>

namespace pvs::app {

struct BakeOptions {
    std::string input;
    std::string output;
    std::string output_name; // how messages and the report name the output when not `output` (vis: the map it replaces)
    std::string method = "portal-full"; // a baking method of the registry (vis_method.h)
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
    bool per_source = false;            // reference with --samples: each region's lines its own (shardable)
    // raster: pixels per cube face side, points per region (region cells), lattice step in grid
    // units (grid cells; 0 = centre only), back faces drawn or not.
    uint32_t resolution = 64;
    uint32_t points = 16;
    float step = 0.0f;
    std::string lattice = "open";       // grid cells: open (random points in open space), centred, hateengine
    std::string raster_engine = "rays"; // rays (Embree packets) or rasteriser
    std::string device = "cpu";         // raster: cpu, gpu (headless OpenGL through EGL) or auto
    uint32_t gpu_batch = 0;             // raster on the GPU: views per compute pass (0: as many as fit)
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
    std::string phs_rule = "quake2";       // Quake 2 maps: the PHS written with the PVS, quake2 | ericw
    // A PVS edit list (wld/pvs_edit_list.h) applied to the bake before it is written: hand fixes
    // that survive a re-vis.
    std::string apply_edits;
    // "K/N": bake only shard K of N (bake_shard.h) and write its rows as a part file (.pvsp) for
    // `pvscope merge`; empty: the whole bake.
    std::string shard;
};

// The argument errors, each a sentence; empty when the options are usable. Output folders are
// checked here, before a bake's minutes of work.
std::string check_bake_options(const BakeOptions& options);

// The registry's settings for these options (threads, sky, level, samples, raster knobs, ...);
// portals, clusters and progress are the command's to add.
MethodSettings bake_method_settings(const BakeOptions& options);

// True for the methods that bake on portals (portal-fast, portal-full): --prt, --write-prt and
// --clusters are theirs.
bool bakes_on_portals(const std::string& method);

// The folder a file is to be written into when it does not exist ("" when it does, for a bare
// name and for "-", stdout): checked before a bake, not after its minutes of work.
std::string missing_folder(const std::string& path);

} // namespace pvs::app
