#include "visibility/raster/raster_vis.h"

#include "visibility/raster/gl_headless.h"
#include "visibility/raster/gpu_cube.h"
#include "visibility/raster/ray_cube.h"

#include "visibility/bit_row.h"
#include "visibility/face_regions.h"
#include "visibility/worker_pool.h"
#include "visibility/reference/mesh_tracer.h"
#include "visibility/reference/region_sampler.h"
#include "visibility/reference/sample_sequence.h"
#include "visibility/region_lookup.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace pvs {

namespace {

// One thread's renderer: the rasteriser, or pixel rays through the shared tracer.
struct Worker {
    std::optional<CubeRaster> raster;
    std::optional<RayCube> rays;
    std::vector<uint8_t> seen; // per face

    void render(const glm::vec3& eye)
    {
        if (rays)
            rays->render(eye, seen);
        else
            raster->render(eye, seen);
    }
};

// The GPU for `device` (gl_headless.h), or null for the CPU: Auto falls back with `note` set to
// why; Gpu throws GlUnavailable.
std::unique_ptr<GlHeadless> open_gpu(RasterDevice device, std::string& note)
{
    if (device == RasterDevice::Cpu)
        return nullptr;
    try {
        return GlHeadless::open();
    } catch (const GlUnavailable& e) {
        if (device == RasterDevice::Gpu)
            throw;
        note = std::string("no GPU, the CPU ran: ") + e.what();
        return nullptr;
    }
}

// Bakes `cells` rows: points_of(cell, out) gives each cell's points in zone space.
template <class PointsOf>
Pvs bake_cells(const Zone& zone, uint32_t cells, const RasterParams& params, RasterReport* report, PointsOf&& points_of,
               bool own_region, const MeshTracer* tracer)
{
    const auto start = std::chrono::steady_clock::now();
    const FaceRegions faces = build_face_regions(zone);
    const std::vector<uint8_t> translucent = translucent_face_mask(zone);
    const uint32_t regions = uint32_t(zone.region_count());
    const size_t words = bits::words_for(regions);
    std::vector<uint64_t> rows(size_t(cells) * words, 0);
    std::atomic<uint64_t> done{0}, points{0};
    std::atomic<bool> stop{false};
    const unsigned threads = params.threads;
    // The cells to bake: params.cells (a shard's), else every cell; the others' rows stay empty.
    for (uint32_t cell : params.cells)
        if (cell >= cells)
            throw std::invalid_argument("raster: cell " + std::to_string(cell) + " of " + std::to_string(cells));
    const size_t items = params.cells.empty() ? cells : params.cells.size();
    const auto cell_of = [&](size_t item) { return params.cells.empty() ? uint32_t(item) : params.cells[item]; };
    // One cell's row from the faces its points saw.
    const auto store = [&](uint32_t cell, const std::vector<uint8_t>& seen, size_t eyes) {
        const std::span<uint64_t> row(rows.data() + size_t(cell) * words, words);
        for (uint32_t f = 0; f < seen.size(); ++f)
            if (seen[f])
                for (uint32_t r : faces.of(f))
                    bits::set(row, r);
        if (own_region)
            bits::set(row, cell);
        points.fetch_add(eyes, std::memory_order_relaxed);
        done.fetch_add(1, std::memory_order_relaxed);
    };
    std::string device = "cpu", device_note;
    std::unique_ptr<GlHeadless> gpu = open_gpu(params.device, device_note);
    std::optional<GpuCube> cube;
    if (gpu) {
        try {
            cube.emplace(*gpu, zone, params.raster, params.gpu_batch_views);
        } catch (const GlUnavailable& e) { // no memory for one point's views, a shader refused
            if (params.device == RasterDevice::Gpu)
                throw;
            device_note = std::string("the GPU cannot bake this, the CPU ran: ") + e.what();
            gpu.reset();
        }
    }
    bool finished = true;
    if (cube) {
        device = "gpu: " + gpu->description();
        std::vector<uint8_t> seen(zone.mesh.faces.size(), 0);
        for (size_t item = 0; item < items && finished; ++item) {
            const uint32_t cell = cell_of(item);
            std::fill(seen.begin(), seen.end(), 0);
            const std::vector<glm::vec3> eyes = points_of(cell);
            cube->render(eyes, seen);
            store(cell, seen, eyes.size());
            finished = !params.progress || params.progress(double(item + 1) / double(items));
        }
    } else {
        finished = parallel_items(
            items, threads, params.progress, [&] { return items ? double(done.load()) / double(items) : 1.0; }, stop,
            [&] {
                Worker w;
                if (params.engine == RasterEngine::Rays)
                    w.rays.emplace(*tracer, params.raster, translucent);
                else
                    w.raster.emplace(zone, params.raster);
                w.seen.assign(zone.mesh.faces.size(), 0);
                return w;
            },
            [&](size_t item, Worker& w) {
                const uint32_t cell = cell_of(item);
                std::fill(w.seen.begin(), w.seen.end(), 0);
                const std::vector<glm::vec3> eyes = points_of(cell);
                for (const glm::vec3& eye : eyes)
                    w.render(eye);
                store(cell, w.seen, eyes.size());
            });
    }
    Pvs pvs = Pvs::build_rows(cells, regions, [&](uint32_t c, std::span<uint64_t> out) {
        std::copy_n(rows.begin() + std::ptrdiff_t(size_t(c) * words), words, out.begin());
        return true;
    });
    if (report) {
        report->cells = done.load();
        report->points = points.load();
        report->threads = gpu ? 1 : thread_count(threads, items);
        report->device = device;
        report->device_note = device_note;
        report->cancelled = !finished;
        report->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        uint64_t bits_set = 0;
        for (uint64_t w : rows)
            bits_set += uint64_t(std::popcount(w));
        report->mean_visible = items ? double(bits_set) / double(items) : 0.0;
    }
    return pvs;
}

// A point of `region` (the region's cells carry an epsilon, so a drawn point may lie just outside)
// with open space `clearance` away along each axis: an eye closer to a wall than the near plane
// would see through it (the near plane cuts the wall away), which no camera does, since an
// engine keeps its camera that far from walls. A sample 0.037 units from a wall showed the rooms
// behind it on a generated zone.
bool clear_of_walls(const Zone& zone, const glm::vec3& p, uint32_t region, float clearance)
{
    if (locate_point(zone.tree, p).region != int32_t(region))
        return false;
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-clearance, clearance}) {
            glm::vec3 q = p;
            q[axis] += side;
            if (!locate_point(zone.tree, q).in_region())
                return false;
        }
    return true;
}

