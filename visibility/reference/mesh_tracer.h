// Sight lines against the mesh itself, for zones with no BSP tree (OBJ levels): Intel's Embree 3
// (Debian's libembree-dev) in robust mode, which is watertight: a ray cannot slip between two
// triangles that share an edge, so a wall made of triangles stops it as a solid leaf would.
//
// first_hit() gives the first triangle a ray meets (both sides count: a ray from outside the
// level meets the back of a wall), its mesh face and whether the ray met its front (the side the
// triangle's counter-clockwise order faces, the side a camera in the level sees). A point is in
// open space (in_open_space) when rays along the six axes all meet a front face: from inside a
// closed level every first hit is a front face; from the rock or void around it some ray meets a
// back face or escapes. Thread-safe after construction (Embree's scene is read-only then).
//
// A FaceFilter narrows a query to what a picture shows: only the faces a renderer drew (a mask
// over the mesh faces) and, with front_only, only triangles whose front faces the ray's origin
// (a renderer with back-face culling draws nothing else). The inspector's depth-tested overlay
// lines and its hover use it: "is this point of a line behind a wall of the picture", "which
// face of the picture is under the mouse". Unfiltered queries do not pay for it (the filter is
// Embree's per-query context filter, not a per-geometry one).
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <span>

namespace pvs {

class MeshTracer {
public:
    struct Hit {
        bool hit = false;
        bool front = false;
        uint32_t face = 0;
        float t = 0.0f;
    };

    struct FaceFilter {
        std::span<const uint8_t> face_enabled; // per mesh face, non-zero = counts; empty = all count
        bool front_only = false;
    };

    explicit MeshTracer(const Zone& zone); // throws std::runtime_error when Embree fails
    ~MeshTracer();
    MeshTracer(const MeshTracer&) = delete;
    MeshTracer& operator=(const MeshTracer&) = delete;

    Hit first_hit(const glm::vec3& origin, const glm::vec3& direction, float t_far) const;
    Hit first_hit(const glm::vec3& origin, const glm::vec3& direction, float t_far, const FaceFilter& filter) const;
    // first_hit for many rays from one origin (a camera's pixel rays), traced in packets of 8
    // (Embree's rtcIntersect8): coherent rays share their walk down the hierarchy. out[i] is the
    // hit of directions[i]; out must be as long as directions.
    // With `filter`, only the triangles it lets through count (as first_hit with a filter).
    void first_hits(const glm::vec3& origin, std::span<const glm::vec3> directions, float t_near, float t_far,
                    std::span<Hit> out, const FaceFilter* filter = nullptr) const;
    // Whether any triangle the filter lets through lies on the ray within (0, t_far): cheaper
    // than first_hit (Embree stops at the first one it finds).
    bool occluded(const glm::vec3& origin, const glm::vec3& direction, float t_far, const FaceFilter& filter) const;
    // clearance: also no face nearer than this along the six axes (an eye that close to a wall
    // would see through it past the near plane).
    bool in_open_space(const glm::vec3& point, float clearance = 0.0f) const;
    size_t triangle_count() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace pvs
