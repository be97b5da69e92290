#include "app/cli_validators.h"
#include "app/cmd_bake.h"
#include "app/sigint_scope.h"
#include "visibility/methods/vis_method.h"

// The whole CLI11 (not only App.hpp): its config and formatter classes are header-only, and a
// test that links this file without main.cpp needs their definitions here.
#include <CLI/CLI.hpp>

#include <memory>
#include <string>
#include <vector>

namespace pvs::app {

void register_bake_command(CLI::App& app, int& exit_code)
{
    auto o = std::make_shared<BakeOptions>();
    CLI::App* cmd = app.add_subcommand(
        "bake",
        "Compute a PVS (portal vis, clustered, the sampled reference, or raster cube maps) and write it back in "
        "the zone's own format (.bsp: new visdata, other lumps unchanged; .s3d: new VISLISTs; an OBJ level: "
        "a .hepvs). Ctrl-C cancels and writes nothing.");
    cmd->add_option("file", o->input, "Zone file (Quake .bsp, EverQuest .s3d, or an OBJ level / its .hepvs)")
        ->required();
    cmd->add_option("-o,--output", o->output,
                    "Output file, in the input's format (.bsp, .s3d; .hepvs for an OBJ; "
                    "a Doom map: a copy of its GL file, .gwa or .wad)");
    cmd->add_option("--map", o->map, "Doom WAD: the map to bake (E1M1, MAP10; default: the first)");
    cmd->add_option("--gwa", o->gwa, "Doom WAD: its GL nodes (default: the .gwa beside it, else the WAD's own)");
    cmd->add_flag("--heights", o->heights,
                  "Doom: floors and ceilings as built block sight (3-D portals; closed "
                  "doors and lifts count as built: only for maps whose sectors never move). "
                  "Default: 2-D, as glVIS");
    cmd->add_flag("--reject", o->reject, "Doom: also rebuild the map's REJECT from the PVS (as glVIS does)");
    cmd->add_flag(
        "!--no-ambient", o->ambient,
        "Quake: keep the map's ambient sound levels instead of computing them from the new PVS (as vis does)");
    cmd->add_option("--phs-rule", o->phs_rule,
                    "Quake 2: the PHS written with the PVS: quake2 (the engine's, as id's qvis3) or ericw (what "
                    "ericw-tools vis writes)")
        ->check(CLI::IsMember({"quake2", "ericw"}))
        ->capture_default_str();
    cmd->add_option("--apply-edits", o->apply_edits,
                    "Apply this PVS edit list (saved by the inspector) to the bake "
                    "before writing it: hand fixes that survive a re-vis")
        ->check(CLI::ExistingFile);
    cmd->add_flag("--in-place", o->in_place,
                  "Doom: write GL_PVS into the map's own GL file (.gwa or WAD), keeping "
                  "the old one as .~gw / .~wa, as glVIS does");
    cmd->add_option("--method", o->method,
                    "portal-fast (base vis only, loose), portal-full (clipped flow), "
                    "clustered (portal-full over clusters of regions), terrain (the ground as "
                    "the occluder: a horizon over the zone's heightfield, for open zones), "
                    "reference (sampled "
                    "sight lines: a lower bound, for judging other PVSs) or raster (cube "
                    "maps rendered from points in each cell, as HateEngine's baker)")
        ->check(CLI::IsMember(baking_method_choices()))
        ->capture_default_str();
    cmd->add_option("--level", o->level, "portal-full: separating-plane test level 0..4")
        ->check(CLI::Range(0, 4))
        ->capture_default_str();
    cmd->add_option("--threads", o->threads, "Worker threads (0 = all cores); the result does not depend on it")
        ->check(threads_validator())
        ->capture_default_str();
    cmd->add_option("--sky", o->sky,
                    "Portals at sky leaves when built from the tree: sky-to-sky (ericw's default), "
                    "all (-transsky), none (as id's shipped maps)")
        ->check(CLI::IsMember({"sky-to-sky", "all", "none"}))
        ->capture_default_str();
    cmd->add_option("--clusters", o->clusters,
                    "none: bake per region; auto: over box clusters when the regions "
                    "are boxes (generated zones; faster, looser), per leaf for Quake")
        ->check(CLI::IsMember({"none", "auto"}))
        ->capture_default_str();
    cmd->add_option("--passages", o->passages,
                    "portal-full: prune the flow with passages (true: about half the "
                    "time on Quake maps; false: faster on open generated zones); the "
                    "rows are the same")
        ->capture_default_str();
    cmd->add_option("--target-checks", o->target_checks,
                    "portal-full: before walking into a leaf already seen, "
                    "check that a leaf not yet seen is still reachable "
                    "(true: about a third faster on Quake maps)")
        ->capture_default_str();
    cmd->add_option("--samples", o->samples,
                    "reference: volume lines per region at most, with an eye walked "
                    "through the portals per 8 lines (0: double until a doubling adds "
                    "under 0.1% of the bits, up to 8192: e1m1 converges at 2048, about "
                    "20 s with 2 cores)")
        ->capture_default_str();
    cmd->add_flag("--per-source", o->per_source,
                  "reference with --samples N: each region's walks aim by what its own lines found (not every "
                  "region's), so its lines depend on it alone and the bake splits into shards (--shard); a few more "
                  "lines");
    cmd->add_option("--seed", o->seed, "reference, raster: the sampling seed (the same seed gives the same PVS)")
        ->capture_default_str();
    cmd->add_option("--resolution", o->resolution, "raster: pixels per cube face side")->capture_default_str();
    cmd->add_option("--engine", o->raster_engine,
                    "raster: how the six views are drawn: rays (a ray per pixel centre, Embree packets; faster) "
                    "or rasteriser (pvscope's CPU rasteriser; the same pixel centres)")
        ->check(CLI::IsMember({"rays", "rasteriser"}))
        ->capture_default_str();
    cmd->add_option("--device", o->device,
                    "raster: where the views are drawn: cpu, gpu (a headless OpenGL 4.5 context through EGL, no "
                    "display needed; Mesa's llvmpipe counts) or auto (the GPU when one answers, else the CPU; the "
                    "summary says which ran). GPU rows differ from the CPU's only where a triangle edge crosses a "
                    "pixel centre")
        ->check(CLI::IsMember({"cpu", "gpu", "auto"}))
        ->capture_default_str();
    cmd->add_option("--gpu-batch", o->gpu_batch,
                    "raster on the GPU: views drawn per compute pass (0: as many as fit in 256 MiB; smaller when "
                    "the GPU runs out of memory). Changes no bit");
    cmd->add_option("--points", o->points,
                    "raster: sample points in each region, or in the open space of each grid "
                    "cell (--lattice open)")
        ->capture_default_str();
    cmd->add_option("--lattice", o->lattice,
                    "raster over a grid: open (random points in the cell's open space), "
                    "centred (a lattice of --step) or hateengine (the baker's lattice, "
                    "points on the cell's far faces included)")
        ->check(CLI::IsMember({"open", "centred", "hateengine"}))
        ->capture_default_str();
    cmd->add_option("--step", o->step,
                    "raster, centred or hateengine lattice: step in grid units (HateEngine's -s; "
                    "1 with --cell 8 is its 1 + 8^3 points a cell); 0: each cell's centre only")
        ->capture_default_str();
    cmd->add_option("--back-faces", o->cull_back_faces,
                    "raster: cull faces seen from behind (true, as the "
                    "HateEngine baker) or draw them")
        ->capture_default_str();
    cmd->add_option("--cell", o->cell,
                    "OBJ level: view cells of this many grid units (0: the .hepvs's grid, "
                    "else 8)")
        ->capture_default_str();
    cmd->add_option("--grid-size", o->grid_size, "OBJ level: OBJ units per grid unit (HateEngine's -g)")
        ->capture_default_str();
    cmd->add_option("--hepvs", o->hepvs, "OBJ level: its .hepvs when not the one of the same name beside it");
    cmd->add_option("--prt", o->prt_in,
                    "Read the portals from this PRT1 file (leaf k = region k; PRT2 / PRT1-AM: "
                    "baked over the file's clusters) instead of building them from the BSP tree")
        ->check(CLI::ExistingFile);
    cmd->add_option("--write-prt", o->prt_out,
                    "Also write the portals the bake used to this file (PRT1; PRT2 when "
                    "baked over clusters)");
    cmd->add_option("--report", o->report,
                    "Write a JSON report (times, memory, portals, comparison with the "
                    "file's own PVS) to this file, '-' for stdout");
    cmd->add_option("--shard", o->shard,
                    "Bake only shard K of N (K/N, from 0/N) of the rows, for a job array: -o names a part file "
                    "(.pvsp) that `pvscope merge` joins with the others into the whole bake's file, byte for byte "
                    "(raster; reference with --per-source --samples N)");
    cmd->callback([o, &exit_code] {
        const SigintScope sigint;
        exit_code = run_bake(*o, stderr, &SigintScope::interrupted());
    });
}

} // namespace pvs::app