glm::vec3 grid_to_zone(const ViewGrid& grid, const glm::vec3& g)
{
    const glm::vec3 obj = g * grid.grid_size; // OBJ file space (y up)
    return {obj.x, -obj.z, obj.y};
}

} // namespace

std::vector<glm::vec3> grid_cell_points(const ViewGrid& grid, uint32_t cell, float step, Lattice lattice)
{
    const uint32_t z = cell % grid.counts.z, y = (cell / grid.counts.z) % grid.counts.y,
                   x = cell / (grid.counts.z * grid.counts.y);
    const glm::vec3 lo = grid.min + glm::vec3(float(x), float(y), float(z)) * grid.cell_size;
    std::vector<glm::vec3> points{lo + glm::vec3(0.5f * grid.cell_size)};
    if (!(step > 0.0f))
        return points;
    // n steps fit in the cell (with a little slack for rounding, as 8 / 1).
    const auto n = uint32_t(std::floor(grid.cell_size / step + 1e-4f));
    const float shift = lattice == Lattice::Centred ? 0.5f : 0.0f;
    for (uint32_t i = 1; i <= n; ++i)
        for (uint32_t j = 1; j <= n; ++j)
            for (uint32_t k = 1; k <= n; ++k)
                points.push_back(lo + (glm::vec3(float(i), float(j), float(k)) - shift) * step);
    return points;
}

