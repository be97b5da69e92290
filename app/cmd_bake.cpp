#include "app/cmd_bake.h"

#include "app/arguments.h"
#include "app/cli_validators.h"
#include "app/process_memory.h"
#include "app/progress_bar.h"
#include "app/sigint_scope.h"
#include "report/pvs_diff_json.h"
#include "report/report_fields_json.h"
#include "visibility/bit_row.h"
#include "visibility/eval/pvs_gap.h"
#include "visibility/file_error.h"
#include "visibility/methods/vis_method.h"
#include "visibility/methods/vis_report_fields.h"
#include "visibility/portal/box_clusters.h"
#include "visibility/portal/cluster_vis.h"
#include "visibility/portal/portal_vis.h"
#include "visibility/portal/portalize.h"
#include "wld/common/read_file.h"
#include "wld/convert.h"
#include "wld/doom/doom_specials.h"
#include "wld/doom/doom_zone.h"
#include "wld/doom/gl_pvs_writer.h"
#include "wld/eq/eq_zone_reader.h"
#include "wld/hepvs/hepvs_zone.h"
#include "wld/pvs_edit_list.h"
#include "wld/pvs_writeback.h"
#include "wld/quake/bsp29_reader.h"
#include "wld/quake/bsp29_vis_writer.h"
#include "wld/quake/prt_file.h"
#include "wld/quake2/ibsp38_file.h"
#include "wld/quake2/ibsp38_zone.h"
#include "wld/quake2/quake2_vis.h"
#include "wld/zone_file.h"

// The whole CLI11 (not only App.hpp): its config and formatter classes are header-only, and a
// test that links this file without main.cpp needs their definitions here.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>

namespace pvs::app {

namespace {

enum class InputFormat { QuakeBsp, Quake2Bsp, EqS3d, ObjHepvs, DoomWad };

struct Input {
    InputFormat format;
    Zone zone;
    // Doom: where the map and its GL group are, and each subsector's sector (for REJECT).
    doom::MapSource doom_source;
    std::vector<uint32_t> sector_of_subsector;
    uint32_t sector_count = 0;

    bool drawing_dropped = false; // mesh and pixels freed for the bake (drop_what_a_portal_bake_does_not_read)

