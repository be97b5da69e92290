// The portal-vis baker (portal_vis.h for the method, the determinism rule and the limits): the
// phases of a bake and the bake's shared state. One concept per file beside it:
//   portal_graph  directed portals, points, portals per region (input)
//   run_rows      finished bit rows kept as runs of nonzero words
//   base_vis      each directed portal's mightsee (Method::Fast's rows)
//   passages      rows of the leaves a line through two portals can reach; mightsee narrowed
//   flow_order    the ranking and the rows a flow prunes with (determinism)
//   flow          the recursive portal flow on one thread (flow_frame: a frame and its clip;
//                 separators: ClipToSeparators' planes; target_checks: the dead-walk test)
//   vis_progress  the progress bar's phase shares (threads: visibility/worker_pool.h)
#include "visibility/portal/portal_vis.h"

#include "visibility/bit_row.h"
#include "visibility/portal/base_vis_batch.h"
#include "visibility/portal/flow.h"
#include "visibility/portal/flow_order.h"
#include "visibility/portal/passages.h"
#include "visibility/portal/portal_graph.h"
#include "visibility/portal/run_rows.h"
#include "visibility/portal/vis_progress.h"
#include "visibility/worker_pool.h"

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

// What the phases of one bake share: the graph, the rows and each portal's state. Rows are
// dense only while a worker builds them; finished, they are kept as runs (run_rows.h) in pools
// of the thread that made them.
struct Bake {
    const Graph& g;
    const VisParams& params;
    int level = 4;
    uint32_t n = 0;             // directed portals
    unsigned threads = 1;
    std::vector<RunRow> mightsee; // per directed portal
    std::vector<uint32_t> nummightsee;
    std::vector<RunRow> visbits;  // Full only; visbits[i] is set before state[i] becomes kDone
    std::vector<RowPool> might_pools, vis_pools; // per thread
    std::unique_ptr<std::atomic<uint8_t>[]> state;
    std::atomic<bool> cancel{false}, user_cancel{false};
    size_t worker_bytes = 0; // summed by the flow's workers under worker_bytes_mutex
    std::mutex worker_bytes_mutex;
    size_t passage_row_bytes = 0;
    size_t narrowing_row_bytes = 0; // base rows and their narrowed copies, both held for a moment
    // Source::Region: each region's row, its state, and each directed portal's destination region.
    std::vector<RunRow> region_rows;
    std::unique_ptr<std::atomic<uint8_t>[]> region_state;
    std::vector<uint32_t> leaf_of_portal;
    bool by_region() const { return params.source == VisParams::Source::Region; }

    Bake(const Graph& graph, const VisParams& p, int lvl, unsigned workers)
        : g(graph), params(p), level(lvl), n(uint32_t(graph.portals.size())), threads(workers),
          mightsee(n), nummightsee(n, 0), might_pools(workers), state(new std::atomic<uint8_t>[n])
    {
        for (uint32_t i = 0; i < n; ++i)
            state[i].store(kNone, std::memory_order_relaxed);
    }
    size_t row_bytes() const
    {
        size_t bytes = (mightsee.capacity() + visbits.capacity()) * sizeof(RunRow);
        for (const RowPool& pool : might_pools)
            bytes += pool.bytes();
        for (const RowPool& pool : vis_pools)
            bytes += pool.bytes();
        return bytes;
    }
};

