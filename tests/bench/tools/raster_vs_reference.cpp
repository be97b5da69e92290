// The raster baker on an OBJ level's view grid against its mesh reference: for each
// (points per cell, pixels per face side) pair given, the bake's wall time and the reference pairs
// it misses (what it would pop) and holds beyond it, next to what the level's own .hepvs misses.
// The reference is 256 open points a cell and 256 rays each (65 536 rays a cell), as the compare
// figures in docs/performance.md; the raster bakes use the default engine (pixel rays), the
// open-random lattice and 2 threads.
//
// Usage: raster_vs_reference LEVEL.obj POINTS RESOLUTION [POINTS RESOLUTION ...]
#include "visibility/eval/pvs_gap.h"
#include "visibility/raster/raster_vis.h"
#include "visibility/reference/mesh_reference.h"
#include "wld/zone_file.h"

#include <cstdio>
#include <cstdlib>
#include <exception>

int main(int argc, char** argv)
{
    using namespace pvs;
    if (argc < 4 || argc % 2) {
        std::fprintf(stderr, "usage: %s LEVEL.obj POINTS RESOLUTION [POINTS RESOLUTION ...]\n", argv[0]);
        return 2;
    }
    Zone zone;
    try {
        zone = load_zone(argv[1]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    if (!zone.view_grid || !zone.baked_pvs) {
        std::fprintf(stderr, "%s: no .hepvs beside it\n", argv[1]);
        return 1;
    }
    MeshReferenceParams reference_params;
    reference_params.points_per_cell = 256;
    reference_params.rays_per_point = 256;
    reference_params.threads = 2;
    MeshReferenceReport reference_report;
    const Pvs reference = bake_mesh_reference_grid(zone, *zone.view_grid, reference_params, &reference_report);
    std::printf("reference: %.1f s; the file misses %llu of its pairs\n", reference_report.seconds,
                static_cast<unsigned long long>(pvs_gap(&*zone.baked_pvs, reference).missing_bits));
    for (int i = 2; i + 1 < argc; i += 2) {
        RasterParams params;
        params.points_per_region = uint32_t(std::atoi(argv[i]));
        params.raster.resolution = uint32_t(std::atoi(argv[i + 1]));
        params.threads = 2;
        RasterReport report;
        const Pvs pvs = bake_raster_grid(zone, *zone.view_grid, params, &report);
        const PvsGap gap = pvs_gap(&pvs, reference);
        std::printf("%u points a cell, %u^2: %.1f s wall, misses %llu, %llu beyond the reference\n",
                    params.points_per_region, params.raster.resolution, report.seconds,
                    static_cast<unsigned long long>(gap.missing_bits), static_cast<unsigned long long>(gap.excess_bits));
        std::fflush(stdout);
    }
    return 0;
}
