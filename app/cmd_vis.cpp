#include "app/cmd_vis.h"
#include "app/error_path.h"
#include "app/vis_quake2.h"

#include "app/cli_validators.h"
#include "app/cmd_bake.h"
#include "app/sigint_scope.h"
#include "visibility/file_error.h"
#include "wld/common/read_file.h"
#include "wld/quake/ambient_sounds.h"
#include "wld/quake/bsp29_reader.h"
#include "wld/quake/bsp_layout.h"
#include "wld/quake2/ibsp38_file.h"
#include "wld/zone_file.h"

#include <CLI/CLI.hpp>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <memory>
#include <unistd.h>

namespace pvs::app {

namespace {

namespace fs = std::filesystem;

// MAP, MAP.bsp: the map's path (vis adds .bsp when the name has no extension).
std::string map_path(const std::string& name)
{
    fs::path p(name);
    if (p.extension().empty())
        p += ".bsp";
    return p.string();
}

quake::AmbientOptions ambient_classes(const VisCommandOptions& o)
{
    quake::AmbientOptions a;
    a.sky = !(o.noambient || o.noambientsky);
    a.water = !(o.noambient || o.noambientwater);
    a.slime = !(o.noambient || o.noambientslime);
    a.lava = !(o.noambient || o.noambientlava);
    return a;
}

// The temporary file beside the map: same folder (so the rename is atomic), .bsp extension.
std::string temporary_beside(const std::string& map)
{
    const fs::path p(map);
    return (p.parent_path() / (p.stem().string() + ".pvscope-" + std::to_string(::getpid()) + ".tmp.bsp")).string();
}

// Renames the complete temporary file over the map; when that fails the temporary file goes.
void replace_map(const std::string& temporary, const std::string& map)
{
    std::error_code ec;
    fs::rename(temporary, map, ec);
    if (ec) {
        fs::remove(temporary, ec);
        throw FileError(map, 0, "could not replace the map with the vised file: " + ec.message());
    }
}

int ambient_only(const VisCommandOptions& o, const std::string& map, std::FILE* err)
{
    const std::vector<uint8_t> bytes = read_whole_file(map);
    const Zone zone = quake::load_bsp29(bytes, map); // the bytes read once, for the zone and the levels
    if (!zone.baked_pvs)
        throw FileError(map, 0, "--ambient-only: the map has no PVS to compute ambient sounds from (run vis first)");
    const std::vector<quake::AmbientLevels> levels =
        quake::compute_ambient_levels(bytes, *zone.baked_pvs, ambient_classes(o), map);
    replace_atomically(map, quake::with_ambient_levels(bytes, levels, map));
    size_t with_sound = 0;
    for (const quake::AmbientLevels& l : levels)
        with_sound += l != quake::AmbientLevels{0, 0, 0, 0};
    std::fprintf(err, "%s: ambient sounds on %zu of %zu leaves (the PVS kept)\n", map.c_str(), with_sound, levels.size());
    return 0;
}

// The first `count` bytes of the file (fewer when it is shorter): enough to tell the format by,
// without reading a whole map that bake reads again.
std::vector<uint8_t> read_file_head(const std::string& path, size_t count)
{
    std::ifstream in(path, std::ios::binary);
    std::vector<uint8_t> head(count);
    in.read(reinterpret_cast<char*>(head.data()), std::streamsize(count));
    head.resize(size_t(in.gcount()));
    return head;
}


// vis through bake: the PVS from MAP.prt or (--portals tree) from the BSP tree, written to a
// temporary file beside the map that then replaces it. Quake maps get ambient sounds, Quake 2
// maps the PHS by --phs-rule.
int vis_through_bake(const VisCommandOptions& o, const std::string& map, std::FILE* err,
                     const std::atomic<bool>* cancel)
{
    BakeOptions b;
    b.input = map;
    b.method = o.fast ? "portal-fast" : o.method;
    b.level = o.level;
    b.threads = o.threads;
    b.report = o.report;
    b.ambient = true;
    b.ambient_classes = ambient_classes(o);
    b.phs_rule = o.phs_rule;
    if (o.portals == "file") {
        const std::string prt = (fs::path(map).replace_extension(".prt")).string();
        if (!fs::is_regular_file(prt)) {
            return file_error(err, prt + ": no portal file beside the map (qbsp writes it; or --portals tree to build "
                                   "portals from the BSP tree)");
        }
        b.prt_in = prt;
    }
    const std::string temporary = temporary_beside(map);
    b.output = temporary;
    b.output_name = map;
    const int code = run_bake(b, err, cancel);
    if (code != 0) {
        std::error_code ec;
        fs::remove(temporary, ec);
        std::fprintf(err, "pvscope: %s left as it was\n", map.c_str());
        return code;
    }
    replace_map(temporary, map);
    return 0;
}

int checked(const VisCommandOptions& o, std::FILE* err, const std::atomic<bool>* cancel)
{
    if (o.visdist > 0.0)
        return bad_arguments(err, "-visdist is not supported: pvscope bakes what the portals let through; a distance "
                                  "cut belongs to the renderer's far plane");
    if (const std::string folder = missing_folder(o.report); !folder.empty())
        return bad_arguments(err, "--report " + o.report + ": no folder " + folder + " to write it in");
    const std::string map = map_path(o.map);
    if (!fs::is_regular_file(map))
        return file_error(err, map + ": no such map");
    const std::vector<uint8_t> head = read_file_head(map, 8);
    if (quake2::looks_like_ibsp38(head)) {
        if (o.ambient_only)
            return bad_arguments(err, map + " is a Quake 2 map: --ambient-only is for Quake maps (Quake 2 keeps no "
                                            "ambient sounds in the map)");
        if (o.phs_only)
            return quake2_phs_only(o, map, read_whole_file(map), err);
        // qbsp's portal file over the clusters, or (--portals tree) per leaf from the tree with the
        // leaves' rows ORed per cluster: bake writes both.
        if (const int code = vis_through_bake(o, map, err, cancel); code != 0)
            return code;
        std::fprintf(err, "%s: PVS and PHS written in place\n", map.c_str());
        return 0;
    }
    if (!quake::detect_bsp_variant(head)) {
        const std::string header = quake::describe_bsp_header(head);
        return file_error(err, map + ": offset 0: not a Quake map (" +
                                   (header.starts_with("version ") ? std::string("no BSP header") : header) +
                                   "): vis writes Quake BSP 29, BSP2, 2PSB and Quake 2 IBSP 38 maps; `pvscope bake` "
                                   "writes the other formats");
    }
    if (o.phs_only)
        return bad_arguments(err, "--phs-only is for Quake 2 maps (IBSP 38); " + map + " is not one");
    if (o.ambient_only)
        return ambient_only(o, map, err);
    if (const int code = vis_through_bake(o, map, err, cancel); code != 0)
        return code;
    std::fprintf(err, "%s: PVS and ambient sounds written in place\n", map.c_str());
    return 0;
}

} // namespace

int run_vis_command(const VisCommandOptions& options, std::FILE* err, const std::atomic<bool>* cancel)
{
    // Nothing is written over the map before the vised file is complete: say so after an error.
    const auto left_as_it_was = [&] {
        std::error_code ec;
        if (const std::string map = map_path(options.map); fs::is_regular_file(map, ec))
            std::fprintf(err, "pvscope: %s left as it was\n", map.c_str());
    };
    return run_reporting_errors(map_path(options.map), err, [&] { return checked(options, err, cancel); },
                                left_as_it_was);
}

std::vector<std::string> normalize_vis_arguments(const std::vector<std::string>& arguments)
{
    std::vector<std::string> out;
    bool in_vis = false;
    for (const std::string& a : arguments) {
        if (!in_vis) {
            in_vis = a == "vis";
            out.push_back(a);
            continue;
        }
        const bool one_dash_long = a.size() > 2 && a[0] == '-' && a[1] != '-' && std::isalpha(static_cast<unsigned char>(a[1]));
        out.push_back(one_dash_long ? "-" + a : a);
    }
    return out;
}

void register_vis_command(CLI::App& app, int& exit_code)
{
    auto o = std::make_shared<VisCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "vis", "Quake's vis as a drop-in: MAP.prt -> PVS and ambient sounds, written into MAP.bsp in place (BSP 29, "
               "BSP2, 2PSB; a Quake 2 IBSP 38 map: PVS and PHS over its clusters); ericw's options with one dash or "
               "two. Ctrl-C leaves the map as it was");
    cmd->add_option("map", o->map, "The map (MAP or MAP.bsp); its .prt is read from beside it")->required();
    cmd->add_option("--threads", o->threads, "Worker threads (0 = all cores)")->check(threads_validator())->capture_default_str();
    cmd->add_flag("--fast", o->fast, "Base vis only (portal-fast): quick and loose, as vis -fast");
    cmd->add_option("--level", o->level, "Separator test level of the full flow, 0..4")
        ->check(CLI::Range(0, 4))
        ->capture_default_str();
    cmd->add_flag("--noambient", o->noambient, "Write no ambient sound levels (all 0)");
    cmd->add_flag("--noambientsky", o->noambientsky, "Sky textures make no ambient sound");
    cmd->add_flag("--noambientwater", o->noambientwater, "Water textures make no ambient sound");
    cmd->add_flag("--noambientslime", o->noambientslime, "Slime textures make no ambient sound (vis plays slime on the water channel)");
    cmd->add_flag("--noambientlava", o->noambientlava, "Lava textures make no ambient sound");
    cmd->add_flag("--nostate", o->nostate, "Accepted for vis's command line; pvscope keeps no state file");
    cmd->add_option("--visdist", o->visdist, "Not supported (an error)");
    cmd->add_option("--method", o->method, "portal-full (default) or portal-fast")
        ->check(CLI::IsMember({"portal-full", "portal-fast"}))
        ->capture_default_str();
    cmd->add_option("--portals", o->portals, "file: MAP.prt beside the map; tree: portals built from the BSP tree per leaf")
        ->check(CLI::IsMember({"file", "tree"}))
        ->capture_default_str();
    cmd->add_flag("--ambient-only", o->ambient_only, "Keep the map's PVS; compute only the ambient sound levels from it");
    cmd->add_option("--report", o->report, "Write a JSON report of the bake (\"-\" = stdout)");
    cmd->add_flag("--phsonly,--phs-only", o->phs_only, "Quake 2: keep the map's PVS and make only the PHS again");
    cmd->add_option("--phs-rule", o->phs_rule, "Quake 2: quake2 (the engine's PHS, as id's qvis3) or ericw (what "
                                               "ericw-tools vis writes: a subset, byte for byte)")
        ->check(CLI::IsMember({"quake2", "ericw"}))
        ->capture_default_str();
    cmd->callback([o, &exit_code] {
        const SigintScope sigint;
        exit_code = run_vis_command(*o, stderr, &SigintScope::interrupted());
    });
}

} // namespace pvs::app
