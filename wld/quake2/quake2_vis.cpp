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

} // namespace

Quake2VisResult vis_quake2_map(std::span<const uint8_t> map, const std::string& file, const quake::PrtFile* prt,
                               const std::string& prt_file, const Quake2VisOptions& options)
{
    const Ibsp38File parsed = read_ibsp38(map, file);
    Quake2VisResult result;
    std::vector<uint64_t> pvs_rows;
    if (options.phs_only) {
        if (parsed.clusters == 0)
            throw FileError(file, parsed.lumps[kQ2LumpVisibility].offset,
                            "--phs-only: the map has no PVS to make the PHS from (run vis first)");
        result.clusters = parsed.clusters;
        pvs_rows = parsed.pvs_rows;
    } else {
        const uint32_t clusters = leaf_clusters(parsed);
        if (!prt)
            throw FileError(file, 0, "no portal file to bake the PVS from");
        if (prt->has_clusters())
            throw FileError(prt_file, 0, "a Quake 2 map's portal file is PRT1 over its clusters, not PRT2 / PRT1-AM");
        if (prt->leaf_count != clusters)
            throw FileError(prt_file, 0, "the portal file has " + std::to_string(prt->leaf_count) +
                                             " leaves but the map has " + std::to_string(clusters) +
                                             " clusters: not this map's portals");
        result.clusters = clusters;
        const Pvs pvs = bake_portal_vis(prt->portals, clusters, options.vis, &result.report);
        if (result.report.cancelled) {
            result.cancelled = true;
            return result;
        }
        const size_t words = bits::words_for(clusters);
        pvs_rows.assign(size_t(clusters) * words, 0);
        for (uint32_t c = 0; c < clusters; ++c)
            pvs.decode_row(c, std::span(pvs_rows).subspan(size_t(c) * words, words));
    }
    const std::vector<uint64_t> phs_rows = compute_phs(pvs_rows, result.clusters, options.phs);
    result.mean_visible = mean_bits(pvs_rows, result.clusters);
    result.mean_hearable = mean_bits(phs_rows, result.clusters);
    result.map = with_visibility_lump(map, encode_visibility_lump(pvs_rows, phs_rows, result.clusters), file);
    return result;
}

} // namespace pvs::quake2
