#include "visibility/terrain/terrain_vis.h"

#include "visibility/bit_matrix.h"
#include "visibility/bit_row.h"
#include "visibility/geometry/region_boxes.h"
#include "visibility/portal/portalize.h"
#include "visibility/terrain/horizon_parents.h"
#include "visibility/worker_pool.h"

#include <algorithm>
#include <bit>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace pvs {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Footprint {
    int32_t x = 0, y = 0;   // first column
    uint32_t w = 0, h = 0;  // columns; 0: no box
    double top = 0.0;

    bool known() const { return w != 0; }
    auto key() const { return std::tuple(w, h, x, y, top); }
};

// The first and last columns whose span [origin + i cell, origin + (i + 1) cell] covers
// [lo, hi] (a superset: a column is taken when in doubt).
std::pair<int32_t, int32_t> column_range(double lo, double hi, double origin, double cell, uint32_t columns)
{
    int32_t first = int32_t(std::clamp(std::floor((lo - origin) / cell), 0.0, double(columns - 1)));
    while (first > 0 && origin + first * cell > lo)
        --first;
    int32_t last = int32_t(std::clamp(std::ceil((hi - origin) / cell) - 1.0, double(first), double(columns - 1)));
    while (last + 1 < int32_t(columns) && origin + (last + 1) * cell < hi)
        ++last;
    return {first, last};
}

Footprint footprint_of(const Aabb& box, const Heightfield& field)
{
    Footprint f;
    if (box.empty())
        return f;
    const auto [x0, x1] = column_range(box.min.x, box.max.x, field.origin_x, field.cell_x, field.columns_x);
    const auto [y0, y1] = column_range(box.min.y, box.max.y, field.origin_y, field.cell_y, field.columns_y);
    f.x = x0;
    f.y = y0;
    f.w = uint32_t(x1 - x0 + 1);
    f.h = uint32_t(y1 - y0 + 1);
    f.top = box.max.z;
    return f;
}

// The footprint a source sweeps from: `f` grown to powers of two columns along each axis (within
// the grid; shifted back from its edge), so that few parent tables serve every source. A larger
// source only adds sight lines: still conservative.
Footprint source_footprint(const Footprint& f, const Heightfield& field)
{
    if (!f.known())
        return f;
    Footprint s = f;
    s.w = std::min<uint32_t>(std::bit_ceil(f.w), field.columns_x);
    s.h = std::min<uint32_t>(std::bit_ceil(f.h), field.columns_y);
    s.x = std::min<int32_t>(f.x, int32_t(field.columns_x - s.w));
    s.y = std::min<int32_t>(f.y, int32_t(field.columns_y - s.h));
    return s;
}

// Distances between the footprint (w x h columns at the origin) and the column at (dx, dy), in
// zone units: smallest and largest over their points.
struct Distances {
    double smallest, largest;
};
Distances distances(int32_t dx, int32_t dy, uint32_t w, uint32_t h, double cell_x, double cell_y)
{
    const double gap_x = std::max({0, dx - int32_t(w), -(dx + 1)}) * cell_x;
    const double gap_y = std::max({0, dy - int32_t(h), -(dy + 1)}) * cell_y;
    const double far_x = std::max(dx + 1, int32_t(w) - dx) * cell_x;
    const double far_y = std::max(dy + 1, int32_t(h) - dy) * cell_y;
    return {std::sqrt(gap_x * gap_x + gap_y * gap_y), std::sqrt(far_x * far_x + far_y * far_y)};
}

// The lowest slope an unblocked line from the footprint at `top` has over a column of `height`.
double slope_bound(double height, double top, const Distances& d)
{
    if (height > top)
        return (height - top) / d.largest;
    if (d.smallest == 0.0)
        return -kInf;
    return (height - top) / d.smallest;
}

// A parent table with the distances of every offset, for one footprint size and column size.
struct SweepTable {
    HorizonParents parents;
    std::vector<Distances> distance; // per offset index

    SweepTable(uint32_t w, uint32_t h, const Heightfield& field)
        : parents(w, h, field.columns_x, field.columns_y), distance(parents.order().size())
    {
        for (uint32_t i = 0; i < distance.size(); ++i)
            distance[i] = distances(parents.offset_dx(i), parents.offset_dy(i), w, h, field.cell_x, field.cell_y);
    }
    size_t memory_bytes() const { return parents.memory_bytes() + distance.capacity() * sizeof(Distances); }
};

struct Sweep {
    std::vector<double> slope;     // S per column
    std::vector<double> threshold; // per column: tops below this are hidden
};

