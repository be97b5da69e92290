#include "visibility/reference/mesh_reference.h"

#include "visibility/bit_row.h"
#include "visibility/face_regions.h"
#include "visibility/worker_pool.h"
#include "visibility/reference/mesh_tracer.h"
#include "visibility/reference/sample_sequence.h"

#include <atomic>
#include <bit>
#include <chrono>
#include <limits>
#include <thread>

namespace pvs {

namespace {
constexpr uint64_t kPointStream = 0x3e54, kDirectionStream = 0x3e55;
}

Pvs bake_mesh_reference_grid(const Zone& zone, const ViewGrid& grid, const MeshReferenceParams& params,
                             MeshReferenceReport* report)
{
    const auto start = std::chrono::steady_clock::now();
    const MeshTracer tracer(zone);
    const FaceRegions faces = build_face_regions(zone);

    const auto cells = uint32_t(grid.cell_count());
    const size_t words = bits::words_for(zone.region_count());
    std::vector<uint64_t> rows(size_t(cells) * words, 0);
    std::atomic<uint64_t> done{0}, points{0}, open_points{0}, open_cells{0}, rays{0};
    std::atomic<bool> stop{false};
    const unsigned threads = params.threads;
    const bool finished = parallel_items(
        cells, threads, params.progress, [&] { return cells ? double(done.load()) / cells : 1.0; }, stop,
        [] { return 0; },
        [&](size_t cell, int&) {
            const Aabb box = grid.cell_bounds(uint32_t(cell));
            const std::span<uint64_t> row(rows.data() + cell * words, words);
            uint64_t kept = 0, traced = 0;
            for (uint32_t i = 0; i < params.points_per_cell; ++i) {
                const uint64_t key = sampling::sample_key(params.seed, kPointStream, cell, i);
                const glm::vec3 u(float(sampling::hash_unit(key, 0)), float(sampling::hash_unit(key, 1)),
                                  float(sampling::hash_unit(key, 2)));
                const glm::vec3 p = box.min + u * (box.max - box.min);
                if (!tracer.in_open_space(p))
                    continue;
                ++kept;
                const uint64_t shift = sampling::sample_key(params.seed, kDirectionStream, cell, i);
                for (uint32_t j = 0; j < params.rays_per_point; ++j) {
                    const glm::vec3 d(sampling::stratified_direction(j, shift));
                    const MeshTracer::Hit h = tracer.first_hit(p, d, std::numeric_limits<float>::infinity());
                    ++traced;
                    if (h.hit && h.front)
                        for (uint32_t r : faces.of(h.face))
                            bits::set(row, r);
                }
            }
            points.fetch_add(params.points_per_cell, std::memory_order_relaxed);
            open_points.fetch_add(kept, std::memory_order_relaxed);
            open_cells.fetch_add(kept > 0 ? 1 : 0, std::memory_order_relaxed);
            rays.fetch_add(traced, std::memory_order_relaxed);
            done.fetch_add(1, std::memory_order_relaxed);
        });
    Pvs pvs = Pvs::build_rows(cells, uint32_t(zone.region_count()), [&](uint32_t c, std::span<uint64_t> out) {
        std::copy_n(rows.begin() + std::ptrdiff_t(size_t(c) * words), words, out.begin());
        return true;
    });
    if (report) {
        report->cells = done.load();
        report->points = points.load();
        report->open_points = open_points.load();
        report->open_cells = open_cells.load();
        report->rays = rays.load();
        report->threads = thread_count(threads, cells);
        report->cancelled = !finished;
        report->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        uint64_t set = 0;
        for (uint64_t w : rows)
            set += uint64_t(std::popcount(w));
        report->mean_visible = cells ? double(set) / cells : 0.0;
    }
    return pvs;
}

} // namespace pvs