// Base vis: the directed portals in batches of kBatchLanes (base_vis_batch.h), in
// base_vis_batch_order. False when cancelled.
bool run_base_vis(Bake& b, bool full)
{
    std::atomic<uint32_t> next{0}, done{0};
    const BaseVisTables tables = base_vis_tables(b.g); // freed when base vis ends
    const std::vector<uint32_t> order = base_vis_batch_order(b.g);
    const uint32_t batches = (b.n + kBatchLanes - 1) / kBatchLanes;
    const bool kept_going = run_workers(
        b.threads,
        [&](unsigned t) {
            BaseVisBatch batch(b.g);
            std::vector<uint64_t> encoded;
            while (!b.cancel.load(std::memory_order_relaxed)) {
                const uint32_t i = next.fetch_add(1);
                if (i >= batches)
                    break;
                const uint32_t first = i * kBatchLanes, lanes = std::min(kBatchLanes, b.n - first);
                const std::span<const uint32_t> sources(&order[first], lanes);
                batch.run(b.g, tables, sources);
                for (uint32_t lane = 0; lane < lanes; ++lane) {
                    encode_runs(batch.row(lane), encoded);
                    b.mightsee[sources[lane]] = b.might_pools[t].append(encoded);
                    b.nummightsee[sources[lane]] = batch.count(lane);
                }
                done.fetch_add(lanes, std::memory_order_relaxed);
            }
        },
        b.cancel, b.params.progress,
        [&] { return (full ? kBaseWeight : 1.0) * double(done.load()) / double(std::max(b.n, 1u)); });
    if (!kept_going)
        b.user_cancel.store(true);
    return !b.cancel.load();
}

// The flow's counters, summed over its workers.
struct FlowTotals {
    std::atomic<uint64_t> wait_nanos{0};
    std::atomic<size_t> leaf_recursions{0};
    std::atomic<size_t> frames{0}, portal_visible{0};
    std::atomic<size_t> target_checks{0}, target_check_prunes{0};
    std::atomic<size_t> dominated_windows{0};
    std::atomic<size_t> clips{0}, separators{0};
};

// Adds a worker's counters to the bake's totals.
void add_worker_totals(Bake& b, const FlowWorker& worker, FlowTotals& totals)
{
    totals.target_checks.fetch_add(worker.target_checks());
    totals.target_check_prunes.fetch_add(worker.target_check_prunes());
    totals.wait_nanos.fetch_add(worker.wait_nanos());
    totals.leaf_recursions.fetch_add(worker.leaf_recursions());
    totals.frames.fetch_add(worker.frames_entered());
    totals.portal_visible.fetch_add(worker.portal_visible());
    totals.dominated_windows.fetch_add(worker.dominated_windows());
    totals.clips.fetch_add(worker.clips());
    totals.separators.fetch_add(worker.separators());
    std::lock_guard lock(b.worker_bytes_mutex);
    b.worker_bytes += worker.bytes();
}

// One worker of the flow: portals in rank order from `next` until none is left or the bake is
// cancelled; each finished portal's visbits are published through its state.
void flow_worker(Bake& b, unsigned t, const FlowOrder& order, const Passages* passages, std::atomic<uint32_t>& next,
                 std::atomic<uint64_t>& done_weight, FlowTotals& totals)
{
    FlowWorker worker(b.g, b.level);
    worker.use_target_checks(b.params.target_checks);
    worker.watch(b.params.probe);
    worker.use_symmetry(b.params.symmetry);
    worker.use_window_memo(b.params.dominated_windows);
    if (passages != nullptr)
        worker.use_passages(passages);
    const PruneRows prune_rows(order.rank.data(), b.state.get(), b.mightsee.data(), b.visbits.data());
    std::vector<uint64_t> encoded;
    while (!b.cancel.load(std::memory_order_relaxed)) {
        const uint32_t r = next.fetch_add(1);
        if (r >= b.n)
            break;
        const uint32_t pi = order.order[r];
        FlowTicket ticket(b.state[pi]); // Aborted unless done(): a portal waiting on pi goes on
        if (b.cancel.load(std::memory_order_relaxed))
            break; // handed out after a cancel
        bool ok = false;
        try {
            ok = worker.run(pi, r, b.mightsee[pi], prune_rows, b.cancel);
            if (ok) {
                encode_runs(worker.vis(), encoded);
                b.visbits[pi] = b.vis_pools[t].append(encoded);
                ticket.done();
            }
        } catch (...) {
            b.cancel.store(true); // (bad_alloc growing the frames or the pool) stop the others
            throw;
        }
        done_weight.fetch_add(b.nummightsee[pi], std::memory_order_relaxed);
        if (!ok)
            break;
    }
    add_worker_totals(b, worker, totals);
}

