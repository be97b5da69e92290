// Passages (passages.h): the rows, their flood (FlowWorker::passage_row, which clips with the
// flow's frame and scratch) and the narrowing of mightsee.
#include "visibility/portal/passages.h"

#include "visibility/bit_row.h"
#include "visibility/portal/flow.h"
#include "visibility/portal/separators.h"
#include "visibility/portal/vis_progress.h"
#include "visibility/worker_pool.h"

#include <algorithm>
#include <span>

namespace pvs::portal_vis {

void encode_passage_row(std::span<const uint64_t> dense, std::vector<uint64_t>& out)
{
    uint32_t lo = 0, hi = uint32_t(dense.size());
    while (lo < hi && dense[lo] == 0)
        ++lo;
    while (hi > lo && dense[hi - 1] == 0)
        --hi;
    if (lo == hi) { // empty: a narrow row with no word
        out.push_back(0);
        return;
    }
    if (hi - lo <= kPassageMaskSpan && lo < (uint32_t{1} << 24)) {
        const size_t header = out.size();
        out.push_back(0);
        uint64_t mask = 0;
        for (uint32_t w = lo; w < hi; ++w)
            if (dense[w] != 0) {
                mask |= uint64_t{1} << (w - lo);
                out.push_back(dense[w]);
            }
        out[header] = uint64_t{lo} | mask << 24;
        return;
    }
    out.push_back(kPassageWide | uint64_t{lo} | uint64_t{hi} << 31);
    out.insert(out.end(), dense.begin() + lo, dense.begin() + hi);
}

void narrow_mightsee(const Graph& g, const Passages& passages, std::vector<RunRow>& mightsee, RowPool& pool)
{
    const size_t words = g.words;
    std::vector<uint64_t> reach(words), might(words), encoded;
    for (uint32_t a = 0; a < uint32_t(g.portals.size()); ++a) {
        std::fill(reach.begin(), reach.end(), 0);
        bits::set(reach, g.portals[a].leaf);
        for (size_t k = 0; k < passages.first[a + 1] - passages.first[a]; ++k) {
            passages.row(a, k).or_into(reach.data());
        }
        std::fill(might.begin(), might.end(), 0);
        mightsee[a].or_into(might.data());
        for (size_t w = 0; w < words; ++w)
            might[w] &= reach[w];
        encode_runs(might, encoded);
        mightsee[a] = pool.append(encoded);
    }
}

// A row: a flood from b's leaf through the portals that survive a's plane, b's plane and the
// separators between a and b (b clipped to the front of a), within a.mightsee & b.mightsee.
void FlowWorker::passage_row(uint32_t ai, uint32_t k, const uint64_t* ma, const uint64_t* mb, uint64_t* out)
{
    const size_t words = g_.words;
    std::fill(out, out + words, 0);
    const DirectedPortal& a = g_.portals[ai];
    const uint32_t bi = g_.leaf_portals[g_.leaf_first[a.leaf] + k];
    const DirectedPortal& b = g_.portals[bi];
    if (bi == (ai ^ 1u))
        return;
    Frame& f = frame(0);
    for (bool& used : f.slot_used)
        used = false;
    if (normals_equal(a.plane.normal, -b.plane.normal))
        return;
    const WRef bw = clip(portal_winding(bi), a.plane, f);
    if (!bw)
        return;
    bits::set(std::span<uint64_t>(out, words), b.leaf);
    const WRef aw = portal_winding(ai);
    std::vector<DPlane>& planes = passage_planes_;
    planes.clear();
    const auto keep = [&](const DPlane& sep) {
        planes.push_back(sep);
        return true;
    };
    if (level_ > 0) // test 0: a -> b
        for_each_separator(aw, a.plane, bw, false, b_side_.data(), keep);
    if (level_ > 1) // test 1: b -> a, mirrored
        for_each_separator(bw, b.plane, aw, true, b_side_.data(), keep);
    // Flood from b's leaf through the portals a line through a and b can cross.
    std::vector<uint32_t>& stack = passage_stack_;
    stack.clear();
    stack.push_back(b.leaf);
    const std::span<uint64_t> row(out, words);
    while (!stack.empty()) {
        const uint32_t y = stack.back();
        stack.pop_back();
        for (uint32_t o = g_.leaf_first[y]; o < g_.leaf_first[y + 1]; ++o) {
            const uint32_t ri = g_.leaf_portals[o];
            const DirectedPortal& r = g_.portals[ri];
            const uint32_t x = r.leaf;
            if (bits::test(row, x) || !bits::test(std::span<const uint64_t>(ma, words), x) ||
                !bits::test(std::span<const uint64_t>(mb, words), x))
                continue;
            // Spheres first: one dot product per plane.
            bool behind = false, inside = true;
            auto sphere = [&](const DPlane& pl) {
                const double c = pl.distance(r.origin);
                behind |= c < -r.radius;
                inside &= c > r.radius;
            };
            sphere(a.plane);
            sphere(b.plane);
            for (size_t pl = 0; pl < planes.size() && !behind; ++pl)
                sphere(planes[pl]);
            if (behind)
                continue;
            bool seen = inside;
            if (!seen) {
                for (int s2 = 0; s2 < kStackWindings; ++s2)
                    f.slot_used[s2] = s2 == bw.slot && bw.owner == &f;
                WRef w = clip(portal_winding(ri), a.plane, f);
                w = clip(w, b.plane, f);
                for (size_t pl = 0; pl < planes.size() && w; ++pl)
                    w = clip(w, planes[pl], f);
                seen = bool(w);
            }
            if (!seen)
                continue;
            bits::set(row, x);
            stack.push_back(x);
        }
    }
}

namespace {

constexpr uint32_t kSampleStride = 64; // every 64th portal's rows estimate the whole

// One builder's scratch and the loop over a portal's pairs, shared by the sample and the build.
struct RowBuilder {
    FlowWorker worker;
    std::vector<uint64_t> dense, ma, mb;

