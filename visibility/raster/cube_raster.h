// What a point sees, by rasterising the whole zone into the six faces of a cube map around it:
// an ID + depth buffer of resolution x resolution per face (90 degree views along +-x, +-y, +-z),
// the way the HateEngine baker renders colour-ID cube maps on a GPU (quake-doom-hepvs.md §5.6),
// here on the CPU over flat arrays. The faces whose pixels survive the depth test are "seen".
//
// Per point: each triangle is moved to the eye once; with back-face culling (the baker's default)
// a triangle facing away from the eye is dropped there, for all six views at once; the others are
// tested against each view's four side planes, clipped at the near distance, and filled with
// edge functions at pixel centres, depth as 1/w (linear in screen space). No allocation per
// point or per triangle: buffers and clip scratch live in the object. Not thread-safe: one per
// thread. Cost: O(triangles) per point plus the filled pixels (e1m1: about 0.3 ms a point at 64²).
//
// Translucent faces (translucent_face_mask: Quake 2 glass) hide nothing: they are drawn after
// every opaque one, depth-tested but writing no depth, and are seen wherever a pixel passes.
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace pvs {

struct CubeRasterOptions {
    uint32_t resolution = 64;    // pixels per cube face side
    bool cull_back_faces = true; // the HateEngine baker culls them (a wall seen from behind is not drawn)
    float near_distance = 0.05f; // zone units
};

class CubeRaster {
public:
    CubeRaster(const Zone& zone, const CubeRasterOptions& options);

    // Renders the six views around `eye` and sets seen[face] = 1 for each mesh face with a
    // pixel (seen must have one entry per face; entries already set stay set).
    void render(const glm::vec3& eye, std::vector<uint8_t>& seen);

private:
    struct Vertex {
        float u, v, inv_w; // screen position in pixels, 1 / depth
    };
    void add_face(const Mesh& mesh, uint32_t f);
    void draw(int view, const glm::vec3 (&d)[3], uint32_t face);
    void fill(int view, const Vertex& a, const Vertex& b, const Vertex& c, uint32_t face);

    std::vector<glm::vec3> corners_;     // three per triangle
    std::vector<uint32_t> triangle_face_;
    std::vector<glm::vec3> triangle_normal_;
    uint32_t resolution_;
    bool cull_back_faces_;
    float near_;
    size_t first_translucent_ = 0; // triangles from here on are translucent (drawn last)
    bool translucent_pass_ = false;
    std::vector<uint8_t>* seen_ = nullptr; // render()'s output, for the translucent pass
    std::vector<float> depth_;  // 6 * resolution^2: 1/w of the nearest fragment (0 = empty)
    std::vector<uint32_t> id_;  // face + 1 of the nearest fragment (0 = empty)
};

} // namespace pvs
