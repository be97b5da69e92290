// A Quake 2 map's PVS and PHS as written: a PVS baked over the map's zone (by any method of the
// registry; qbsp's portal file bakes it over the map's clusters) written as the cluster rows the
// engine reads, with the PHS made from them (phs.h), both into the visibility lump
// (ibsp38_writer.h); every other lump's bytes unchanged. Or the map's own PVS kept and only the
// PHS made again (ericw's -phsonly).
//
// Which PHS: PhsRule::Quake2 by default (what the engine reads it for: every cluster a sound in a
// cluster of the PVS could be heard from; id's qvis3); PhsRule::EricwTools writes what today's
// ericw-tools vis writes (a subset: phs.h says why), byte for byte. Library code: throws FileError
// for a map it cannot use, never prints.
#pragma once

#include "visibility/methods/report_field.h"
#include "visibility/pvs.h"
#include "visibility/zone.h"
#include "wld/quake2/phs.h"

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace pvs::quake2 {

// What a Quake 2 PVS and PHS as written hold, for reports (report_field.h): "clusters" (the map's
// cluster count), "mean_visible" and "mean_hearable" (clusters per cluster row of the PVS and the
// PHS: the rows the engine reads) and "phs_rule" (quake2 or ericw).
std::vector<ReportField> quake2_written_fields(uint32_t clusters, double mean_visible, double mean_hearable,
                                               PhsRule phs);

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

// The map's own PVS rows kept, the PHS made again from them by `phs` (vis --phs-only). Throws
// FileError when the map has no PVS.
Quake2ZonePvsResult remake_quake2_phs(std::span<const uint8_t> map, const std::string& file, PhsRule phs);

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