// Fills sweep.threshold for the source footprint `r` at its top (see the header).
void sweep_from(const Heightfield& field, const SweepTable& table, const Footprint& r, Sweep& sweep)
{
    const HorizonParents& parents = table.parents;
    const int32_t nx = int32_t(field.columns_x), ny = int32_t(field.columns_y);
    for (const uint32_t index : parents.order()) {
        const int32_t dx = parents.offset_dx(index), dy = parents.offset_dy(index);
        const int32_t cx = r.x + dx, cy = r.y + dy;
        if (cx < 0 || cy < 0 || cx >= nx || cy >= ny)
            continue;
        const size_t column = size_t(cx) + size_t(cy) * size_t(nx);
        // Each strip bounds the slope from below; the larger bound holds.
        double s = -kInf;
        const uint32_t strips = parents.strip_count(index);
        double strip_bound[2] = {kInf, kInf};
        for (const HorizonParents::Parent* p = parents.parents_begin(index); p != parents.parents_end(index); ++p) {
            const int32_t pdx = parents.offset_dx(p->offset), pdy = parents.offset_dy(p->offset);
            const int32_t px = r.x + pdx, py = r.y + pdy;
            if (px < 0 || py < 0 || px >= nx || py >= ny)
                continue; // outside the grid is no region's: solid, never the lowest term
            const size_t pc = size_t(px) + size_t(py) * size_t(nx);
            const double bound = slope_bound(field.top[pc], r.top, table.distance[p->offset]);
            double before = -kInf; // what lies before the cell (inside) or its partner (touching)
            if (p->inside) {
                before = sweep.slope[pc];
            } else if (p->partner != HorizonParents::kNone) {
                const int32_t qx = r.x + parents.offset_dx(p->partner), qy = r.y + parents.offset_dy(p->partner);
                before = sweep.slope[size_t(qx) + size_t(qy) * size_t(nx)]; // inside cells are in the grid
            }
            const double term = std::max(before, bound);
            strip_bound[p->strip] = std::min(strip_bound[p->strip], term);
        }
        for (uint32_t k = 0; k < strips; ++k)
            if (strip_bound[k] != kInf) // a strip with no cell in the grid cannot happen; be safe
                s = std::max(s, strip_bound[k]);
        sweep.slope[column] = s;
        if (s == -kInf) {
            sweep.threshold[column] = -kInf;
            continue;
        }
        const Distances& d = table.distance[index];
        const double rise = s * (s >= 0.0 ? d.smallest : d.largest);
        // A hair below the exact bound: round-off may only make more visible.
        sweep.threshold[column] = r.top + rise - 1e-9 * (std::abs(r.top) + std::abs(rise) + 1.0);
    }
}

// The targets of the row test, flat: a region whose footprint is one column is tested with one
// load; the others (and those without a box) go through their footprints.
struct Targets {
    std::vector<uint32_t> column; // per region: its column, or kMany
    std::vector<double> top;      // per region
    std::vector<uint32_t> many;   // regions with a footprint of several columns, or none
    static constexpr uint32_t kMany = UINT32_MAX;
};

Targets flat_targets(const std::vector<Footprint>& footprints, const Heightfield& field)
{
    Targets t;
    t.column.resize(footprints.size());
    t.top.resize(footprints.size());
    for (size_t b = 0; b < footprints.size(); ++b) {
        const Footprint& f = footprints[b];
        const bool single = f.known() && f.w == 1 && f.h == 1;
        t.column[b] = single ? uint32_t(f.x) + uint32_t(f.y) * field.columns_x : Targets::kMany;
        t.top[b] = f.top;
        if (!single)
            t.many.push_back(uint32_t(b));
    }
    return t;
}

