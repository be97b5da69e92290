// What a point sees, by casting one ray through every pixel centre of the six 90-degree views
// around it (the same views and pixel centres as cube_raster.h), in packets of 8 through Embree
// (MeshTracer::first_hits). The other way to the same answer as the rasteriser: measured on
// E1M1 (bench_raster, docs/performance.md), 2.4x faster at 64 pixels a side and 1.4x at 128,
// the faces seen equal to 0.2 % (pixels a triangle edge crosses: the rasteriser's fill rule
// against the exact ray). The raster baker uses it by default (RasterEngine::Rays).
//
// Back faces: with cull_back_faces (the HateEngine baker's default) a triangle seen from behind
// is passed through, as a renderer culling back faces draws nothing there; without, it stops the
// ray and is seen. The near distance is where each ray starts. The tracer is shared (read-only);
// one RayCube per thread (its buffers).
#pragma once

#include "visibility/raster/cube_raster.h"
#include "visibility/reference/mesh_tracer.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace pvs {

class RayCube {
public:
    RayCube(const MeshTracer& tracer, const CubeRasterOptions& options);

    // Sets seen[face] = 1 for each mesh face a pixel ray of the six views meets first (seen has
    // one entry per face; entries already set stay set).
    void render(const glm::vec3& eye, std::vector<uint8_t>& seen);

private:
    const MeshTracer& tracer_;
    CubeRasterOptions options_;
    MeshTracer::FaceFilter front_only_{{}, true}; // every face, front sides only (culls back faces)
    std::vector<glm::vec3> directions_; // one view's pixel directions, rows of resolution
    std::vector<MeshTracer::Hit> hits_;
};

} // namespace pvs
