#include "visibility/portal/cluster_vis.h"

#include "visibility/bit_row.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

namespace pvs {
namespace {

void validate_cluster_map(std::span<const uint32_t> cluster_of_region, uint32_t cluster_count)
{
    if (cluster_count == 0 && !cluster_of_region.empty())
        throw std::invalid_argument("bake_clustered_portal_vis: cluster_count is 0 but " +
                                    std::to_string(cluster_of_region.size()) + " regions need a cluster");
    for (size_t r = 0; r < cluster_of_region.size(); ++r)
        if (cluster_of_region[r] >= cluster_count)
            throw std::invalid_argument("bake_clustered_portal_vis: region " + std::to_string(r) + " has cluster " +
                                        std::to_string(cluster_of_region[r]) + ", out of range [0, " +
                                        std::to_string(cluster_count) + ")");
}

void validate_portal_regions(const PortalSet& portals, size_t region_count)
{
    for (size_t i = 0; i < portals.portals.size(); ++i)
        for (int32_t region : portals.portals[i].regions)
            if (region >= 0 && size_t(region) >= region_count)
                throw std::invalid_argument("bake_clustered_portal_vis: portal " + std::to_string(i) + " names region " +
                                            std::to_string(region) + " but the cluster map covers " +
                                            std::to_string(region_count) + " regions");
}

// The portals between clusters: same points, sides renamed to clusters, inside portals dropped.
// A negative side stays -1, which bake_portal_vis skips and counts.
PortalSet cluster_portals(const PortalSet& region_portals, std::span<const uint32_t> cluster_of_region,
                          size_t& inside)
{
    const auto cluster_of = [&](int32_t region) -> int32_t {
        return region >= 0 ? int32_t(cluster_of_region[size_t(region)]) : -1; // validated: in range
    };
    PortalSet out;
    out.points = region_portals.points;
    out.portals.reserve(region_portals.portals.size());
    inside = 0;
    for (const Portal& portal : region_portals.portals) {
        Portal mapped = portal;
        mapped.regions[0] = cluster_of(portal.regions[0]);
        mapped.regions[1] = cluster_of(portal.regions[1]);
        if (mapped.regions[0] >= 0 && mapped.regions[0] == mapped.regions[1]) {
            ++inside;
            continue;
        }
        out.portals.push_back(mapped);
    }
    return out;
}

// Each cluster's regions as (word index, bit mask) pairs, in word order: a cluster's part of a
// region row. Stored flat: cluster c's pairs are [first[c], first[c+1]).
struct ClusterMasks {
    std::vector<uint32_t> first;
    std::vector<uint32_t> word;
    std::vector<uint64_t> mask;
};

ClusterMasks cluster_masks(std::span<const uint32_t> cluster_of_region, uint32_t cluster_count)
{
    // Counting sort of the regions by cluster keeps each cluster's regions in increasing order.
    std::vector<uint32_t> start(size_t{cluster_count} + 1, 0);
    for (uint32_t c : cluster_of_region)
        ++start[size_t{c} + 1];
    for (size_t c = 0; c < cluster_count; ++c)
        start[c + 1] += start[c];
    std::vector<uint32_t> members(cluster_of_region.size());
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t r = 0; r < cluster_of_region.size(); ++r)
        members[fill[cluster_of_region[r]]++] = uint32_t(r);

    ClusterMasks masks;
    masks.first.reserve(size_t{cluster_count} + 1);
    for (size_t c = 0; c < cluster_count; ++c) {
        masks.first.push_back(uint32_t(masks.word.size()));
        for (uint32_t i = start[c]; i < start[c + 1]; ++i) {
            const uint32_t word = members[i] >> 6;
            const uint64_t bit = uint64_t{1} << (members[i] & 63);
            if (masks.first.back() < masks.word.size() && masks.word.back() == word) // this cluster's last word
                masks.mask.back() |= bit;
            else {
                masks.word.push_back(word);
                masks.mask.push_back(bit);
            }
        }
    }
    masks.first.push_back(uint32_t(masks.word.size()));
    return masks;
}

// Region row of cluster `cluster`: the OR of the masks of every cluster its row holds. `row` is
// zeroed on entry; `cluster_row` is scratch of the cluster Pvs's row size.
void expand_row(const Pvs& clusters, const ClusterMasks& masks, uint32_t cluster, std::span<uint64_t> cluster_row,
                std::span<uint64_t> row)
{
    clusters.decode_row(cluster, cluster_row);
    bits::for_each_set(cluster_row, [&](size_t seen) {
        for (uint32_t i = masks.first[seen]; i < masks.first[seen + 1]; ++i)
            row[masks.word[i]] |= masks.mask[i];
    });
}

} // namespace