// Source::Region: regions in rank order from `next`; each region's portals walk into one row,
// published through the region's state.
void region_flow_worker(Bake& b, unsigned t, const FlowOrder& order, const Passages* passages,
                        std::atomic<uint32_t>& next, std::atomic<uint64_t>& done_weight, FlowTotals& totals)
{
    const Graph& g = b.g;
    FlowWorker worker(g, b.level);
    worker.use_target_checks(b.params.target_checks);
    worker.watch(b.params.probe);
    worker.use_symmetry(b.params.symmetry);
    worker.use_window_memo(b.params.dominated_windows);
    if (passages != nullptr)
        worker.use_passages(passages);
    const PruneRows prune_rows(order.rank.data(), b.region_state.get(), b.mightsee.data(), b.region_rows.data(),
                               b.leaf_of_portal.data());
    std::vector<uint64_t> encoded;
    const uint32_t regions = g.leaf_count;
    while (!b.cancel.load(std::memory_order_relaxed)) {
        const uint32_t r = next.fetch_add(1);
        if (r >= regions)
            break;
        const uint32_t region = order.order[r];
        FlowTicket ticket(b.region_state[region]);
        if (b.cancel.load(std::memory_order_relaxed))
            break;
        bool ok = true;
        uint64_t weight = 0;
        try {
            worker.begin_row();
            worker.mark_visible(region);
            for (uint32_t k = g.leaf_first[region]; k < g.leaf_first[region + 1] && ok; ++k) {
                const uint32_t pi = g.leaf_portals[k];
                ok = worker.walk(pi, r, b.mightsee[pi], prune_rows, b.cancel);
                weight += b.nummightsee[pi];
            }
            if (ok) {
                worker.end_row();
                encode_runs(worker.vis(), encoded);
                b.region_rows[region] = b.vis_pools[t].append(encoded);
                ticket.done();
            }
        } catch (...) {
            b.cancel.store(true);
            throw;
        }
        done_weight.fetch_add(weight, std::memory_order_relaxed);
        if (!ok)
            break;
    }
    add_worker_totals(b, worker, totals);
}

// Source::Region: regions ranked by the summed mightsee of their portals.
FlowOrder rank_regions(const Bake& b)
{
    std::vector<uint32_t> weight(b.g.leaf_count, 0);
    for (uint32_t pi = 0; pi < b.n; ++pi)
        weight[b.g.portals[pi].owner] += b.nummightsee[pi];
    return rank_portals(weight);
}

// Full: ranking, passages, then the flow of every portal in rank order.
void run_flow(Bake& b, Clock::time_point start, VisReport& rep)
{
    b.vis_pools.resize(b.threads);
    if (b.by_region()) {
        b.region_rows.assign(b.g.leaf_count, RunRow{});
        b.region_state.reset(new std::atomic<uint8_t>[b.g.leaf_count]);
        for (uint32_t r = 0; r < b.g.leaf_count; ++r)
            b.region_state[r].store(kNone, std::memory_order_relaxed);
        b.leaf_of_portal.resize(b.n);
        for (uint32_t pi = 0; pi < b.n; ++pi)
            b.leaf_of_portal[pi] = b.g.portals[pi].leaf;
    } else
        b.visbits.assign(b.n, RunRow{});
    const FlowOrder order = b.by_region() ? rank_regions(b) : rank_portals(b.nummightsee);
    uint64_t total_weight = 0;
    for (uint32_t i = 0; i < b.n; ++i)
        total_weight += b.nummightsee[i];
    // Passages, then every portal's mightsee narrowed to what its passages reach.
    const size_t base_row_bytes = b.row_bytes();
    Passages passages;
    RowPool narrowed;
    const bool use_passages = build_passages(b.g, b.level, b.mightsee, narrowed, b.params.passage_budget_bytes,
                                             b.threads, b.cancel, b.user_cancel, b.params.progress, passages);
    if (use_passages) {
        // Every row was replaced by its narrowed copy: the base rows go.
        b.narrowing_row_bytes = base_row_bytes + narrowed.bytes();
        b.might_pools.clear();
        b.might_pools.push_back(std::move(narrowed));
        rep.passage_pairs = passages.pairs();
        b.passage_row_bytes = passages.bytes();
    }
    rep.passage_seconds = std::chrono::duration<double>(Clock::now() - start).count() - rep.base_seconds;

    std::atomic<uint32_t> next{0};
    std::atomic<uint64_t> done_weight{0};
    FlowTotals totals;
    const bool kept_going = run_workers(
        b.threads,
        [&](unsigned t) {
            if (b.by_region())
                region_flow_worker(b, t, order, use_passages ? &passages : nullptr, next, done_weight, totals);
            else
                flow_worker(b, t, order, use_passages ? &passages : nullptr, next, done_weight, totals);
        },
        b.cancel, b.params.progress,
        [&] {
            const double before = kBaseWeight + (use_passages ? kPassageWeight : 0.0);
            return before + (1.0 - before) * double(done_weight.load()) / double(std::max<uint64_t>(total_weight, 1));
        });
    if (!kept_going)
        b.user_cancel.store(true);
    rep.leaf_recursions = totals.leaf_recursions.load();
    rep.frames = totals.frames.load();
    rep.portal_visible = totals.portal_visible.load();
    rep.target_checks = totals.target_checks.load();
    rep.target_check_prunes = totals.target_check_prunes.load();
    rep.dominated_windows = totals.dominated_windows.load();
    rep.clips = totals.clips.load();
    rep.separators = totals.separators.load();
    rep.wait_seconds = double(totals.wait_nanos.load()) * 1e-9;
}

