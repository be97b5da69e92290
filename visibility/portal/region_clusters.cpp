#include "visibility/portal/region_clusters.h"

#include <algorithm>
#include <utility>

namespace pvs {
namespace {

// What a subtree holds, for deciding whether it is one cluster.
struct SubtreeSummary {
    uint32_t open_leaves = 0;
    bool closed = false;   // holds a solid or outside leaf (or a region id out of range)
    uint8_t media = 0;     // bit 0: a non-sky open leaf, bit 1: a sky open leaf
};

class ClusterBuilder {
public:
    ClusterBuilder(const BspTree& tree, const std::vector<Region>& regions, const ClusterOptions& options)
        : tree_(tree), regions_(regions), options_(options), union_(regions.size())
    {
    }

    RegionClusters run()
    {
        if (valid_child(tree_.root)) {
            summarise();
            group();
        }
        return union_.clusters();
    }

private:
    bool valid_child(int32_t child) const
    {
        return BspTree::is_leaf(child) ? size_t(BspTree::leaf_index(child)) < tree_.leaf_region.size()
                                       : size_t(child) < tree_.nodes.size();
    }

    // Region id of an open leaf, or -1.
    int32_t leaf_region(int32_t child) const
    {
        const int32_t region = tree_.leaf_region[size_t(BspTree::leaf_index(child))];
        return region >= 0 && size_t(region) < regions_.size() ? region : -1;
    }

    SubtreeSummary leaf_summary(int32_t child) const
    {
        SubtreeSummary s;
        const int32_t region = leaf_region(child);
        if (region < 0) {
            s.closed = true;
            return s;
        }
        s.open_leaves = 1;
        s.media = (regions_[size_t(region)].flags & kRegionSky) ? 2 : 1;
        return s;
    }

    SubtreeSummary child_summary(int32_t child) const
    {
        if (!valid_child(child))
            return SubtreeSummary{0, true, 0};
        return BspTree::is_leaf(child) ? leaf_summary(child) : node_summary_[size_t(child)];
    }

    // Post-order over the nodes the root reaches, each once (explicit stack).
    void summarise()
    {
        node_summary_.assign(tree_.nodes.size(), SubtreeSummary{});
        std::vector<uint8_t> state(tree_.nodes.size(), 0); // 0 unseen, 1 children pending, 2 done
        std::vector<int32_t> stack;
        if (!BspTree::is_leaf(tree_.root))
            stack.push_back(tree_.root);
        while (!stack.empty()) {
            const int32_t node = stack.back();
            if (state[size_t(node)] == 0) {
                state[size_t(node)] = 1;
                for (int32_t child : tree_.nodes[size_t(node)].children)
                    if (!BspTree::is_leaf(child) && valid_child(child) && state[size_t(child)] == 0)
                        stack.push_back(child);
                continue;
            }
            stack.pop_back();
            if (state[size_t(node)] == 2)
                continue;
            state[size_t(node)] = 2;
            SubtreeSummary& s = node_summary_[size_t(node)];
            for (int32_t child : tree_.nodes[size_t(node)].children) {
                const SubtreeSummary c = child_summary(child);
                s.open_leaves += c.open_leaves;
                s.closed = s.closed || c.closed;
                s.media = uint8_t(s.media | c.media);
            }
        }
    }

    bool is_cluster(const SubtreeSummary& s) const
    {
        return (options_.allow_walls || !s.closed) && s.media != 3 && s.open_leaves > 0 &&
               (options_.max_regions == 0 || s.open_leaves <= options_.max_regions);
    }

    // Top-down: the first subtree on each path that is a cluster becomes one.
    void group()
    {
        std::vector<uint8_t> seen(tree_.nodes.size(), 0);
        std::vector<int32_t> stack{tree_.root};
        while (!stack.empty()) {
            const int32_t child = stack.back();
            stack.pop_back();
            if (!valid_child(child) || BspTree::is_leaf(child))
                continue; // an open leaf not inside a cluster stays its own
            if (seen[size_t(child)])
                continue;
            if (is_cluster(node_summary_[size_t(child)])) {
                join_subtree(child, seen);
                continue;
            }
            seen[size_t(child)] = 1;
            for (int32_t c : tree_.nodes[size_t(child)].children)
                stack.push_back(c);
        }
    }

    void join_subtree(int32_t top, std::vector<uint8_t>& seen)
    {
        int32_t first = -1;
        std::vector<int32_t> stack{top};
        while (!stack.empty()) {
            const int32_t child = stack.back();
            stack.pop_back();
            if (!valid_child(child))
                continue;
            if (BspTree::is_leaf(child)) {
                const int32_t region = leaf_region(child);
                if (region < 0)
                    continue;
                if (first < 0)
                    first = region;
                else
                    union_.unite(uint32_t(first), uint32_t(region));
                continue;
            }
            if (seen[size_t(child)])
                continue;
            seen[size_t(child)] = 1;
            for (int32_t c : tree_.nodes[size_t(child)].children)
                stack.push_back(c);
        }
    }

    const BspTree& tree_;
    const std::vector<Region>& regions_;
    ClusterOptions options_;
    RegionUnion union_;
    std::vector<SubtreeSummary> node_summary_;
};

} // namespace

RegionClusters bsp_subtree_clusters(const BspTree& tree, const std::vector<Region>& regions,
                                    const ClusterOptions& options)
{
    return ClusterBuilder(tree, regions, options).run();
}

} // namespace pvs