    RowBuilder(const Graph& g, int level) : worker(g, level), dense(g.words), ma(g.words), mb(g.words) {}

    // Appends the encoded rows of directed portal a's `pairs` pairs to `packed`; starts[k], when
    // given, receives the offset in `packed` of pair k's row.
    void append_rows(const Graph& g, const std::vector<RunRow>& mightsee, uint32_t a, size_t pairs,
                     std::vector<uint64_t>& packed, uint32_t* starts)
    {
        std::fill(ma.begin(), ma.end(), 0);
        mightsee[a].or_into(ma.data());
        const uint32_t first_leaving = g.leaf_first[g.portals[a].leaf];
        for (size_t k = 0; k < pairs; ++k) {
            std::fill(mb.begin(), mb.end(), 0);
            mightsee[g.leaf_portals[first_leaving + k]].or_into(mb.data());
            worker.passage_row(a, uint32_t(k), ma.data(), mb.data(), dense.data());
            if (starts)
                starts[k] = uint32_t(packed.size());
            encode_passage_row(dense, packed);
        }
    }
};

// Whether the rows of every kSampleStride-th portal, times kSampleStride, take more than `limit`
// words: an estimate of all the rows' words from a fixed sample (built on this thread, so it
// does not depend on the threads). The sum only grows, so the sample stops as soon as it passes
// the limit: the answer is the whole sample's.
bool sample_exceeds(const Graph& g, int level, const std::vector<RunRow>& mightsee, const std::vector<size_t>& first,
                    size_t limit)
{
    RowBuilder builder(g, level);
    std::vector<uint64_t> packed;
    for (uint32_t a = 0; a < uint32_t(g.portals.size()); a += kSampleStride) {
        builder.append_rows(g, mightsee, a, first[a + 1] - first[a], packed, nullptr);
        if (packed.size() * kSampleStride > limit)
            return true;
    }
    return false;
}

} // namespace

bool build_passages(const Graph& g, int level, std::vector<RunRow>& mightsee, RowPool& narrowed, size_t budget,
                    unsigned threads, std::atomic<bool>& cancel, std::atomic<bool>& user_cancel,
                    const std::function<bool(double)>& progress, Passages& out)
{
    const auto n = uint32_t(g.portals.size());
    if (n == 0)
        return false;
    out.first.assign(size_t{n} + 1, 0);
    for (uint32_t a = 0; a < n; ++a) {
        const uint32_t leaf = g.portals[a].leaf;
        out.first[a + 1] = out.first[a] + (g.leaf_first[leaf + 1] - g.leaf_first[leaf]);
    }
    const size_t pairs = out.first[n];
    const size_t fixed_bytes = out.first.size() * sizeof(size_t) + pairs * sizeof(uint32_t);
    if (fixed_bytes > budget) {
        out = {};
        return false;
    }
    out.start.assign(pairs, 0);
    out.block.assign(n, nullptr);
    out.pools.resize(threads);
    // (the per-portal block pointers are not counted: the decision stays what it was when the
    // rows were one array)
    const size_t word_budget = std::min<size_t>((budget - fixed_bytes) / sizeof(uint64_t), UINT32_MAX);
    // Rows far over the budget are found out before they are all built: when a fixed sample
    // extrapolates to more than twice the budget, no passages. At 5000 rooms the build used to
    // run until the budget stopped it: 2.8 s of two threads and 64 MB at the bake's peak, for
    // nothing. Within twice the budget, the rows' real size decides, as before.
    if (n / kSampleStride >= 16 && sample_exceeds(g, level, mightsee, out.first, 2 * word_budget)) {
        out = {};
        return false;
    }
    std::atomic<size_t> total_words{0};
    std::atomic<bool> over_budget{false};
    std::atomic<uint32_t> next_portal{0}, portals_done{0};
    const bool kept_going = run_workers(
        threads,
        [&](unsigned t) {
            RowBuilder builder(g, level);
            std::vector<uint64_t> packed;
            while (!cancel.load(std::memory_order_relaxed) && !over_budget.load(std::memory_order_relaxed)) {
                const uint32_t a = next_portal.fetch_add(1);
                if (a >= n)
                    break;
                packed.clear();
                builder.append_rows(g, mightsee, a, out.first[a + 1] - out.first[a], packed, &out.start[out.first[a]]);
                if (total_words.fetch_add(packed.size()) + packed.size() > word_budget) {
                    over_budget.store(true);
                    break;
                }
                out.block[a] = out.pools[t].append_words(packed);
                portals_done.fetch_add(1, std::memory_order_relaxed);
            }
        },
        cancel, progress,
        [&] { return kBaseWeight + kPassageWeight * double(portals_done.load()) / double(n); });
    if (!kept_going)
        user_cancel.store(true);
    if (cancel.load() || over_budget.load()) {
        out = {};
        return false;
    }
    narrow_mightsee(g, out, mightsee, narrowed);
    return true;
}

} // namespace pvs::portal_vis