// Whether every directed portal has its visbits (a cancelled flow leaves some with mightsee only).
bool every_flow_done(const Bake& b)
{
    if (b.by_region()) {
        for (uint32_t r = 0; r < b.g.leaf_count; ++r)
            if (b.region_state[r].load(std::memory_order_acquire) != kDone)
                return false;
        return true;
    }
    for (uint32_t i = 0; i < b.n; ++i)
        if (b.state[i].load(std::memory_order_acquire) != kDone)
            return false;
    return true;
}

// Once every portal has its visbits, aggregate reads no mightsee row: they are freed before the
// PVS is built (at 5000 rooms they were most of the 265 MB of rows still held while the PVS was
// compressed, which made the bake's peak).
void free_mightsee(Bake& b)
{
    std::vector<RunRow>().swap(b.mightsee);
    std::vector<RowPool>().swap(b.might_pools);
}

// Aggregation (§3.5): a region sees what its outgoing portals see, plus itself; every region
// when base vis did not finish.
Pvs aggregate(Bake& b, bool base_done, bool flow_started, VisReport& rep)
{
    const Graph& g = b.g;
    const uint32_t region_count = g.leaf_count;
    size_t total_visible = 0;
    size_t saw_self = 0;
    Pvs pvs = Pvs::build(region_count, [&](uint32_t r, std::span<uint64_t> row) {
        if (!base_done) {
            bits::fill(row, region_count); // cancelled early: everything may be visible
        } else if (flow_started && b.by_region() && b.region_state[r].load(std::memory_order_acquire) == kDone) {
            b.region_rows[r].or_into(row.data());
        } else if (flow_started && b.by_region()) {
            for (uint32_t k = g.leaf_first[r]; k < g.leaf_first[r + 1]; ++k)
                b.mightsee[g.leaf_portals[k]].or_into(row.data());
            bits::set(row, r);
        } else {
            for (uint32_t k = g.leaf_first[r]; k < g.leaf_first[r + 1]; ++k) {
                const uint32_t pi = g.leaf_portals[k];
                const bool use_vis = flow_started && b.state[pi].load(std::memory_order_acquire) == kDone;
                (use_vis ? b.visbits[pi] : b.mightsee[pi]).or_into(row.data());
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
    if (params.probe != nullptr)
        params.probe->found.assign(b.n, std::nullopt);

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
    const size_t row_bytes = b.row_bytes();
    if (flow_started && every_flow_done(b))
        free_mightsee(b);

    Pvs pvs = aggregate(b, base_done, flow_started, rep);
    rep.peak_bytes_estimate = g.bytes() + std::max(row_bytes, b.narrowing_row_bytes) +
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
