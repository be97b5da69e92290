// The portal-vis baker (portal_vis.h for the method, the determinism rule and the limits): the
// phases of a bake and the bake's shared state. One concept per file beside it:
//   portal_graph  directed portals, points, portals per region (input)
//   base_vis      each directed portal's mightsee (Method::Fast's rows)
//   passages      rows of the leaves a line through two portals can reach; mightsee narrowed
//   flow_order    the ranking and the rows a flow prunes with (determinism)
//   flow          the recursive portal flow on one thread (flow_frame: a frame and its clip;
//                 separators: ClipToSeparators' planes; target_checks: the dead-walk test)
//   vis_threads   worker threads, progress, cancellation
#include "visibility/portal/portal_vis.h"

#include "visibility/bit_row.h"
#include "visibility/portal/base_vis.h"
#include "visibility/portal/flow.h"
#include "visibility/portal/flow_order.h"
#include "visibility/portal/passages.h"
#include "visibility/portal/portal_graph.h"
#include "visibility/portal/vis_threads.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <vector>

namespace pvs {
namespace {

using namespace portal_vis;
using Clock = std::chrono::steady_clock;

// What the phases of one bake share: the graph, the rows and each portal's state.
struct Bake {
    const Graph& g;
    const VisParams& params;
    int level = 4;
    uint32_t n = 0;             // directed portals
    unsigned threads = 1;
    std::vector<uint64_t> mightsee; // n rows of g.words words
    std::vector<uint32_t> nummightsee;
    std::vector<uint64_t> visbits;  // Full only
    std::unique_ptr<std::atomic<uint8_t>[]> state;
    std::atomic<bool> cancel{false}, user_cancel{false};
    size_t worker_bytes = 0; // summed by the flow's workers under worker_bytes_mutex
    std::mutex worker_bytes_mutex;
    size_t passage_row_bytes = 0;

