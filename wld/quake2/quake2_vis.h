// Quake 2's vis on a map: the PVS over clusters from the portal file qbsp wrote beside it (PRT1,
// whose "leaves" are the map's clusters), the PHS made from it (phs.h), both written into the
// visibility lump (ibsp38_writer.h); every other lump's bytes unchanged. With `phs_only`, the map's
// own PVS is kept and only the PHS is made again (ericw's -phsonly).
//
// Which PHS: PhsRule::Quake2 by default (what the engine reads it for: every cluster a sound in a
// cluster of the PVS could be heard from; id's qvis3); PhsRule::EricwTools writes what today's
// ericw-tools vis writes (a subset: phs.h says why), byte for byte. Library code: throws FileError
// for a map or portal file it cannot use, never prints; a cancelled bake returns no bytes.
#pragma once

#include "visibility/methods/report_field.h"
#include "visibility/portal/portal_vis.h"
#include "wld/quake/prt_file.h"
#include "visibility/zone.h"
#include "wld/quake2/phs.h"

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace pvs::quake2 {

struct Quake2VisOptions {
    VisParams vis;                    // method, level, threads, progress
    PhsRule phs = PhsRule::Quake2;
    bool phs_only = false;            // keep the map's PVS, make the PHS again
};

struct Quake2VisResult {
    std::vector<uint8_t> map;         // the vised map (empty when cancelled)
    uint32_t clusters = 0;
    double mean_visible = 0.0;        // PVS bits per cluster
    double mean_hearable = 0.0;       // PHS bits per cluster
    VisReport report;                 // the bake's (nothing baked with phs_only)
    bool cancelled = false;
};

// `prt`: the portal file (unused with phs_only; its leaf count must be the map's cluster count).
// What a Quake 2 PVS and PHS as written hold, for reports (report_field.h): "clusters" (the map's
// cluster count), "mean_visible" and "mean_hearable" (clusters per cluster row of the PVS and the
// PHS: the rows the engine reads) and "phs_rule" (quake2 or ericw).
std::vector<ReportField> quake2_written_fields(uint32_t clusters, double mean_visible, double mean_hearable,
                                               PhsRule phs);

Quake2VisResult vis_quake2_map(std::span<const uint8_t> map, const std::string& file, const quake::PrtFile* prt,
                               const std::string& prt_file, const Quake2VisOptions& options);

// A PVS over the map's zone (its leaves: ibsp38_zone.h), as `pvscope bake` makes it, written as
// Quake 2 rows: a cluster's row holds every cluster that one of its leaves sees (the leaves'
// rows ORed: what the engine reads per cluster), with the PHS made from them. `zone` is the map
// loaded with load_ibsp38 (its leaves give the regions' clusters). Every other lump's bytes
// unchanged. Throws FileError for a map it cannot read, std::invalid_argument for a PVS of
// another size than the zone's.
struct Quake2ZonePvsResult {
    std::vector<uint8_t> map;
    uint32_t clusters = 0;
    double mean_visible = 0.0, mean_hearable = 0.0; // per cluster
};
Quake2ZonePvsResult write_quake2_zone_pvs(std::span<const uint8_t> map, const std::string& file, const Zone& zone,
                                          const Pvs& pvs, PhsRule phs = PhsRule::Quake2);

// The cluster of each region of `zone` (the map loaded with load_ibsp38), from the map's leaves,
// and the map's cluster count: what a Quake 2 portal file (PRT1 over clusters) needs to be baked
// as clusters of the zone's leaves. Throws FileError when a region has no cluster or the map's
// leaves are not the zone's.
struct RegionClusterMap {
    std::vector<int32_t> cluster_of_region;
    uint32_t clusters = 0;
};
RegionClusterMap region_clusters(std::span<const uint8_t> map, const std::string& file, const Zone& zone);

} // namespace pvs::quake2
