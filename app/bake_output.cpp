#include "app/bake_output.h"

#include "visibility/file_error.h"
#include "wld/common/read_file.h"
#include "wld/doom/gl_pvs_writer.h"
#include "wld/eq/eq_zone_reader.h"
#include "wld/pvs_edit_list.h"
#include "wld/pvs_writeback.h"
#include "wld/quake/prt_file.h"
#include "wld/quake2/quake2_vis.h"

#include <optional>

namespace pvs::app {

namespace {

// A Doom map's PVS as GL_PVS: into -o (a copy of the GL file: the .gwa, or the WAD holding the
// GL nodes, REJECT too with --reject), or with --in-place into the GL file itself with a backup.
void write_doom_output(const BakeOptions& o, const BakeInput& in, const Pvs& pvs, std::FILE* err)
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

} // namespace

std::vector<ReportField> write_bake_output(const BakeOptions& o, const BakeInput& in, const Pvs& pvs, std::FILE* err)
{
    if (in.format == ZoneFormat::DoomWad) {
        write_doom_output(o, in, pvs, err);
        return {};
    }
    // An S3D is written again from the whole zone: read it again if the bake let its drawing go.
    std::optional<Zone> reloaded;
    if (in.format == ZoneFormat::EqS3d && in.drawing_dropped) {
        reloaded = eq::load_eq_zone(read_whole_file(o.input), o.input);
        if (reloaded->region_count() != in.zone.region_count())
            throw FileError(o.input, 0,
                            "changed during the bake: " + std::to_string(reloaded->region_count()) + " regions now, " +
                                std::to_string(in.zone.region_count()) + " when it was read");
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
    return written.fields;
}

size_t apply_edit_list(const BakeOptions& o, Pvs& pvs, std::FILE* err)
{
    if (o.apply_edits.empty())
        return 0;
    const std::vector<PvsEdit> edits = read_edit_list(o.apply_edits, pvs.row_count(), pvs.region_count());
    pvs = apply_edits(pvs, edits);
    std::fprintf(err, "applied %zu edits from %s\n", edits.size(), o.apply_edits.c_str());
    return edits.size();
}

void write_portal_file(const std::string& path, const Zone& zone, const PortalInput& portals, std::FILE* err)
{
    quake::PrtFile prt;
    prt.leaf_count = uint32_t(zone.region_count());
    prt.portals = portals.portals;
    if (portals.clusters) {
        prt.version = quake::PrtVersion::Prt2;
        prt.cluster_count = portals.clusters->cluster_count;
        prt.cluster_of_leaf = portals.clusters->cluster_of_region;
    }
    quake::save_prt(path, prt);
    std::fprintf(err, "wrote %s: %s, %zu portals\n", path.c_str(), portals.clusters ? "PRT2" : "PRT1",
                 prt.portals.portals.size());
}

} // namespace pvs::app
