#include "wld/pvs_writeback.h"

#include "visibility/file_error.h"
#include "wld/common/read_file.h"
#include "wld/convert.h"
#include "wld/doom/doom_map.h"
#include "wld/doom/gl_pvs_writer.h"
#include "wld/doom/wad_file.h"
#include "wld/eq/eq_zone_reader.h"
#include "wld/hepvs/hepvs_file.h"
#include "wld/hepvs/hepvs_zone.h"
#include "wld/quake/bsp_layout.h"
#include "wld/obj/obj_reader.h"
#include "wld/quake/bsp29_reader.h"
#include "wld/quake/bsp29_vis_writer.h"
#include "wld/quake2/ibsp38_file.h"
#include "wld/quake2/quake2_vis.h"

#include <cstdio>

#include <filesystem>

namespace pvs {

namespace {

PvsWriteback write_hepvs_of(const Zone& zone, const Pvs& pvs, const std::string& out_path)
{
    Zone copy = zone;
    copy.baked_pvs = pvs;
    const HepvsFile hepvs = hepvs_from_zone(copy);
    write_whole_file(out_path, write_hepvs(hepvs));
    return {": " + std::to_string(hepvs.counts.x) + " x " + std::to_string(hepvs.counts.y) +
                " x " + std::to_string(hepvs.counts.z) + " cells, " + std::to_string(hepvs.names.size()) + " objects",
            {},
            {}};
}

PvsWriteback write_gl_pvs_of(const Zone& zone, const ZoneLoadOptions& load, const Pvs& pvs, const std::string& out_path)
{
    const doom::DoomMap map = doom::open_doom_map(zone.source.path, load.map, load.gwa).map;
    const doom::WadFile gl = doom::read_wad(map.source.gl_path);
    write_whole_file(out_path, doom::with_gl_pvs(gl, map.source.gl_marker, doom::gl_pvs_lump(pvs)));
    return {": " + map.source.gl_path + " with GL_PVS (" + std::to_string(pvs.region_count()) +
                " subsectors)",
            {},
            {}};
}

// The writer of the zone's format; the summary is what follows "wrote FILE".
PvsWriteback write_in_zone_format(const Zone& zone, const ZoneLoadOptions& load, const Pvs& pvs,
                                  const std::string& out_path, const PvsWriteOptions& options)
{
    const std::string& path = zone.source.path;
    std::error_code ec;
    if (path.empty() || !std::filesystem::is_regular_file(path, ec))
        throw FileError(path.empty() ? out_path : path, 0,
                        "this zone was not read from a file (a generated zone): there is nothing to write the PVS into");
    if (zone.view_grid)
        return write_hepvs_of(zone, pvs, out_path);
    const std::vector<uint8_t> bytes = read_whole_file(path);
    if (quake::detect_bsp_variant(bytes)) {
        quake::Bsp29VisStats stats;
        std::vector<quake::AmbientLevels> ambient;
        if (options.quake_ambient)
            ambient = quake::compute_ambient_levels(bytes, pvs, options.ambient, path);
        write_whole_file(out_path, quake::write_bsp29_vis(bytes, pvs, path, &stats, ambient));
        size_t with_sound = 0;
        for (const quake::AmbientLevels& levels : ambient)
            with_sound += levels != quake::AmbientLevels{0, 0, 0, 0};
        const std::string sounds = options.quake_ambient
                                       ? ", ambient sounds on " + std::to_string(with_sound) + " of " +
                                             std::to_string(ambient.size()) + " leaves"
                                       : ", ambient sounds kept as they were";
        return {": " + std::to_string(stats.rows) + " rows, " + std::to_string(stats.unique_rows) +
                    " distinct, " + std::to_string(stats.visdata_bytes) + " bytes of visdata" + sounds,
                {},
                {}};
    }
    if (quake2::looks_like_ibsp38(bytes)) {
        const quake2::Quake2ZonePvsResult q = quake2::write_quake2_zone_pvs(bytes, path, zone, pvs, options.phs);
        write_whole_file(out_path, q.map);
        char line[160];
        std::snprintf(line, sizeof line, ": %u clusters (the leaves' rows ORed per cluster), mean %.1f visible, %.1f hearable",
                      q.clusters, q.mean_visible, q.mean_hearable);
        return {line, {}, quake2::quake2_written_fields(q.clusters, q.mean_visible, q.mean_hearable, options.phs)};
    }
    if (doom::looks_like_wad(bytes))
        return write_gl_pvs_of(zone, load, pvs, out_path);
    if (eq::looks_like_pfs(bytes)) {
        Zone copy = zone;
        copy.baked_pvs = pvs;
        PvsWriteback out;
        out.notes = write_zone(copy, out_path, ZoneOutput::S3d);
        return out;
    }
    throw FileError(path, 0, "cannot write a PVS back into this format");
}

} // namespace

PvsWriteback write_pvs_in_zone_format(const Zone& zone, const ZoneLoadOptions& load, const Pvs& pvs,
                                      const std::string& out_path, const PvsWriteOptions& options)
{
    PvsWriteback written = write_in_zone_format(zone, load, pvs, out_path, options);
    written.summary = "wrote " + (options.shown_path.empty() ? out_path : options.shown_path) + written.summary;
    return written;
}

} // namespace pvs
