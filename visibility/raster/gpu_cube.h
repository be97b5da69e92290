// What a set of points sees, rendered on a GPU: the raster baker's `--device gpu` path, the way
// the HateEngine baker renders colour-ID cube maps. The same six 90-degree views and pixel
// centres as the CPU paths (cube_raster.h, ray_cube.h): view k looks along +-axis k/2, its
// picture spans the other two axes in cyclic order, pixel (x, y) at ((2x + 1) / r - 1,
// (2y + 1) / r - 1); the same near distance and back-face rule.
//
// How: the zone's triangles are uploaded once (three vertices each, with their face's id). Each
// view is one draw into a layer of an R32UI texture array (face + 1, 0 = empty) with a 32-bit
// float depth buffer holding near / w (reversed depth: as exact far away as near). When a batch of
// layers is drawn, a compute pass reads every pixel and ORs its face's bit into a buffer of face
// bits; only those bits (faces / 8 bytes) are read back, once per render() call, never the
// pixels. Translucent faces (translucent_face_mask) are drawn after the opaque ones, depth-tested
// but writing nothing, and their fragment shader sets their bit directly: they hide nothing, as
// on the CPU.
//
// A pixel whose centre lies within 1/1024 of a pixel of its face's outline takes its depth but
// does not count its face: the GPU snaps vertices to a sub-pixel grid and decides such a centre
// either way, and along seams (a wall going on above a ceiling, seen from under it) that handed
// it faces no exact sample sees (gpu_cube.cpp). So the answers differ from the CPU rasteriser's
// only where a pixel centre lies that close to an edge or coplanar faces tie in depth, and do not
// depend on the batch size: each view is cleared and drawn alone, and the OR ignores order.
//
// Contract: one GpuCube per GlHeadless, used on the thread that opened it. `batch_views` is the
// number of views drawn before each compute pass (0: as many as fit in 256 MiB of ID buffer,
// at most 6 * 64, halved while the GPU reports itself out of memory, down to 6); the constructor
// throws GlUnavailable when the device lacks what is needed (shaders, memory), naming what and
// suggesting a smaller batch or the CPU.
#pragma once

#include "visibility/raster/cube_raster.h"
#include "visibility/raster/gl_headless.h"
#include "visibility/zone.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace pvs {

class GpuCube {
public:
    GpuCube(GlHeadless& context, const Zone& zone, const CubeRasterOptions& options, uint32_t batch_views = 0);
    ~GpuCube();
    GpuCube(const GpuCube&) = delete;
    GpuCube& operator=(const GpuCube&) = delete;

    // Renders the six views around every eye and sets seen[face] = 1 for each mesh face with a
    // pixel in any of them (seen has one entry per face; entries already set stay set).
    void render(std::span<const glm::vec3> eyes, std::vector<uint8_t>& seen);

    // One view's picture as drawn (view k as above): face + 1 per pixel, 0 where nothing is,
    // rows of `resolution` from the picture's bottom; kUncounted is set where the pixel centre
    // lies so near the face's outline that the face is not counted (gpu_cube.cpp says why). Read
    // back pixel by pixel, so for tests and pictures, not for baking.
    static constexpr uint32_t kUncounted = 0x80000000u;
    std::vector<uint32_t> view_ids(const glm::vec3& eye, int view);

    uint32_t batch_views() const { return batch_views_; }

private:
    void upload_mesh(const Zone& zone);
    void make_targets(uint32_t requested_batch);
    void make_programs();
    void draw_view(const glm::vec3& eye, int view, uint32_t layer);
    void reduce(uint32_t layers);

    const GlApi& gl_;
    uint32_t resolution_;
    float near_;
    bool cull_back_faces_;
    uint32_t faces_;
    uint32_t batch_views_;
    int32_t opaque_vertices_ = 0, translucent_vertices_ = 0;
    // GL objects.
    uint32_t vertex_buffer_ = 0, vertex_array_ = 0, bits_buffer_ = 0;
    uint32_t ids_ = 0, depth_ = 0, framebuffer_ = 0;
    uint32_t opaque_program_ = 0, translucent_program_ = 0, reduce_program_ = 0;
    int32_t opaque_eye_ = -1, opaque_view_ = -1; // uniform locations
    int32_t translucent_eye_ = -1, translucent_view_ = -1;
    std::vector<uint32_t> bits_; // read-back face bits
};

} // namespace pvs