    Bake(const Graph& graph, const VisParams& p, int lvl, unsigned thread_count)
        : g(graph), params(p), level(lvl), n(uint32_t(graph.portals.size())), threads(thread_count),
          mightsee(size_t{n} * graph.words, 0), nummightsee(n, 0), state(new std::atomic<uint8_t>[n])
    {
        for (uint32_t i = 0; i < n; ++i)
            state[i].store(kNone, std::memory_order_relaxed);
    }
    uint64_t* mightsee_row(uint32_t i) { return &mightsee[size_t{i} * g.words]; }
};

// Base vis: every directed portal on its own. False when cancelled.
bool run_base_vis(Bake& b, bool full)
{
    std::atomic<uint32_t> next{0}, done{0};
    run_parallel(
        b.threads,
        [&](unsigned) {
            std::vector<uint32_t> stack;
            stack.reserve(b.g.leaf_count);
            while (!b.cancel.load(std::memory_order_relaxed)) {
                const uint32_t i = next.fetch_add(1);
                if (i >= b.n)
                    break;
                b.nummightsee[i] = base_portal_vis(b.g, i, stack, b.mightsee_row(i));
                done.fetch_add(1, std::memory_order_relaxed);
            }
        },
        b.cancel, b.user_cancel, b.params.progress,
        [&] { return (full ? kBaseWeight : 1.0) * double(done.load()) / double(std::max(b.n, 1u)); });
    return !b.cancel.load();
}

// The flow's counters, summed over its workers.
struct FlowTotals {
    std::atomic<uint64_t> wait_nanos{0};
    std::atomic<size_t> leaf_recursions{0};
    std::atomic<size_t> target_checks{0}, target_check_prunes{0};
};

// One worker of the flow: portals in rank order from `next` until none is left or the bake is
// cancelled; each finished portal's visbits are published through its state.
void flow_worker(Bake& b, const FlowOrder& order, const Passages* passages, std::atomic<uint32_t>& next,
                 std::atomic<uint64_t>& done_weight, FlowTotals& totals)
{
    FlowWorker worker(b.g, b.level);
    worker.use_target_checks(b.params.target_checks);
    if (passages != nullptr)
        worker.use_passages(passages);
    const PruneRows prune_rows(order.rank.data(), b.state.get(), b.mightsee.data(), b.visbits.data(), b.g.words);
    while (!b.cancel.load(std::memory_order_relaxed)) {
        const uint32_t r = next.fetch_add(1);
        if (r >= b.n)
            break;
        const uint32_t pi = order.order[r];
        if (b.cancel.load(std::memory_order_relaxed)) {
            // Handed out after a cancel: still marked, for any portal waiting on it.
            b.state[pi].store(kAborted, std::memory_order_release);
            b.state[pi].notify_all();
            break;
        }
        b.state[pi].store(kWorking, std::memory_order_relaxed);
        bool ok = false;
        try {
            ok = worker.run(pi, r, b.mightsee_row(pi), prune_rows, b.cancel);
        } catch (...) {
            b.cancel.store(true); // (bad_alloc growing the frames) release the waiters
            b.state[pi].store(kAborted, std::memory_order_release);
            b.state[pi].notify_all();
            throw;
        }
        if (ok)
            std::copy(worker.vis().begin(), worker.vis().end(), b.visbits.begin() + ptrdiff_t(size_t{pi} * b.g.words));
        b.state[pi].store(ok ? kDone : kAborted, std::memory_order_release);
        b.state[pi].notify_all();
        done_weight.fetch_add(b.nummightsee[pi], std::memory_order_relaxed);
        if (!ok)
            break;
    }
    totals.target_checks.fetch_add(worker.target_checks());
    totals.target_check_prunes.fetch_add(worker.target_check_prunes());
    totals.wait_nanos.fetch_add(worker.wait_nanos());
    totals.leaf_recursions.fetch_add(worker.leaf_recursions());
    std::lock_guard lock(b.worker_bytes_mutex);
    b.worker_bytes += worker.bytes();
}

// Full: ranking, passages, then the flow of every portal in rank order.
void run_flow(Bake& b, Clock::time_point start, VisReport& rep)
{
    b.visbits.assign(size_t{b.n} * b.g.words, 0);
    const FlowOrder order = rank_portals(b.nummightsee);
    uint64_t total_weight = 0;
    for (uint32_t i = 0; i < b.n; ++i)
        total_weight += b.nummightsee[i];
    // Passages, then every portal's mightsee narrowed to what its passages reach.
    Passages passages;
    const bool use_passages = build_passages(b.g, b.level, b.mightsee, b.params.passage_budget_bytes, b.threads,
                                             b.cancel, b.user_cancel, b.params.progress, passages);
    if (use_passages) {
        rep.passage_pairs = passages.pairs();
        b.passage_row_bytes = passages.bytes();
    }
    rep.passage_seconds = std::chrono::duration<double>(Clock::now() - start).count() - rep.base_seconds;

    std::atomic<uint32_t> next{0};
    std::atomic<uint64_t> done_weight{0};
    FlowTotals totals;
    run_parallel(
        b.threads, [&](unsigned) { flow_worker(b, order, use_passages ? &passages : nullptr, next, done_weight, totals); },
        b.cancel, b.user_cancel, b.params.progress,
        [&] {
            const double before = kBaseWeight + (use_passages ? kPassageWeight : 0.0);
            return before + (1.0 - before) * double(done_weight.load()) / double(std::max<uint64_t>(total_weight, 1));
        });
    rep.leaf_recursions = totals.leaf_recursions.load();
    rep.target_checks = totals.target_checks.load();
    rep.target_check_prunes = totals.target_check_prunes.load();
    rep.wait_seconds = double(totals.wait_nanos.load()) * 1e-9;
}

// Aggregation (§3.5): a region sees what its outgoing portals see, plus itself; every region
// when base vis did not finish.
Pvs aggregate(Bake& b, bool base_done, bool flow_started, VisReport& rep)
{
    const Graph& g = b.g;
    const size_t words = g.words;
    const uint32_t region_count = g.leaf_count;
    size_t total_visible = 0;
    size_t saw_self = 0;
    Pvs pvs = Pvs::build(region_count, [&](uint32_t r, std::span<uint64_t> row) {
        if (!base_done) {
            bits::fill(row, region_count); // cancelled early: everything may be visible
        } else {
            for (uint32_t k = g.leaf_first[r]; k < g.leaf_first[r + 1]; ++k) {
                const uint32_t pi = g.leaf_portals[k];
                const bool use_vis = flow_started && b.state[pi].load(std::memory_order_acquire) == kDone;
                const uint64_t* src = use_vis ? &b.visbits[size_t{pi} * words] : &b.mightsee[size_t{pi} * words];
                for (size_t w = 0; w < words; ++w)
                    row[w] |= src[w];
            }
            saw_self += bits::test(row, r);
            bits::set(row, r);
        }
        total_visible += bits::count(row);
        return true;
    });
    rep.saw_into_own_region = saw_self;
    rep.mean_visible = region_count == 0 ? 0.0 : double(total_visible) / double(region_count);
    return pvs;
}

} // namespace

Pvs bake_portal_vis(const PortalSet& input, uint32_t region_count, const VisParams& params, VisReport* report)
{
    const auto start = Clock::now();
    const bool full = params.method == VisParams::Method::Full;
    VisReport rep;
    const Graph g = build_graph(input, region_count);
    rep.portals = g.used;
    rep.portals_skipped = g.skipped;
    rep.threads = thread_count(params.threads, g.portals.size());
    Bake b(g, params, std::clamp(params.level, 0, 4), rep.threads);

    bool base_done = false;
    if (params.progress && !params.progress(0.0))
        b.user_cancel.store(true);
    else
        base_done = run_base_vis(b, full);
    rep.base_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    const bool flow_started = full && base_done;
    if (flow_started)
        run_flow(b, start, rep);
    rep.cancelled = b.user_cancel.load();

    Pvs pvs = aggregate(b, base_done, flow_started, rep);
    rep.peak_bytes_estimate = g.bytes() + (b.mightsee.capacity() + b.visbits.capacity()) * sizeof(uint64_t) +
                              size_t{b.n} * (sizeof(uint32_t) * 3 + 1) + b.worker_bytes + b.passage_row_bytes +
                              pvs.memory_bytes() + size_t{region_count} * sizeof(uint32_t) * rep.threads;
    rep.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (params.progress && !rep.cancelled)
        params.progress(1.0);
    if (report)
        *report = rep;
    return pvs;
}

} // namespace pvs