// Sets in `row` every region the sweep does not hide.
void fill_row(const Sweep& sweep, const Targets& targets, const std::vector<Footprint>& footprints,
              const Heightfield& field, std::span<uint64_t> row)
{
    const size_t n = targets.column.size();
    const double* threshold = sweep.threshold.data();
    for (size_t word = 0; word * 64 < n; ++word) {
        uint64_t bits = 0;
        const size_t end = std::min(n, word * 64 + 64);
        for (size_t b = word * 64; b < end; ++b) {
            const uint32_t column = targets.column[b];
            // kMany reads column 0: decided below instead.
            const bool visible = !(targets.top[b] < threshold[column == Targets::kMany ? 0 : column]);
            bits |= uint64_t(visible) << (b - word * 64);
        }
        row[word] = bits;
    }
    for (const uint32_t b : targets.many) {
        const Footprint& f = footprints[b];
        bool visible = !f.known();
        for (uint32_t y = 0; y < f.h && !visible; ++y)
            for (uint32_t x = 0; x < f.w && !visible; ++x)
                visible = !(f.top < threshold[size_t(f.x + int32_t(x)) + size_t(f.y + int32_t(y)) * field.columns_x]);
        if (visible)
            bits::set(row, b);
        else
            bits::clear(row, b);
    }
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

Pvs bake_terrain_vis(const Zone& zone, const TerrainVisParams& params, TerrainVisReport* report)
{
    const auto start = std::chrono::steady_clock::now();
    TerrainVisReport local;
    TerrainVisReport& out = report ? *report : local;
    out = TerrainVisReport{};

    // The world the portals and the reference take regions in (the zone's bounds and a margin):
    // a region open to the sky reaches above the zone's top, and sees more from there.
    const std::vector<Aabb> boxes = region_volume_boxes(zone.tree, zone.regions.size(), zone_portal_world(zone));
    const size_t n = zone.regions.size();
    // The grid, the footprints (exact, for the targets), the sources (footprints rounded up to
    // powers of two, so few parent tables serve them) and the tables; a grid whose tables would
    // pass the budget is made again with columns twice as wide.
    Heightfield field;
    std::vector<Footprint> footprints(n), source_of(n);
    std::vector<uint32_t> order;
    std::vector<size_t> source_first; // into order
    std::map<std::pair<uint32_t, uint32_t>, std::unique_ptr<SweepTable>> tables;
    size_t table_bytes = 0;
    for (double cell = params.cell;; cell = 2.0 * std::max(field.cell_x, field.cell_y)) {
        field = zone_heightfield(zone.tree, boxes, cell);
        out.regions_without_box = 0;
        for (size_t i = 0; i < n; ++i) {
            footprints[i] = footprint_of(boxes[i], field);
            source_of[i] = source_footprint(footprints[i], field);
            out.regions_without_box += !footprints[i].known();
        }
        // Sources: regions with the same source footprint and top share a sweep and a row.
        order.clear();
        for (uint32_t i = 0; i < n; ++i)
            if (footprints[i].known())
                order.push_back(i);
        std::sort(order.begin(), order.end(),
                  [&](uint32_t a, uint32_t b) { return source_of[a].key() < source_of[b].key(); });
        source_first.clear();
        for (size_t i = 0; i < order.size(); ++i)
            if (i == 0 || source_of[order[i]].key() != source_of[order[i - 1]].key())
                source_first.push_back(i);
        source_first.push_back(order.size());
        tables.clear();
        table_bytes = 0;
        for (size_t s = 0; s + 1 < source_first.size() && table_bytes <= params.table_budget_bytes; ++s) {
            const Footprint& f = source_of[order[source_first[s]]];
            auto& table = tables[{f.w, f.h}];
            if (!table) {
                table = std::make_unique<SweepTable>(f.w, f.h, field);
                table_bytes += table->memory_bytes();
            }
        }
        if (table_bytes <= params.table_budget_bytes || (field.columns_x <= 1 && field.columns_y <= 1))
            break;
    }
    out.heightfield_seconds = seconds_since(start);
    out.columns_x = field.columns_x;
    out.columns_y = field.columns_y;
    out.cell_x = field.cell_x;
    out.cell_y = field.cell_y;
    const size_t sources = source_first.size() - 1;
    out.sources = sources;
    out.footprint_sizes = tables.size();

    const Targets targets = flat_targets(footprints, field);
    const size_t words = bits::words_for(n);
    std::vector<uint64_t> matrix(n * words, 0);
    for (uint32_t i = 0; i < n; ++i)
        if (!footprints[i].known())
            bits::fill(std::span(matrix).subspan(i * words, words), n); // no box: sees everything

    std::atomic<size_t> done{0};
    std::atomic<bool> stop{false};
    const unsigned threads = thread_count(params.threads, sources);
    out.threads = threads;
    const bool finished = parallel_items(
        sources, threads, params.progress, [&] { return 0.95 * double(done.load()) / double(std::max<size_t>(sources, 1)); },
        stop,
        [&] {
            return Sweep{std::vector<double>(field.column_count()), std::vector<double>(field.column_count())};
        },
        [&](size_t s, Sweep& sweep) {
            const Footprint& f = source_of[order[source_first[s]]];
            sweep_from(field, *tables.at({f.w, f.h}), f, sweep);
            const uint32_t first = order[source_first[s]];
            std::span<uint64_t> row = std::span(matrix).subspan(size_t(first) * words, words);
            fill_row(sweep, targets, footprints, field, row);
            for (size_t k = source_first[s] + 1; k < source_first[s + 1]; ++k)
                std::copy(row.begin(), row.end(), matrix.begin() + ptrdiff_t(size_t(order[k]) * words));
            done.fetch_add(1, std::memory_order_relaxed);
        });
    if (!finished) {
        out.cancelled = true;
        out.seconds = seconds_since(start);
        return Pvs{};
    }

    bits::and_with_transpose(matrix, n, words);
    Pvs pvs = Pvs::build(uint32_t(n), [&](uint32_t region, std::span<uint64_t> row) {
        std::copy_n(matrix.begin() + ptrdiff_t(size_t(region) * words), words, row.begin());
        return true;
    });
    size_t visible = 0;
    for (uint64_t w : matrix)
        visible += bits::popcount(w);
    out.mean_visible = n ? double(visible) / double(n) : 0.0;
    out.peak_bytes_estimate = matrix.size() * sizeof(uint64_t) + pvs.memory_bytes() + table_bytes +
                              field.column_count() * (sizeof(double) + threads * 2 * sizeof(double));
    out.seconds = seconds_since(start);
    if (params.progress)
        params.progress(1.0);
    return pvs;
}

} // namespace pvs
