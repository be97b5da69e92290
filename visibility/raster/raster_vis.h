// The raster baker (`--method raster`): a PVS by sampling, as HateEngine's pvs_baker
// does it (quake-doom-hepvs.md §5.6), on the CPU. For each cell, cube maps are rendered from
// sample points in it (cube_raster.h) and every face with a pixel is seen; the cell's row is the
// union of the regions of those faces (in an OBJ zone a face belongs to one object; where a face
// is listed by several regions, as Quake's marksurfaces list it, each of them).
//
// Cells are either
//  - the view grid (bake_raster_grid): grid zones (OBJ + .hepvs), one row per cell. Sample points:
//    the cell's centre plus a lattice of n^3 points, n = cell size / step (step 0: the centre only).
//    Lattice::HateEngine puts them at offsets step, 2 step, ... up to the cell size from the
//    cell's min corner, as the baker does: its last layer lies on the cell's far faces, and where
//    a wall lies on a cell boundary (levels built on a grid) the eye sits on the wall and sees
//    through it (the raster test's two rooms show it). Lattice::Centred puts them at
//    offsets (i - 1/2) step, the centres of n^3 equal boxes, never on a cell face. Points not in
//    open space are dropped unless open_space_only is off (below);
//  - or the regions (bake_raster_regions, zones with a tree): points_per_region points drawn
//    uniformly in each region's volume (reference/region_sampler.h, the reference's sampler),
//    keeping those with open space twice the near distance away along each axis (an eye nearer a
//    wall sees through it, as no camera can), so raster, portal and reference PVSs of one zone
//    compare row for row. Each region sees itself.
//
// A sample, so a lower bound of what the cell sees at that density (up to the caveat about
// shared faces above): more points and more pixels only add. Deterministic (per-cell results,
// fixed point sets, any thread count), progress(fraction) false cancels (the report says so and
// the rows so far are kept).
#pragma once

#include "visibility/pvs.h"
#include "visibility/raster/cube_raster.h"
#include "visibility/view_grid.h"
#include "visibility/zone.h"

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace pvs {

// OpenRandom (the default): not a lattice but points uniform in the cell, kept when in open space
// (with the near plane's clearance), until points_per_region are kept (at most 32 times that many
// drawn): the samples go where cameras can be, however little of the cell that is. On E1M1 it
// misses 368 reference pairs with 128 points a cell where the centred lattice with 512 misses
// 804 (docs/performance.md).
enum class Lattice : uint8_t { Centred, HateEngine, OpenRandom };

// How a point's six views are drawn: pixel rays in Embree packets (ray_cube.h: faster on E1M1 at
// every resolution measured, 32 to 128) or pvscope's rasteriser (cube_raster.h). The same pixel
// centres; the faces seen differ only where a triangle edge crosses one.
enum class RasterEngine : uint8_t { Rays, Rasteriser };

// Where the views are drawn: the CPU (`engine` above, on `threads` cores), a GPU through a
// headless OpenGL 4.5 context (gpu_cube.h: one thread feeds it; on Mesa's llvmpipe the driver's
// own threads rasterise), or Auto: the GPU when one answers, else the CPU (the report says which
// ran and why). Gpu throws GlUnavailable (gl_headless.h) when none answers.
enum class RasterDevice : uint8_t { Cpu, Gpu, Auto };

struct RasterParams {
    CubeRasterOptions raster;
    RasterEngine engine = RasterEngine::Rays;
    Lattice lattice = Lattice::OpenRandom;
    float step = 0.0f;               // grid cells: lattice step in grid units (HateEngine -s); 0 = centre only
    // Grid cells: keep only points in open space (mesh_tracer.h: inside the level, where a camera
    // can be); a cell with none gets an empty row. Off, every lattice point renders, as the
    // HateEngine baker's do (from the rock around a level they see into rooms through the backs
    // of walls).
    bool open_space_only = true;
    uint32_t points_per_region = 16; // region cells
    uint64_t seed = 1;
    unsigned threads = 0;            // 0 = all cores
    RasterDevice device = RasterDevice::Cpu;
    uint32_t gpu_batch_views = 0; // views drawn per compute pass on the GPU (0: gpu_cube.h's default)
    // Bake only these cells (a shard's; ascending or not, each once); the other rows stay empty.
    // Empty: every cell. A cell's row never depends on which other cells are baked.
    std::span<const uint32_t> cells;
    std::function<bool(double fraction)> progress;
};

struct RasterReport {
    uint64_t cells = 0, points = 0; // cells baked and points rendered (six views each)
    unsigned threads = 0;
    double seconds = 0.0, mean_visible = 0.0;
    bool cancelled = false;
    // What drew the views: "cpu", or "gpu: <renderer> via <platform>"; with Auto and no GPU,
    // device_note says why the CPU ran.
    std::string device = "cpu";
    std::string device_note;
};

// Lattice points of one grid cell in grid space: the centre first, then the lattice (above).
std::vector<glm::vec3> grid_cell_points(const ViewGrid& grid, uint32_t cell, float step,
                                        Lattice lattice = Lattice::Centred);

Pvs bake_raster_grid(const Zone& zone, const ViewGrid& grid, const RasterParams& params, RasterReport* report = nullptr);
// Throws std::invalid_argument for a zone without a tree.
Pvs bake_raster_regions(const Zone& zone, const RasterParams& params, RasterReport* report = nullptr);

// The points each cell would render (the zone's view grid cells, else its regions), a cell's cost
// for splitting a bake into shards: a point's six views cost about the same anywhere. Throws as
// the bakes do.
std::vector<uint32_t> raster_cell_point_counts(const Zone& zone, const RasterParams& params);

} // namespace pvs
