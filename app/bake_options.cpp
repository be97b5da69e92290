#include "app/bake_options.h"

#include "app/argument_parsers.h"
#include "app/bake_input.h"
#include "app/bake_shard.h"

#include <filesystem>

namespace pvs::app {

namespace {

std::string check_shard_options(const BakeOptions& o)
{
    if (o.shard.empty())
        return {};
    if (!parse_shard_spec(o.shard))
        return "--shard must be K/N with 0 <= K < N (shard 0/4 is the first of four), not '" + o.shard + "'";
    const VisMethod* m = find_vis_method(o.method);
    if (m && !m->source_costs)
        return "--shard: " + o.method + " cannot be split into shards yet: " + std::string(m->shard_refusal) +
               " (raster and reference can)";
    if (o.method == "reference" && (!o.per_source || o.samples == 0))
        return "--shard: the reference splits with --per-source and --samples N only: by default " +
               std::string(m->shard_refusal);
    if (o.in_place || !o.apply_edits.empty() || !o.prt_out.empty())
        return "--shard writes a part file only: --in-place, --apply-edits and --write-prt belong to the whole bake "
               "(give --apply-edits to `pvscope merge`)";
    if (o.device == "auto")
        return "--shard with --device auto: name the device (cpu or gpu), so that every shard draws alike and the "
               "merge is the one-machine bake's bytes";
    if (lowercase_extension(o.output) != ".pvsp")
        return "--shard: the output is a part file, so -o must end in .pvsp, not '" + o.output + "'";
    return {};
}

} // namespace

bool bakes_on_portals(const std::string& method) { return method == "portal-fast" || method == "portal-full"; }

std::string check_bake_options(const BakeOptions& o)
{
    if (o.input.empty())
        return "no input file";
    if (o.output.empty() && !o.in_place)
        return "no output file: give -o OUT (.bsp for a Quake map, .s3d for an EverQuest zone, .gwa/.wad for a Doom "
               "map), or --in-place for a Doom map";
    if (o.in_place && !o.output.empty())
        return "--in-place writes into the Doom map's own GL file: give it or -o, not both";
    if (const VisMethod* m = find_vis_method(o.method); !m || !m->bakes)
        return "--method must be portal-fast, portal-full, clustered, reference or raster, not '" + o.method + "'";
    if (o.method == "raster" && (o.resolution < 1 || o.resolution > 4096))
        return "--resolution must be 1..4096, not " + std::to_string(o.resolution);
    if (o.device != "cpu" && o.device != "gpu" && o.device != "auto")
        return "--device must be cpu, gpu or auto, not '" + o.device + "'";
    if (o.device != "cpu" && o.method != "raster")
        return "--device " + o.device + ": only the raster method draws on a GPU";
    if (o.lattice != "open" && o.lattice != "centred" && o.lattice != "hateengine")
        return "--lattice must be open, centred or hateengine, not '" + o.lattice + "'";
    if (!(o.step >= 0.0f) || !(o.cell >= 0.0f) || !(o.grid_size > 0.0f))
        return "--step and --cell must be 0 or more and --grid-size more than 0";
    if (!bakes_on_portals(o.method) && !o.prt_in.empty())
        return "--prt: " + o.method + " does not read portals (it builds what it needs from the tree)";
    if (!bakes_on_portals(o.method) && !o.prt_out.empty())
        return "--write-prt: " + o.method + " uses no portals to write (portal-fast and portal-full do)";
    if (!bakes_on_portals(o.method) && o.clusters != "none")
        return "--clusters: only for portal-fast and portal-full (clustered always bakes over clusters)";
    if (o.level < 0 || o.level > 4)
        return "--level must be 0..4, not " + std::to_string(o.level);
    if (o.sky != "sky-to-sky" && o.sky != "all" && o.sky != "none")
        return "--sky must be sky-to-sky, all or none, not '" + o.sky + "'";
    if (o.phs_rule != "quake2" && o.phs_rule != "ericw")
        return "--phs-rule must be quake2 or ericw, not '" + o.phs_rule + "'";
    if (o.clusters != "none" && o.clusters != "auto")
        return "--clusters must be none or auto, not '" + o.clusters + "'";
    if (!o.prt_out.empty() && o.prt_out == o.output)
        return "--write-prt and -o name the same file";
    for (const auto& [option, file] :
         {std::pair{"-o", &o.output}, {"--report", &o.report}, {"--write-prt", &o.prt_out}})
        if (const std::string folder = missing_folder(*file); !folder.empty())
            return std::string(option) + " " + *file + ": no folder " + folder + " to write it in";
    if (o.per_source && (o.method != "reference" || o.samples == 0))
        return "--per-source is for --method reference with --samples N (a fixed budget of lines per region)";
    if (const std::string problem = check_shard_options(o); !problem.empty())
        return problem;
    std::error_code ec;
    if (!o.apply_edits.empty() && !std::filesystem::is_regular_file(o.apply_edits, ec))
        return "--apply-edits " + o.apply_edits + ": no such file";
    return {};
}

MethodSettings bake_method_settings(const BakeOptions& o)
{
    MethodSettings settings;
    settings.sky = sky_mode_from_name(o.sky);
    settings.threads = o.threads;
    settings.level = o.level;
    settings.passages = o.passages;
    settings.target_checks = o.target_checks;
    settings.samples = o.samples;
    settings.seed = o.seed;
    settings.reference_per_source = o.per_source;
    settings.raster_resolution = o.resolution;
    settings.raster_engine = o.raster_engine == "rasteriser" ? RasterEngine::Rasteriser : RasterEngine::Rays;
    settings.raster_device = o.device == "gpu"    ? RasterDevice::Gpu
                             : o.device == "auto" ? RasterDevice::Auto
                                                  : RasterDevice::Cpu;
    settings.raster_gpu_batch = o.gpu_batch;
    settings.raster_points = o.points;
    settings.raster_step = o.step;
    settings.raster_lattice = o.lattice == "hateengine" ? Lattice::HateEngine
                              : o.lattice == "centred"  ? Lattice::Centred
                                                        : Lattice::OpenRandom;
    settings.cull_back_faces = o.cull_back_faces;
    settings.heights = o.heights;
    return settings;
}

std::string missing_folder(const std::string& path)
{
    if (path.empty() || path == "-")
        return {};
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    std::error_code ec;
    return folder.empty() || std::filesystem::is_directory(folder, ec) ? std::string() : folder.string();
}

} // namespace pvs::app
