#include "app/bake_input.h"

#include "app/process_memory.h"
#include "visibility/file_error.h"
#include "wld/common/read_file.h"
#include "wld/convert.h"
#include "wld/doom/doom_specials.h"
#include "wld/doom/doom_zone.h"
#include "wld/eq/eq_zone_reader.h"
#include "wld/hepvs/hepvs_zone.h"
#include "wld/quake/bsp29_reader.h"
#include "wld/quake/prt_file.h"
#include "wld/quake2/ibsp38_file.h"
#include "wld/quake2/ibsp38_zone.h"
#include "wld/quake2/quake2_vis.h"
#include "wld/zone_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>

namespace pvs::app {

// A Quake map's name says its variant (BSP 29, BSP2, 2PSB), as `info` does.
std::string format_name(const BakeInput& in)
{
    const ZoneFormat f = in.format;
    if (f == ZoneFormat::QuakeBsp)
        return in.zone.source.version == "29" || in.zone.source.version.empty() ? "Quake BSP 29"
                                                                                : "Quake " + in.zone.source.version;
    return f == ZoneFormat::Quake2Bsp ? "Quake 2 BSP (IBSP 38)"
           : f == ZoneFormat::EqS3d   ? "EverQuest S3D"
           : f == ZoneFormat::DoomWad ? "Doom WAD + GL nodes"
                                      : "OBJ + .hepvs";
}

std::string format_extension(const BakeInput& in)
{
    if (in.format == ZoneFormat::DoomWad)
        return lowercase_extension(in.doom_source.gl_path);
    return in.format == ZoneFormat::QuakeBsp || in.format == ZoneFormat::Quake2Bsp ? ".bsp"
           : in.format == ZoneFormat::EqS3d                                        ? ".s3d"
                                                                                   : ".hepvs";
}

std::string lowercase_extension(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

namespace {

// An OBJ level (or a .hepvs with its OBJ): the grid is the .hepvs's unless --cell asks for
// another, else HateEngine's cell of 8 grid units over the level's vertices.
BakeInput load_obj_input(const BakeOptions& o)
{
    ZoneLoadOptions load;
    load.hepvs = o.hepvs;
    load.grid_size = o.grid_size;
    BakeInput in(ZoneFormat::ObjHepvs, load_zone(o.input, load));
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
BakeInput load_doom_input(const BakeOptions& o, std::FILE* err)
{
    const doom::DoomMap map = doom::open_doom_map(o.input, o.map, o.gwa).map;
    BakeInput in(ZoneFormat::DoomWad, doom::build_doom_zone(map, nullptr));
    in.doom_source = map.source;
    for (const doom::GlSubsector& ss : map.subsectors)
        in.sector_of_subsector.push_back(ss.sector);
    in.sector_count = uint32_t(map.sectors.size());
    if (o.heights) {
        const std::vector<bool> moving = doom::moving_sectors(map);
        const size_t count = size_t(std::count(moving.begin(), moving.end(), true));
        if (count > 0)
            std::fprintf(err,
                         "warning: --heights: %zu of %zu sectors of %s move (doors, lifts, floors, crushers): they "
                         "block sight as built, so a door that opens can show what the PVS hides\n",
                         count, moving.size(), map.name.c_str());
    }
    return in;
}

} // namespace

BakeInput load_bake_input(const BakeOptions& o, std::FILE* err)
{
    const std::string& path = o.input;
    if (const std::optional<ZoneFormat> named = zone_format_from_name(path))
        return *named == ZoneFormat::DoomWad ? load_doom_input(o, err) : load_obj_input(o);
    // The file's bytes are not kept: the writer reads the file again (pvs_writeback.h).
    const std::vector<uint8_t> bytes = read_whole_file(path);
    switch (const ZoneFormat format = zone_format_from_bytes(bytes)) {
    case ZoneFormat::QuakeBsp: return BakeInput(format, quake::load_bsp29(bytes, path));
    case ZoneFormat::Quake2Bsp: return BakeInput(format, quake2::load_ibsp38(bytes, path));
    case ZoneFormat::EqS3d: return BakeInput(format, eq::load_eq_zone(bytes, path));
    default: break;
    }
    load_zone(path); // throws the loader's message for formats it recognises but cannot read
    throw FileError(path, 0,
                    "bake writes Quake BSP 29 / BSP2 / 2PSB, Quake 2 IBSP 38, EverQuest S3D, Doom GL_PVS and "
                    "OBJ + .hepvs only");
}

// A portal bake reads the tree, the regions and their flags, never the faces. So a Quake map's
// and an EverQuest zone's render mesh and textures (1.3 MB of e1m1, more than a tenth of the
// bake's peak; 16 MB of the 5000-room zone's 417) are freed before the bake: a BSP is written
// back from the file's own bytes, and an S3D, which is written again from the whole zone, is
// read again for that (write_bake_output: 0.2 s at 5000 rooms, after the bake's arrays are gone).
// A Doom map keeps its sectors (its writer needs them; they are small).
void drop_drawing(BakeInput& in)
{
    if (in.format != ZoneFormat::QuakeBsp && in.format != ZoneFormat::Quake2Bsp && in.format != ZoneFormat::EqS3d)
        return;
    in.zone.mesh = Mesh{};
    for (Material& material : in.zone.materials)
        material.pixels = {};
    in.drawing_dropped = true;
    // Freed pages in the middle of the heap stay resident: give them back now.
    return_freed_memory();
}

namespace {

// A Quake 2 map's PRT1 from qbsp names the map's clusters, not its leaves (qbsp -q2bsp writes it
// over them): read as a cluster portal file, each region in its leaf's cluster, so the bake is
// the flow over the clusters that `pvscope vis` runs.
quake::PrtFile as_quake2_cluster_portals(quake::PrtFile prt, const quake2::RegionClusterMap& map, const Zone& zone)
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
quake::PrtFile load_prt_for_zone(const std::string& prt_path, const BakeInput& in)
{
    const std::string& zone_path = in.zone.source.path;
    quake::PrtFile prt = quake::load_prt(prt_path);
    if (in.format == ZoneFormat::Quake2Bsp && !prt.has_clusters()) {
        const quake2::RegionClusterMap map = quake2::region_clusters(read_whole_file(zone_path), zone_path, in.zone);
        if (prt.leaf_count == map.clusters)
            return as_quake2_cluster_portals(std::move(prt), map, in.zone);
        if (prt.leaf_count != in.zone.region_count())
            throw FileError(
                prt_path, 0,
                "portal file names " + std::to_string(prt.leaf_count) + " leaves but " + zone_path + " has " +
                    std::to_string(map.clusters) + " clusters and " + std::to_string(in.zone.region_count()) +
                    " regions (a Quake 2 portal file names one or the other: a portal file of another map?)");
    }
    if (prt.leaf_count != in.zone.region_count())
        throw FileError(prt_path, 0,
                        "portal file names " + std::to_string(prt.leaf_count) + " leaves but " + zone_path + " has " +
                            std::to_string(in.zone.region_count()) +
                            " regions (PRT leaf k must be region k: a portal file of another map?)");
    return prt;
}

} // namespace

PortalInput portal_input_from_file(const std::string& prt_path, const BakeInput& in)
{
    quake::PrtFile prt = load_prt_for_zone(prt_path, in);
    PortalInput portals;
    portals.portals = std::move(prt.portals);
    portals.source = prt_path;
    if (prt.has_clusters()) {
        portals.clusters = RegionClusters{std::move(prt.cluster_of_leaf), prt.cluster_count};
        portals.notes.push_back("clusters: " + prt_path + " groups " + std::to_string(in.zone.region_count()) +
                                " leaves in " + std::to_string(portals.clusters->cluster_count) + " clusters");
    }
    return portals;
}

std::string check_output_against_input(const BakeOptions& o, const BakeInput& in)
{
    if (in.format == ZoneFormat::ObjHepvs && o.method != "raster" && o.method != "reference")
        return "'" + o.input + "' is an OBJ level: " + o.method +
               " needs a BSP tree, which it has not; bake it with --method raster (or reference: sight lines "
               "against the mesh)";
    if (in.format != ZoneFormat::DoomWad && (o.in_place || o.reject || o.heights || !o.map.empty()))
        return "--in-place, --reject, --heights and --map are for Doom WADs";
    if (o.reject && !o.in_place && in.doom_source.gl_path != in.doom_source.wad_path)
        return "--reject: REJECT lives in " + in.doom_source.wad_path + " but the GL nodes (and -o) are in " +
               in.doom_source.gl_path + "; use --in-place to write both";
    if (!o.in_place && o.shard.empty() && lowercase_extension(o.output) != format_extension(in))
        return "'" + o.input + "' is in the " + format_name(in) +
               " format and bake writes its PVS in the same format, so the output must end in " + format_extension(in) +
               ", not '" + o.output +
               "' (to change the format, run `pvscope convert` on the "
               "result)";
    if (in.format == ZoneFormat::DoomWad && (!o.prt_in.empty() || !o.prt_out.empty()))
        return "--prt / --write-prt: a Doom map's portals are its GL nodes' segs, not a portal file";
    return {};
}

} // namespace pvs::app