namespace {

// Where a grid zone's open space is: the tree where there is one, else the mesh's tracer.
std::unique_ptr<MeshTracer> grid_tracer(const Zone& zone, const RasterParams& params, bool for_rays)
{
    if ((params.open_space_only && !zone.tree.exists()) || for_rays)
        return std::make_unique<MeshTracer>(zone);
    return nullptr;
}

// A grid cell's sample points in zone space (the bake renders these; a shard plan counts them).
std::vector<glm::vec3> grid_points(const Zone& zone, const ViewGrid& grid, const RasterParams& params,
                                   const MeshTracer* mesh, uint32_t cell)
{
    const auto open = [&](const glm::vec3& p) {
        if (!params.open_space_only)
            return true;
        return zone.tree.exists() ? locate_point(zone.tree, p).in_region()
                                  : mesh->in_open_space(p, 2.0f * params.raster.near_distance);
    };
    std::vector<glm::vec3> points;
    if (params.lattice == Lattice::OpenRandom) {
        const Aabb box = grid.cell_bounds(cell);
        for (uint32_t i = 0; i < 32 * params.points_per_region && points.size() < params.points_per_region; ++i) {
            const uint64_t key = sampling::sample_key(params.seed, 0x7a58, cell, i);
            const glm::vec3 u(float(sampling::hash_unit(key, 0)), float(sampling::hash_unit(key, 1)),
                              float(sampling::hash_unit(key, 2)));
            if (const glm::vec3 p = box.min + u * (box.max - box.min); open(p))
                points.push_back(p);
        }
        return points;
    }
    for (const glm::vec3& g : grid_cell_points(grid, cell, params.step, params.lattice))
        if (const glm::vec3 p = grid_to_zone(grid, g); open(p))
            points.push_back(p);
    return points;
}

// A region's sample points: uniform in its volume, clear of its walls.
std::vector<glm::vec3> region_points(const Zone& zone, const RegionSampler& sampler, const RasterParams& params,
                                     uint32_t region)
{
    std::vector<glm::vec3> points;
    if (!sampler.has_volume(region))
        return points;
    for (uint32_t i = 0; i < params.points_per_region; ++i) {
        const uint64_t key = sampling::sample_key(params.seed, 0x7a57, region, i);
        const glm::vec3 p(sampler.point(region, sampling::hash_unit(key, 0), sampling::hash_unit(key, 1),
                                        sampling::hash_unit(key, 2), sampling::hash_unit(key, 3)));
        if (clear_of_walls(zone, p, region, 2.0f * params.raster.near_distance))
            points.push_back(p);
    }
    return points;
}

void check_grid(const ViewGrid& grid)
{
    if (grid.cell_count() > 0xffffffffull)
        throw std::invalid_argument("raster: too many grid cells");
}

void check_tree(const Zone& zone)
{
    if (!zone.tree.exists())
        throw std::invalid_argument("raster over regions needs a BSP tree to place points in the regions");
}

} // namespace

Pvs bake_raster_grid(const Zone& zone, const ViewGrid& grid, const RasterParams& params, RasterReport* report)
{
    check_grid(grid);
    // The mesh's tracer, built once: where open space is (a zone without a tree) and the pixel rays.
    const std::unique_ptr<MeshTracer> mesh =
        grid_tracer(zone, params, params.engine == RasterEngine::Rays && params.device != RasterDevice::Gpu);
    return bake_cells(
        zone, uint32_t(grid.cell_count()), params, report,
        [&](uint32_t cell) { return grid_points(zone, grid, params, mesh.get(), cell); }, false, mesh.get());
}

Pvs bake_raster_regions(const Zone& zone, const RasterParams& params, RasterReport* report)
{
    check_tree(zone);
    const RegionSampler sampler(zone);
    std::unique_ptr<MeshTracer> mesh; // the pixel rays' tracer, built once for every thread
    if (params.engine == RasterEngine::Rays && params.device != RasterDevice::Gpu)
        mesh = std::make_unique<MeshTracer>(zone);
    return bake_cells(
        zone, uint32_t(zone.region_count()), params, report,
        [&](uint32_t region) { return region_points(zone, sampler, params, region); }, true, mesh.get());
}

std::vector<uint32_t> raster_cell_point_counts(const Zone& zone, const RasterParams& params)
{
    std::vector<uint32_t> counts;
    if (zone.view_grid) {
        check_grid(*zone.view_grid);
        const std::unique_ptr<MeshTracer> mesh = grid_tracer(zone, params, false);
        counts.resize(zone.view_grid->cell_count());
        for (uint32_t cell = 0; cell < counts.size(); ++cell)
            counts[cell] = uint32_t(grid_points(zone, *zone.view_grid, params, mesh.get(), cell).size());
        return counts;
    }
    check_tree(zone);
    const RegionSampler sampler(zone);
    counts.resize(zone.region_count());
    for (uint32_t region = 0; region < counts.size(); ++region)
        counts[region] = uint32_t(region_points(zone, sampler, params, region).size());
    return counts;
}

} // namespace pvs
