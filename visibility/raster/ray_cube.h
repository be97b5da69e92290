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
//
// Translucent faces (`translucent`, per mesh face: translucent_face_mask) hide nothing: the rays
// meet the opaque faces first, then each pixel's translucent faces in front of its opaque hit
// are seen too, layer after layer (up to kTranslucentLayers), as the rasteriser draws them.
#pragma once

#include "visibility/raster/cube_raster.h"
#include "visibility/reference/mesh_tracer.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace pvs {

class RayCube {
public:
    static constexpr int kTranslucentLayers = 16;

    RayCube(const MeshTracer& tracer, const CubeRasterOptions& options, std::span<const uint8_t> translucent = {});

    // Sets seen[face] = 1 for each mesh face a pixel ray of the six views meets first (seen has
    // one entry per face; entries already set stay set).
    void render(const glm::vec3& eye, std::vector<uint8_t>& seen);

private:
    void see_translucent(const glm::vec3& eye, std::vector<uint8_t>& seen);

    const MeshTracer& tracer_;
    CubeRasterOptions options_;
    std::vector<uint8_t> opaque_;         // per face, 1 = opaque (only when some face is translucent)
    std::vector<uint8_t> translucent_;    // per face, 1 = translucent; empty when none is
    MeshTracer::FaceFilter opaque_filter_;      // the faces that stop a ray
    MeshTracer::FaceFilter translucent_filter_; // the faces a ray passes, seen
    std::vector<glm::vec3> directions_; // one view's pixel directions, rows of resolution
    std::vector<MeshTracer::Hit> hits_;
    std::vector<MeshTracer::Hit> translucent_hits_;
};

} // namespace pvs