    Input(InputFormat f, Zone z) : format(f), zone(std::move(z)) {}
};

// A Quake map's name says its variant (BSP 29, BSP2, 2PSB), as `info` does.
std::string format_name(const Input& in)
{
    const InputFormat f = in.format;
    if (f == InputFormat::QuakeBsp)
        return in.zone.source.version == "29" || in.zone.source.version.empty() ? "Quake BSP 29"
                                                                                 : "Quake " + in.zone.source.version;
    return f == InputFormat::Quake2Bsp ? "Quake 2 BSP (IBSP 38)"
           : f == InputFormat::EqS3d     ? "EverQuest S3D"
           : f == InputFormat::DoomWad ? "Doom WAD + GL nodes"
                                       : "OBJ + .hepvs";
}
std::string lowercase_extension(const std::string& path);

// The output's extension: the input's format, and for a Doom map the file holding its GL nodes.
std::string format_extension(const Input& in)
{
    if (in.format == InputFormat::DoomWad)
        return lowercase_extension(in.doom_source.gl_path);
    return in.format == InputFormat::QuakeBsp || in.format == InputFormat::Quake2Bsp ? ".bsp"
           : in.format == InputFormat::EqS3d                                           ? ".s3d"
                                                                                       : ".hepvs";
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string lowercase_extension(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// clustered, terrain, reference and raster run through the method registry; portal-fast and portal-full keep
// this command's own path (portal files in and out, box clusters on request).
bool uses_registry(const BakeOptions& o)
{
    return o.method == "clustered" || o.method == "reference" || o.method == "raster" || o.method == "terrain";
}

// The argument errors, each a sentence; empty when the options are usable.
std::string check_options(const BakeOptions& o)
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
    if (o.lattice != "open" && o.lattice != "centred" && o.lattice != "hateengine")
        return "--lattice must be open, centred or hateengine, not '" + o.lattice + "'";
    if (!(o.step >= 0.0f) || !(o.cell >= 0.0f) || !(o.grid_size > 0.0f))
        return "--step and --cell must be 0 or more and --grid-size more than 0";
    if (uses_registry(o) && !o.prt_in.empty())
        return "--prt: " + o.method + " does not read portals (it builds what it needs from the tree)";
    if (uses_registry(o) && !o.prt_out.empty())
        return "--write-prt: " + o.method + " uses no portals to write (portal-fast and portal-full do)";
    if (uses_registry(o) && o.clusters != "none")
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
    for (const auto& [option, file] : {std::pair{"-o", &o.output}, {"--report", &o.report}, {"--write-prt", &o.prt_out}})
        if (const std::string folder = missing_folder(*file); !folder.empty())
            return std::string(option) + " " + *file + ": no folder " + folder + " to write it in";
    std::error_code ec;
    if (!o.apply_edits.empty() && !std::filesystem::is_regular_file(o.apply_edits, ec))
        return "--apply-edits " + o.apply_edits + ": no such file";
    return {};
}

// An OBJ level (or a .hepvs with its OBJ): the grid is the .hepvs's unless --cell asks for
// another, else HateEngine's cell of 8 grid units over the level's vertices.
Input load_obj_input(const BakeOptions& o)
{
    ZoneLoadOptions load;
    load.hepvs = o.hepvs;
    load.grid_size = o.grid_size;
    Input in(InputFormat::ObjHepvs, load_zone(o.input, load));
    if (!in.zone.view_grid || o.cell > 0.0f) {
        const float cell = o.cell > 0.0f ? o.cell : kConvertHepvsCell;
        const std::optional<ViewGrid> grid = grid_over_points(in.zone.mesh.positions, cell, o.grid_size);
        if (!grid)
            throw FileError(o.input, 0, "no view grid of " + std::to_string(cell) + " grid units fits this level");
        in.zone.view_grid = *grid;
        in.zone.baked_pvs.reset(); // rows of another grid
    }
    return in;
}

// A Doom map: its zone (no textures: nothing is drawn) and where its GL group is.
Input load_doom_input(const BakeOptions& o)
{
    const doom::DoomMap map = doom::open_doom_map(o.input, o.map, o.gwa).map;
    Input in(InputFormat::DoomWad, doom::build_doom_zone(map, nullptr));
    in.doom_source = map.source;
    for (const doom::GlSubsector& ss : map.subsectors)
        in.sector_of_subsector.push_back(ss.sector);
    in.sector_count = uint32_t(map.sectors.size());
    if (o.heights) {
        const std::vector<bool> moving = doom::moving_sectors(map);
        const size_t count = size_t(std::count(moving.begin(), moving.end(), true));
        if (count > 0)
            std::fprintf(stderr,
                         "warning: --heights: %zu of %zu sectors of %s move (doors, lifts, floors, crushers): they "
                         "block sight as built, so a door that opens can show what the PVS hides\n",
                         count, moving.size(), map.name.c_str());
    }
    return in;
}

Input load_input(const BakeOptions& o)
{
    const std::string& path = o.input;
    const std::string ext = lowercase_extension(path);
    if (ext == ".obj" || ext == ".hepvs")
        return load_obj_input(o);
    if (doom::file_looks_like_wad(path) || ext == ".gwa")
        return load_doom_input(o);
    // The file's bytes are not kept: the writer reads the file again (pvs_writeback.h).
    const std::vector<uint8_t> bytes = read_whole_file(path);
    if (quake::looks_like_bsp29(bytes))
        return Input(InputFormat::QuakeBsp, quake::load_bsp29(bytes, path));
    if (quake2::looks_like_ibsp38(bytes))
        return Input(InputFormat::Quake2Bsp, quake2::load_ibsp38(bytes, path));
    if (eq::looks_like_pfs(bytes))
        return Input(InputFormat::EqS3d, eq::load_eq_zone(bytes, path));
    load_zone(path); // throws the loader's message for formats it recognises but cannot read
    throw FileError(path, 0, "bake writes Quake BSP 29 / BSP2 / 2PSB, Quake 2 IBSP 38, EverQuest S3D, Doom GL_PVS and "
                             "OBJ + .hepvs only");
}

// A portal bake reads the tree, the regions and their flags, never the faces. So a Quake map's
// and an EverQuest zone's render mesh and textures (1.3 MB of e1m1, more than a tenth of the
// bake's peak; 16 MB of the 5000-room zone's 417) are freed before the bake: a BSP is written
// back from the file's own bytes, and an S3D, which is written again from the whole zone, is
// read again for that (write_output: 0.2 s at 5000 rooms, after the bake's arrays are gone).
// A Doom map keeps its sectors (its writer needs them; they are small).
void drop_what_a_portal_bake_does_not_read(Input& in)
{
    if (in.format != InputFormat::QuakeBsp && in.format != InputFormat::Quake2Bsp && in.format != InputFormat::EqS3d)
        return;
    in.zone.mesh = Mesh{};
    for (Material& material : in.zone.materials)
        material.pixels = {};
    in.drawing_dropped = true;
    // Freed pages in the middle of the heap stay resident: give them back now.
    return_freed_memory();
}

// A Quake 2 map's PRT1 from qbsp names the map's clusters, not its leaves (qbsp -q2bsp writes it
// over them): read as a cluster portal file, each region in its leaf's cluster, so the bake is
// the flow over the clusters that `pvscope vis` runs.
quake::PrtFile as_quake2_cluster_portals(quake::PrtFile prt, const quake2::RegionClusterMap& map,
                                         const Zone& zone)
{
    prt.version = quake::PrtVersion::Prt2;
    prt.cluster_count = map.clusters;
    prt.cluster_of_leaf.assign(map.cluster_of_region.begin(), map.cluster_of_region.end());
    prt.leaf_count = uint32_t(zone.region_count());
    return prt;
}

// --prt: PRT leaf k is region k (for a Quake map, BSP leaf k+1), so the file must name exactly
// the zone's regions; a PRT2 / PRT1-AM file's portals name its clusters. A Quake 2 map's PRT1
// names either its clusters (qbsp's) or its regions (what --write-prt writes of a bake per leaf).
quake::PrtFile load_prt_for_zone(const std::string& prt_path, const Input& in, const std::string& zone_path)
{
    quake::PrtFile prt = quake::load_prt(prt_path);
    if (in.format == InputFormat::Quake2Bsp && !prt.has_clusters()) {
        const quake2::RegionClusterMap map = quake2::region_clusters(read_whole_file(zone_path), zone_path, in.zone);
        if (prt.leaf_count == map.clusters)
            return as_quake2_cluster_portals(std::move(prt), map, in.zone);
        if (prt.leaf_count != in.zone.region_count())
            throw FileError(prt_path, 0,
                            "portal file names " + std::to_string(prt.leaf_count) + " leaves but " + zone_path +
                                " has " + std::to_string(map.clusters) + " clusters and " +
                                std::to_string(in.zone.region_count()) +
                                " regions (a Quake 2 portal file names one or the other: a portal file of another map?)");
    }
    if (prt.leaf_count != in.zone.region_count())
        throw FileError(prt_path, 0,
                        "portal file names " + std::to_string(prt.leaf_count) + " leaves but " + zone_path + " has " +
                            std::to_string(in.zone.region_count()) +
                            " regions (PRT leaf k must be region k: a portal file of another map?)");
    return prt;
}

struct BakeRun {
    PortalSet portals;
    std::string portal_source = "tree";
    std::optional<PortalStats> portal_stats;
    double portal_seconds = 0.0;
    // Set when the bake runs over clusters (a PRT2 / PRT1-AM file's, or box clusters); `portals`
    // are then the portals between clusters.
    std::optional<RegionClusters> clusters;
    size_t portals_inside_clusters = 0; // box clusters: region portals dropped inside one cluster
    Pvs pvs;
    VisReport report;
    ClusterReport cluster_report;
    size_t edits_applied = 0; // --apply-edits
};

// A Doom map's PVS as GL_PVS: into -o (a copy of the GL file: the .gwa, or the WAD holding the
// GL nodes, REJECT too with --reject), or with --in-place into the GL file itself with a backup.
void write_doom_output(const BakeOptions& o, const Input& in, const Pvs& pvs, std::FILE* err)
{
    const doom::MapSource& src = in.doom_source;
    if (o.in_place) {
        doom::GlPvsWriteOptions options;
        options.rebuild_reject = o.reject;
        const doom::GlPvsWriteResult r = doom::write_gl_pvs(src, pvs, in.sector_of_subsector, in.sector_count, options);
        std::fprintf(err, "wrote GL_PVS into %s (%s; backup %s)%s\n", r.gl_file.c_str(),
                     r.inserted ? "inserted" : "replaced", r.backup_file.c_str(),
                     r.reject_written ? ", and REJECT rebuilt from it" : "");
        return;
    }
    const doom::WadFile gl = doom::read_wad(src.gl_path);
    std::vector<uint8_t> bytes = doom::with_gl_pvs(gl, src.gl_marker, doom::gl_pvs_lump(pvs));
    if (o.reject) {
        // The map lumps come before their GL group, so the map marker keeps its index.
        const doom::WadFile updated = doom::parse_wad(std::move(bytes), o.output);
        bytes = doom::with_reject(updated, src.map_marker,
                                  doom::reject_from_pvs(pvs, in.sector_of_subsector, in.sector_count));
    }
    write_whole_file(o.output, bytes);
    std::fprintf(err, "wrote %s: %s with GL_PVS (%u subsectors)%s\n", o.output.c_str(), src.gl_path.c_str(),
                 pvs.region_count(), o.reject ? " and REJECT rebuilt from it" : "");
}

// --apply-edits: the list applied to the bake in place, before anything is written or reported
// (the summary and the report give what is written). Returns the number of edits, 0 without.
size_t apply_edit_list(const BakeOptions& o, Pvs& pvs, std::FILE* err)
{
    if (o.apply_edits.empty())
        return 0;
    const std::vector<PvsEdit> edits = read_edit_list(o.apply_edits, pvs.row_count(), pvs.region_count());
    pvs = apply_edits(pvs, edits);
    std::fprintf(err, "applied %zu edits from %s\n", edits.size(), o.apply_edits.c_str());
    return edits.size();
}

double mean_visible_of(const Pvs& pvs)
{
    return pvs_gap(&pvs, pvs).mean_visible; // set bits per row
}

void write_output(const BakeOptions& o, const Input& in, const Pvs& pvs, std::FILE* err)
{
    if (in.format == InputFormat::DoomWad) {
        write_doom_output(o, in, pvs, err);
        return;
    }
    // An S3D is written again from the whole zone: read it again if the bake let its drawing go.
    std::optional<Zone> reloaded;
    if (in.format == InputFormat::EqS3d && in.drawing_dropped) {
        reloaded = eq::load_eq_zone(read_whole_file(o.input), o.input);
        if (reloaded->region_count() != in.zone.region_count())
            throw FileError(o.input, 0, "changed during the bake: " + std::to_string(reloaded->region_count()) +
                                            " regions now, " + std::to_string(in.zone.region_count()) + " when it was read");
    }
    // The other formats through the writer the inspector's Save uses too.
    PvsWriteOptions write_options;
    write_options.quake_ambient = o.ambient;
    write_options.ambient = o.ambient_classes;
    write_options.phs = o.phs_rule == "ericw" ? quake2::PhsRule::EricwTools : quake2::PhsRule::Quake2;
    write_options.shown_path = o.output_name;
    const PvsWriteback written =
        write_pvs_in_zone_format(reloaded ? *reloaded : in.zone, ZoneLoadOptions{}, pvs, o.output, write_options);
    for (const std::string& note : written.notes)
        std::fprintf(err, "note: %s\n", note.c_str());
    std::fprintf(err, "%s\n", written.summary.c_str());
}

nlohmann::json report_json(const BakeOptions& o, const Input& in, const BakeRun& run, double load_seconds,
                           double write_seconds)
{
    const VisReport& r = run.report;
    const uint32_t regions = run.pvs.region_count();
    nlohmann::json j = {{"input", o.input},
                        {"output", o.output_name.empty() ? o.output : o.output_name},
                        {"format", format_name(in)},
                        {"method", o.method},
                        {"level", o.method == "portal-full" ? nlohmann::json(o.level) : nlohmann::json(nullptr)},
                        {"threads", r.threads},
                        {"portal_source", run.portal_source},
                        {"portals", r.portals},
                        {"portals_skipped", r.portals_skipped},
                        {"regions", regions},
                        {"time_seconds", r.seconds},
                        {"base_seconds", r.base_seconds},
                        {"passage_pairs", r.passage_pairs},
                        {"passage_seconds", r.passage_seconds},
                        {"target_checks", r.target_checks},
                        {"target_check_prunes", r.target_check_prunes},
                        {"dominated_windows", r.dominated_windows},
                        {"load_seconds", load_seconds},
                        {"portalize_seconds", run.portal_seconds},
                        {"write_seconds", write_seconds},
                        {"peak_memory_estimate_bytes", r.peak_bytes_estimate},
                        {"peak_rss_bytes", peak_rss_bytes()},
                        {"mean_visible", r.mean_visible},
                        {"mean_visible_percent", regions ? 100.0 * r.mean_visible / regions : 0.0},
                        {"saw_into_own_region", r.saw_into_own_region},
                        {"leaf_recursions", r.leaf_recursions},
                        {"flow_frames", r.frames},
                        {"flow_frames_floor", r.portal_visible},
                        {"edits_applied", run.edits_applied}};
    report::add_report_fields(j, vis_report_fields(r, o.method == "portal-full", false));
    if (run.portal_stats)
        j["leaks"] = {{"leaves_touching_world", run.portal_stats->leaves_touching_world.size()},
                      {"leaves_touching_outside", run.portal_stats->leaves_touching_outside.size()}};
    j["clusters"] = run.clusters ? nlohmann::json{{"clusters", run.cluster_report.clusters},
                                                  {"cluster_portals", run.cluster_report.cluster_portals},
                                                  {"portals_inside_clusters", run.cluster_report.portals_inside_clusters},
                                                  {"cluster_mean_visible", run.cluster_report.cluster_mean_visible},
                                                  {"expand_seconds", run.cluster_report.expand_seconds}}
                                 : nlohmann::json(nullptr);
    j["file_pvs"] = in.zone.baked_pvs ? report::pvs_diff_json(run.pvs, *in.zone.baked_pvs) : nlohmann::json(nullptr);
    return j;
}

void find_portals(const BakeOptions& o, const Input& in, BakeRun& run, std::FILE* err)
{
    const Zone& zone = in.zone;
    const auto start = std::chrono::steady_clock::now();
    if (!o.prt_in.empty()) {
        quake::PrtFile prt = load_prt_for_zone(o.prt_in, in, o.input);
        run.portals = std::move(prt.portals);
        run.portal_source = o.prt_in;
        if (prt.has_clusters()) {
            run.clusters = RegionClusters{std::move(prt.cluster_of_leaf), prt.cluster_count};
            std::fprintf(err, "clusters: %s groups %zu leaves in %u clusters\n", o.prt_in.c_str(), zone.region_count(),
                         run.clusters->cluster_count);
        }
    } else {
        PortalOptions options;
        options.sky = sky_mode_from_name(o.sky);
        run.portal_stats.emplace();
        run.portals = build_zone_portals(zone, options, &*run.portal_stats);
        // Only the world box: an EverQuest zone's walls are region-less (outside) leaves, so
        // leaves next to them are normal there.
        if (!run.portal_stats->leaves_touching_world.empty())
            std::fprintf(err,
                         "warning: %s leaks: %zu open leaves touch the world box; no portal leads outside, the PVS "
                         "covers the open leaves only\n",
                         o.input.c_str(), run.portal_stats->leaves_touching_world.size());
    }
    run.portal_seconds = seconds_since(start);
    if (run.portals.portals.empty())
        std::fprintf(err, "warning: %s has no portals: every region will see only itself\n", o.input.c_str());
}

// --clusters auto: box clusters for a zone whose regions are boxes, none for a Quake map.
void choose_clusters(const BakeOptions& o, const Input& in, BakeRun& run, std::FILE* err)
{
    if (o.clusters != "auto" || run.clusters) // a PRT2 file's own clusters are used
        return;
    if (in.format == InputFormat::QuakeBsp || in.format == InputFormat::Quake2Bsp) {
        std::fprintf(err, "note: --clusters auto: a Quake map is baked per leaf (its PVS is per leaf)\n");
        return;
    }
    if (!regions_are_boxes(in.zone.regions, run.portals)) {
        std::fprintf(err, "note: --clusters auto: the regions of %s are not boxes; baked per region\n", o.input.c_str());
        return;
    }
    run.clusters = box_merge_clusters(in.zone.regions, run.portals);
    run.portals = cluster_portal_set(run.portals, run.clusters->cluster_of_region, run.clusters->cluster_count,
                                     &run.portals_inside_clusters);
    std::fprintf(err, "clusters: %zu regions in %u box clusters\n", in.zone.region_count(), run.clusters->cluster_count);
}

bool bake(const BakeOptions& o, const Zone& zone, BakeRun& run, std::FILE* err, const std::atomic<bool>* cancel)
{
    VisParams params;
    params.method = o.method == "portal-fast" ? VisParams::Method::Fast : VisParams::Method::Full;
    params.level = o.level;
    params.threads = o.threads;
    if (!o.passages)
        params.passage_budget_bytes = 0;
    params.target_checks = o.target_checks;
    ProgressBar bar(err, "bake");
    params.progress = [&](double fraction) {
        bar.update(fraction);
        return !(cancel && cancel->load());
    };
    if (run.clusters) {
        run.pvs = bake_cluster_portal_vis(run.portals, run.clusters->cluster_of_region, run.clusters->cluster_count,
                                          params, &run.report, &run.cluster_report);
        run.cluster_report.portals_inside_clusters = run.portals_inside_clusters;
    } else
        run.pvs = bake_portal_vis(run.portals, uint32_t(zone.region_count()), params, &run.report);
    bar.finish(run.report.cancelled ? "cancelled" : "done");
    return !run.report.cancelled;
}

MethodSettings method_settings(const BakeOptions& o)
{
    MethodSettings settings;
    settings.sky = sky_mode_from_name(o.sky);
    settings.threads = o.threads;
    settings.level = o.level;
    settings.passages = o.passages;
    settings.target_checks = o.target_checks;
    settings.samples = o.samples;
    settings.seed = o.seed;
    settings.raster_resolution = o.resolution;
    settings.raster_engine = o.raster_engine == "rasteriser" ? RasterEngine::Rasteriser : RasterEngine::Rays;
    settings.raster_points = o.points;
    settings.raster_step = o.step;
    settings.raster_lattice = o.lattice == "hateengine" ? Lattice::HateEngine
                              : o.lattice == "centred"  ? Lattice::Centred
                                                        : Lattice::OpenRandom;
    settings.cull_back_faces = o.cull_back_faces;
    settings.heights = o.heights;
    return settings;
}

// clustered / reference through the registry; false when cancelled. A reference is a lower
// bound: the user is told it can pop.
bool bake_with_method(const BakeOptions& o, const Input& in, Pvs& pvs, MethodRun& run, std::FILE* err,
                      const std::atomic<bool>* cancel)
{
    MethodSettings settings = method_settings(o);
    ProgressBar bar(err, "bake");
    settings.on_reference_round = [&](const ReferenceRound& round, const Pvs&) {
        char line[240];
        std::snprintf(line, sizeof line,
                      "reference: %8s lines and %6s eyes per region, %9s bits, +%s new (%.3f%%), %.1f s",
                      std::to_string(round.samples_per_region).c_str(),
                      std::to_string(round.eyes_per_region).c_str(), std::to_string(round.bits).c_str(),
                      std::to_string(round.new_bits).c_str(), 100.0 * round.new_share(), round.seconds);
        bar.note(line);
    };
    settings.progress = [&](double fraction) {
        bar.update(fraction);
        return !(cancel && cancel->load());
    };
    run = find_vis_method(o.method)->run(in.zone, settings);
    bar.finish(run.cancelled ? "cancelled" : "done");
    if (run.cancelled)
        return false;
    pvs = std::move(*run.pvs);
    if (o.method == "raster")
        std::fprintf(err, "note: the raster PVS is a sample (what the rendered points saw): a camera between the "
                          "points can see more; denser sampling (--step, --points, --resolution) only adds\n");
    if (o.method == "reference")
        std::fprintf(err, "warning: the reference is a lower bound (only sight lines it traced): culling with it can "
                          "pop where a line it did not find would have shown a region; use it to judge other PVSs\n");
    return true;
}

int run_registry_method(const BakeOptions& o, const Input& in, double load_seconds, std::FILE* err,
                        const std::atomic<bool>* cancel)
{
    Pvs pvs;
    MethodRun run;
    if (!bake_with_method(o, in, pvs, run, err, cancel)) {
        std::fprintf(err, "pvscope: bake cancelled: nothing was written\n");
        return kExitCancelled;
    }
    const size_t edits = apply_edit_list(o, pvs, err);
    const auto write_start = std::chrono::steady_clock::now();
    write_output(o, in, pvs, err);
    const double write_seconds = seconds_since(write_start);
    std::fprintf(err, "%s%s\n", run.summary.c_str(), edits ? " (before the edits)" : "");
    if (!o.report.empty()) {
        const VisMethod& m = *find_vis_method(o.method);
        const uint32_t regions = pvs.region_count();
        nlohmann::json j = {{"input", o.input},
                            {"output", o.output_name.empty() ? o.output : o.output_name},
                            {"format", format_name(in)}, {"method", o.method},
                            {"params", m.label(method_settings(o))},
                            {"bound", bound_name(m.bound)},
                            {"summary", run.summary},     {"regions", regions},
                            {"time_seconds", run.seconds}, {"load_seconds", load_seconds},
                            {"write_seconds", write_seconds},
                            {"peak_memory_estimate_bytes", run.peak_bytes_estimate},
                            {"peak_rss_bytes", peak_rss_bytes()},
                            {"mean_visible", mean_visible_of(pvs)},
                            {"edits_applied", edits}};
        report::add_report_fields(j, run.fields);
        j["file_pvs"] = in.zone.baked_pvs ? report::pvs_diff_json(pvs, *in.zone.baked_pvs) : nlohmann::json(nullptr);
        write_report(o.report, j);
    }
    return 0;
}

// --write-prt: PRT1 of the portals used, or PRT2 (cluster portals and the cluster map) when the
// bake ran over clusters.
void write_portal_file(const std::string& path, const Zone& zone, const BakeRun& run, std::FILE* err)
{
    quake::PrtFile prt;
    prt.leaf_count = uint32_t(zone.region_count());
    prt.portals = run.portals;
    if (run.clusters) {
        prt.version = quake::PrtVersion::Prt2;
        prt.cluster_count = run.clusters->cluster_count;
        prt.cluster_of_leaf = run.clusters->cluster_of_region;
    }
    quake::save_prt(path, prt);
    std::fprintf(err, "wrote %s: %s, %zu portals\n", path.c_str(), run.clusters ? "PRT2" : "PRT1",
                 prt.portals.portals.size());
}

int run_checked(const BakeOptions& o, std::FILE* err, const std::atomic<bool>* cancel)
{
    const auto load_start = std::chrono::steady_clock::now();
    Input in = load_input(o);
    const double load_seconds = seconds_since(load_start);
    if (in.format == InputFormat::ObjHepvs && o.method != "raster" && o.method != "reference") {
        std::fprintf(err, "pvscope: error: '%s' is an OBJ level: %s needs a BSP tree, which it has not; bake it with "
                          "--method raster (or reference: sight lines against the mesh)\n",
                     o.input.c_str(), o.method.c_str());
        return kExitBadArguments;
    }
    if (in.format != InputFormat::DoomWad && (o.in_place || o.reject || o.heights || !o.map.empty())) {
        std::fprintf(err, "pvscope: error: --in-place, --reject, --heights and --map are for Doom WADs\n");
        return kExitBadArguments;
    }
    if (o.reject && !o.in_place && in.doom_source.gl_path != in.doom_source.wad_path) {
        std::fprintf(err, "pvscope: error: --reject: REJECT lives in %s but the GL nodes (and -o) are in %s; use "
                          "--in-place to write both\n",
                     in.doom_source.wad_path.c_str(), in.doom_source.gl_path.c_str());
        return kExitBadArguments;
    }
    if (!o.in_place && lowercase_extension(o.output) != format_extension(in)) {
        std::fprintf(err,
                     "pvscope: error: '%s' is in the %s format and bake writes its PVS in the same format, so the output "
                     "must end in %s, not '%s' (to change the format, run `pvscope convert` on the result)\n",
                     o.input.c_str(), format_name(in).c_str(), format_extension(in).c_str(), o.output.c_str());
        return kExitBadArguments;
    }
    if (in.format == InputFormat::DoomWad && (!o.prt_in.empty() || !o.prt_out.empty())) {
        std::fprintf(err, "pvscope: error: --prt / --write-prt: a Doom map's portals are its GL nodes' segs, not a "
                          "portal file\n");
        return kExitBadArguments;
    }
    // A Doom map goes through the registry, which picks the 2-D baker (or the 3-D one, --heights).
    if (uses_registry(o) || in.format == InputFormat::DoomWad)
        return run_registry_method(o, in, load_seconds, err, cancel);
    drop_what_a_portal_bake_does_not_read(in);
    BakeRun run;
    find_portals(o, in, run, err);
    choose_clusters(o, in, run, err);
    if (!bake(o, in.zone, run, err, cancel)) {
        std::fprintf(err, "pvscope: bake cancelled: nothing was written\n");
        return kExitCancelled;
    }
    if ((run.edits_applied = apply_edit_list(o, run.pvs, err)) > 0)
        run.report.mean_visible = mean_visible_of(run.pvs);
    const auto write_start = std::chrono::steady_clock::now();
    write_output(o, in, run.pvs, err);
    if (!o.prt_out.empty())
        write_portal_file(o.prt_out, in.zone, run, err);
    const double write_seconds = seconds_since(write_start);
    std::fprintf(err, "%s: %zu regions, %zu portals (%zu skipped), mean visible %.1f, %.2f s (base %.2f s), %u threads\n",
                 o.method.c_str(), in.zone.region_count(), run.report.portals, run.report.portals_skipped,
                 run.report.mean_visible, run.report.seconds, run.report.base_seconds, run.report.threads);
    if (!o.report.empty())
        write_report(o.report, report_json(o, in, run, load_seconds, write_seconds));
    return 0;
}

} // namespace

std::string missing_folder(const std::string& path)
{
    if (path.empty() || path == "-")
        return {};
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    std::error_code ec;
    return folder.empty() || std::filesystem::is_directory(folder, ec) ? std::string() : folder.string();
}

void write_report(const std::string& path, const nlohmann::json& report)
{
    const std::string text = report.dump(2) + "\n";
    if (path == "-") {
        std::fputs(text.c_str(), stdout);
        return;
    }
    write_whole_file(path, std::vector<uint8_t>(text.begin(), text.end()));
}

int run_bake(const BakeOptions& options, std::FILE* err, const std::atomic<bool>* cancel)
{
    if (const std::string problem = check_options(options); !problem.empty()) {
        std::fprintf(err, "pvscope: error: %s\n", problem.c_str());
        return kExitBadArguments;
    }
    try {
        return run_checked(options, err, cancel);
    } catch (const FileError& e) {
        std::fprintf(err, "pvscope: error: %s\n", e.what());
        return kExitFileError;
    } catch (const std::invalid_argument& e) { // the zone or portals cannot be written in the format
        std::fprintf(err, "pvscope: error: %s: %s\n", options.input.c_str(), e.what());
        return kExitFileError;
    }
}

void register_bake_command(CLI::App& app, int& exit_code)
{
    auto o = std::make_shared<BakeOptions>();
    CLI::App* cmd = app.add_subcommand(
        "bake", "Compute a PVS (portal vis, clustered, the sampled reference, or raster cube maps) and write it back in "
                "the zone's own format (.bsp: new visdata, other lumps unchanged; .s3d: new VISLISTs; an OBJ level: "
                "a .hepvs). Ctrl-C cancels and writes nothing.");
    cmd->add_option("file", o->input, "Zone file (Quake .bsp, EverQuest .s3d, or an OBJ level / its .hepvs)")->required();
    cmd->add_option("-o,--output", o->output, "Output file, in the input's format (.bsp, .s3d; .hepvs for an OBJ; "
                                              "a Doom map: a copy of its GL file, .gwa or .wad)");
    cmd->add_option("--map", o->map, "Doom WAD: the map to bake (E1M1, MAP10; default: the first)");
    cmd->add_option("--gwa", o->gwa, "Doom WAD: its GL nodes (default: the .gwa beside it, else the WAD's own)");
    cmd->add_flag("--heights", o->heights, "Doom: floors and ceilings as built block sight (3-D portals; closed "
                                           "doors and lifts count as built: only for maps whose sectors never move). "
                                           "Default: 2-D, as glVIS");
    cmd->add_flag("--reject", o->reject, "Doom: also rebuild the map's REJECT from the PVS (as glVIS does)");
    cmd->add_flag("!--no-ambient", o->ambient,
                  "Quake: keep the map's ambient sound levels instead of computing them from the new PVS (as vis does)");
    cmd->add_option("--phs-rule", o->phs_rule,
                    "Quake 2: the PHS written with the PVS: quake2 (the engine's, as id's qvis3) or ericw (what "
                    "ericw-tools vis writes)")
        ->check(CLI::IsMember({"quake2", "ericw"}))
        ->capture_default_str();
    cmd->add_option("--apply-edits", o->apply_edits, "Apply this PVS edit list (saved by the inspector) to the bake "
                                                     "before writing it: hand fixes that survive a re-vis")
        ->check(CLI::ExistingFile);
    cmd->add_flag("--in-place", o->in_place, "Doom: write GL_PVS into the map's own GL file (.gwa or WAD), keeping "
                                             "the old one as .~gw / .~wa, as glVIS does");
    cmd->add_option("--method", o->method, "portal-fast (base vis only, loose), portal-full (clipped flow), "
                                           "clustered (portal-full over clusters of regions), terrain (the ground as "
                                           "the occluder: a horizon over the zone's heightfield, for open zones), "
                                           "reference (sampled "
                                           "sight lines: a lower bound, for judging other PVSs) or raster (cube "
                                           "maps rendered from points in each cell, as HateEngine's baker)")
        ->check(CLI::IsMember({"portal-fast", "portal-full", "clustered", "terrain", "reference", "raster"}))
        ->capture_default_str();
    cmd->add_option("--level", o->level, "portal-full: separating-plane test level 0..4")
        ->check(CLI::Range(0, 4))
        ->capture_default_str();
    cmd->add_option("--threads", o->threads, "Worker threads (0 = all cores); the result does not depend on it")
        ->check(threads_validator())
        ->capture_default_str();
    cmd->add_option("--sky", o->sky, "Portals at sky leaves when built from the tree: sky-to-sky (ericw's default), "
                                     "all (-transsky), none (as id's shipped maps)")
        ->check(CLI::IsMember({"sky-to-sky", "all", "none"}))
        ->capture_default_str();
    cmd->add_option("--clusters", o->clusters, "none: bake per region; auto: over box clusters when the regions "
                                               "are boxes (generated zones; faster, looser), per leaf for Quake")
        ->check(CLI::IsMember({"none", "auto"}))
        ->capture_default_str();
    cmd->add_option("--passages", o->passages, "portal-full: prune the flow with passages (true: about half the "
                                               "time on Quake maps; false: faster on open generated zones); the "
                                               "rows are the same")
        ->capture_default_str();
    cmd->add_option("--target-checks", o->target_checks, "portal-full: before walking into a leaf already seen, "
                                                         "check that a leaf not yet seen is still reachable "
                                                         "(true: about a third faster on Quake maps)")
        ->capture_default_str();
    cmd->add_option("--samples", o->samples, "reference: volume lines per region at most, with an eye walked "
                                             "through the portals per 8 lines (0: double until a doubling adds "
                                             "under 0.1% of the bits, up to 8192: e1m1 converges at 2048, about "
                                             "20 s with 2 cores)")
        ->capture_default_str();
    cmd->add_option("--seed", o->seed, "reference, raster: the sampling seed (the same seed gives the same PVS)")
        ->capture_default_str();
    cmd->add_option("--resolution", o->resolution, "raster: pixels per cube face side")->capture_default_str();
    cmd->add_option("--engine", o->raster_engine,
                    "raster: how the six views are drawn: rays (a ray per pixel centre, Embree packets; faster) "
                    "or rasteriser (pvscope's CPU rasteriser; the same pixel centres)")
        ->check(CLI::IsMember({"rays", "rasteriser"}))
        ->capture_default_str();
    cmd->add_option("--points", o->points, "raster: sample points in each region, or in the open space of each grid "
                                           "cell (--lattice open)")
        ->capture_default_str();
    cmd->add_option("--lattice", o->lattice, "raster over a grid: open (random points in the cell's open space), "
                                             "centred (a lattice of --step) or hateengine (the baker's lattice, "
                                             "points on the cell's far faces included)")
        ->check(CLI::IsMember({"open", "centred", "hateengine"}))
        ->capture_default_str();
    cmd->add_option("--step", o->step, "raster, centred or hateengine lattice: step in grid units (HateEngine's -s; "
                                       "1 with --cell 8 is its 1 + 8^3 points a cell); 0: each cell's centre only")
        ->capture_default_str();
    cmd->add_option("--back-faces", o->cull_back_faces, "raster: cull faces seen from behind (true, as the "
                                                         "HateEngine baker) or draw them")
        ->capture_default_str();
    cmd->add_option("--cell", o->cell, "OBJ level: view cells of this many grid units (0: the .hepvs's grid, "
                                       "else 8)")
        ->capture_default_str();
    cmd->add_option("--grid-size", o->grid_size, "OBJ level: OBJ units per grid unit (HateEngine's -g)")
        ->capture_default_str();
    cmd->add_option("--hepvs", o->hepvs, "OBJ level: its .hepvs when not the one of the same name beside it");
    cmd->add_option("--prt", o->prt_in, "Read the portals from this PRT1 file (leaf k = region k; PRT2 / PRT1-AM: "
                                        "baked over the file's clusters) instead of building them from the BSP tree")
        ->check(CLI::ExistingFile);
    cmd->add_option("--write-prt", o->prt_out, "Also write the portals the bake used to this file (PRT1; PRT2 when "
                                               "baked over clusters)");
    cmd->add_option("--report", o->report, "Write a JSON report (times, memory, portals, comparison with the "
                                           "file's own PVS) to this file, '-' for stdout");
    cmd->callback([o, &exit_code] {
        const SigintScope sigint;
        exit_code = run_bake(*o, stderr, &SigintScope::interrupted());
    });
}

} // namespace pvs::app