PortalSet cluster_portal_set(const PortalSet& region_portals, std::span<const uint32_t> cluster_of_region,
                             uint32_t cluster_count, size_t* portals_inside_clusters)
{
    validate_cluster_map(cluster_of_region, cluster_count);
    validate_portal_regions(region_portals, cluster_of_region.size());
    size_t inside = 0;
    PortalSet portals = cluster_portals(region_portals, cluster_of_region, inside);
    if (portals_inside_clusters)
        *portals_inside_clusters = inside;
    return portals;
}

Pvs bake_cluster_portal_vis(const PortalSet& cluster_portals, std::span<const uint32_t> cluster_of_region,
                            uint32_t cluster_count, const VisParams& params, VisReport* report,
                            ClusterReport* cluster_report)
{
    const auto start = std::chrono::steady_clock::now();
    validate_cluster_map(cluster_of_region, cluster_count);
    const uint32_t region_count = uint32_t(cluster_of_region.size());
    VisReport vis;
    const Pvs clusters = bake_portal_vis(cluster_portals, cluster_count, params, &vis);

    const auto expand_start = std::chrono::steady_clock::now();
    const ClusterMasks masks = cluster_masks(cluster_of_region, cluster_count);
    std::vector<uint64_t> cluster_row(clusters.words_per_row());
    std::vector<uint64_t> expanded(bits::words_for(region_count));
    int64_t expanded_cluster = -1; // the cluster whose region row `expanded` holds
    size_t expanded_count = 0;     // and its bits
    size_t visible_total = 0;
    Pvs result = Pvs::build(region_count, [&](uint32_t region, std::span<uint64_t> row) {
        const uint32_t cluster = cluster_of_region[region];
        if (expanded_cluster != int64_t{cluster}) {
            std::fill(expanded.begin(), expanded.end(), 0);
            expand_row(clusters, masks, cluster, cluster_row, expanded);
            expanded_cluster = cluster;
            expanded_count = bits::count(expanded);
        }
        std::copy(expanded.begin(), expanded.end(), row.begin());
        visible_total += expanded_count;
        return true;
    });
    const auto end = std::chrono::steady_clock::now();

    if (report) {
        *report = vis;
        report->seconds = std::chrono::duration<double>(end - start).count();
        report->mean_visible = region_count ? double(visible_total) / double(region_count) : 0.0;
        const size_t expand_bytes = masks.word.size() * (sizeof(uint32_t) + sizeof(uint64_t)) +
                                    masks.first.size() * sizeof(uint32_t) + result.memory_bytes() +
                                    clusters.memory_bytes();
        report->peak_bytes_estimate = std::max(vis.peak_bytes_estimate, expand_bytes);
    }
    if (cluster_report) {
        *cluster_report = ClusterReport{};
        cluster_report->regions = region_count;
        cluster_report->clusters = cluster_count;
        cluster_report->cluster_portals = cluster_portals.portals.size();
        cluster_report->cluster_mean_visible = vis.mean_visible;
        cluster_report->expand_seconds = std::chrono::duration<double>(end - expand_start).count();
    }
    return result;
}

Pvs bake_clustered_portal_vis(const PortalSet& region_portals, std::span<const uint32_t> cluster_of_region,
                              uint32_t cluster_count, const VisParams& params, VisReport* report,
                              ClusterReport* cluster_report)
{
    const auto start = std::chrono::steady_clock::now();
    size_t inside = 0;
    const PortalSet portals = cluster_portal_set(region_portals, cluster_of_region, cluster_count, &inside);
    Pvs result = bake_cluster_portal_vis(portals, cluster_of_region, cluster_count, params, report, cluster_report);
    if (report) {
        report->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        // The cluster portals live through the bake and the expansion.
        report->peak_bytes_estimate +=
            portals.points.size() * sizeof(glm::vec3) + portals.portals.size() * sizeof(Portal);
    }
    if (cluster_report) {
        cluster_report->region_portals = region_portals.portals.size();
        cluster_report->portals_inside_clusters = inside;
    }
    return result;
}

} // namespace pvs
