#include "wld/quake2/quake2_vis.h"

#include "visibility/bit_row.h"
#include "visibility/file_error.h"
#include "wld/quake2/ibsp38_file.h"
#include "wld/quake2/ibsp38_writer.h"

#include <algorithm>

namespace pvs::quake2 {
namespace {

// The map's cluster count from its leaves (an unvised map's visibility lump is empty).
uint32_t leaf_clusters(const Ibsp38File& f)
{
    int32_t highest = -1;
    for (const Q2Leaf& leaf : f.leaves)
        highest = std::max<int32_t>(highest, leaf.cluster);
    return uint32_t(highest + 1);
}

double mean_bits(std::span<const uint64_t> rows, uint32_t clusters)
{
    return clusters ? double(bits::count(rows)) / double(clusters) : 0.0;
}

RegionClusterMap region_clusters(const Ibsp38File& parsed, const std::string& file, const Zone& zone)
{
    if (zone.tree.leaf_region.size() != parsed.leaves.size())
        throw FileError(file, parsed.lumps[kQ2LumpLeafs].offset, "the map's leaves are not those of the zone given");
    RegionClusterMap result;
    result.clusters = leaf_clusters(parsed);
    result.cluster_of_region.assign(zone.region_count(), -1);
    for (size_t leaf = 0; leaf < parsed.leaves.size(); ++leaf)
        if (const int32_t r = zone.tree.leaf_region[leaf]; r >= 0 && size_t(r) < zone.region_count())
            result.cluster_of_region[size_t(r)] = parsed.leaves[leaf].cluster;
    for (uint32_t r = 0; r < zone.region_count(); ++r) // every region's cluster, before any row uses it
        if (const int32_t c = result.cluster_of_region[r]; c < 0 || uint32_t(c) >= result.clusters)
            throw FileError(file, parsed.lumps[kQ2LumpLeafs].offset, "region " + std::to_string(r) + " has no cluster");
    return result;
}

} // namespace

Quake2ZonePvsResult remake_quake2_phs(std::span<const uint8_t> map, const std::string& file, PhsRule phs)
{
    const Ibsp38File parsed = read_ibsp38(map, file);
    if (parsed.clusters == 0)
        throw FileError(file, parsed.lumps[kQ2LumpVisibility].offset,
                        "--phs-only: the map has no PVS to make the PHS from (run vis first)");
    const std::vector<uint64_t> hearable = compute_phs(parsed.pvs_rows, parsed.clusters, phs);
    Quake2ZonePvsResult result;
    result.map = with_visibility_lump(map, encode_visibility_lump(parsed.pvs_rows, hearable, parsed.clusters), file);
    result.clusters = parsed.clusters;
    result.mean_visible = mean_bits(parsed.pvs_rows, parsed.clusters);
    result.mean_hearable = mean_bits(hearable, parsed.clusters);
    return result;
}

Quake2ZonePvsResult write_quake2_zone_pvs(std::span<const uint8_t> map, const std::string& file, const Zone& zone,
                                          const Pvs& pvs, PhsRule phs)
{
    const Ibsp38File parsed = read_ibsp38(map, file);
    if (pvs.region_count() != zone.region_count())
        throw std::invalid_argument("a PVS of " + std::to_string(pvs.region_count()) + " regions for a zone of " +
                                    std::to_string(zone.region_count()));
    const RegionClusterMap map_clusters = region_clusters(parsed, file, zone);
    const uint32_t clusters = map_clusters.clusters;
    const std::vector<int32_t>& cluster_of = map_clusters.cluster_of_region;
    const size_t words = bits::words_for(clusters);
    std::vector<uint64_t> rows(size_t(clusters) * words, 0);
    for (uint32_t c = 0; c < clusters; ++c)
        bits::set(std::span<uint64_t>(rows.data() + c * words, words), c); // a cluster sees itself
    std::vector<uint64_t> row(pvs.words_per_row());
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        pvs.decode_row(r, row);
        const std::span<uint64_t> out(rows.data() + size_t(cluster_of[r]) * words, words);
        bits::for_each_set(std::span<const uint64_t>(row), [&](size_t s) {
            if (s < cluster_of.size()) // a row's padding bits past the last region name nothing
                bits::set(out, uint32_t(cluster_of[s]));
        });
    }
    const std::vector<uint64_t> hearable = compute_phs(rows, clusters, phs);
    Quake2ZonePvsResult result;
    result.map = with_visibility_lump(map, encode_visibility_lump(rows, hearable, clusters), file);
    result.clusters = clusters;
    result.mean_visible = mean_bits(rows, clusters);
    result.mean_hearable = mean_bits(hearable, clusters);
    return result;
}

RegionClusterMap region_clusters(std::span<const uint8_t> map, const std::string& file, const Zone& zone)
{
    return region_clusters(read_ibsp38(map, file), file, zone);
}

std::vector<ReportField> quake2_written_fields(uint32_t clusters, double mean_visible, double mean_hearable,
                                               PhsRule phs)
{
    return {{"clusters", uint64_t(clusters)},
            {"mean_visible", mean_visible},
            {"mean_hearable", mean_hearable},
            {"phs_rule", std::string(phs == PhsRule::EricwTools ? "ericw" : "quake2")}};
}

} // namespace pvs::quake2
