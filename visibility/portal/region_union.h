// A grouping of a zone's regions into clusters (what cluster_vis.h bakes over), and the
// union-find both groupings build one with (box_clusters.h, region_clusters.h).
// RegionUnion: path-halving find; joining two sets makes the lower id the root, so numbering the
// roots in region order numbers clusters by their lowest region id. Region ids are
// [0, size()); the caller checks ids from files before using them here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace pvs {

struct RegionClusters {
    std::vector<uint32_t> cluster_of_region; // one per zone region, in [0, cluster_count)
    uint32_t cluster_count = 0;
};

class RegionUnion {
public:
    explicit RegionUnion(std::size_t regions) : parent_(regions) { std::iota(parent_.begin(), parent_.end(), 0u); }

    std::size_t size() const { return parent_.size(); }

    uint32_t find(uint32_t r)
    {
        while (parent_[r] != r) {
            parent_[r] = parent_[parent_[r]];
            r = parent_[r];
        }
        return r;
    }

    // Joins two different roots; returns the root of the union (the lower id).
    uint32_t join_roots(uint32_t a, uint32_t b)
    {
        const uint32_t root = a < b ? a : b;
        parent_[a < b ? b : a] = root;
        return root;
    }

    void unite(uint32_t a, uint32_t b)
    {
        a = find(a);
        b = find(b);
        if (a != b)
            join_roots(a, b);
    }

    // The sets as clusters, numbered in order of their lowest region id.
    RegionClusters clusters()
    {
        constexpr uint32_t kNone = ~0u;
        RegionClusters out;
        out.cluster_of_region.resize(parent_.size());
        std::vector<uint32_t> id_of_root(parent_.size(), kNone);
        for (uint32_t r = 0; r < parent_.size(); ++r) {
            const uint32_t root = find(r);
            if (id_of_root[root] == kNone)
                id_of_root[root] = out.cluster_count++;
            out.cluster_of_region[r] = id_of_root[root];
        }
        return out;
    }

private:
    std::vector<uint32_t> parent_;
};

} // namespace pvs
