// What a rendered picture shows, asked by rays instead of the depth buffer Irrlicht keeps to
// itself: the faces of the regions the picture drew, front sides only (the renderer culls back
// faces), traced with Embree (visibility/reference/mesh_tracer.h). Two questions:
//  - hidden(point): is a zone point behind a wall of the picture, seen from the view camera?
//    Overlay lines are depth-tested with it (ui/overlay_lines.h). A point on a drawn wall, or in
//    front of it within kDepthBias of its distance, is not hidden: portals, bounds boxes and
//    split planes lie on walls by construction and must stay in sight.
//  - face_under(direction): the face of the picture a ray from the eye meets first (the
//    inspector's hover); the same answer as an ID render of the picture away from face edges.
//
// Cost. A frame with every overlay on e1m1 tests 100 000+ line pieces, too many for one ray each
// (a few hundred ns each). So the picture is cut into kDepthTile-pixel tiles whose corner
// pixels are traced on demand, a row of corners at a time in packets of coherent rays (each
// row once per frame), for the view depth of the surface there. A
// surface across a tile has its depth between the corners' (1/depth is linear on the screen
// over a plane): a point nearer than every corner is in sight, one farther than every corner
// (by the bias) is hidden, and only points in between (on a wall, or at an edge where the
// surfaces differ) cost an exact ray. An occluder or a hole narrower than a tile that no corner
// sees can be missed: the price of an overlay that keeps its frame rate, stated here.
//
// The tracer is built once per zone (milliseconds on a Quake map; keep the object while the zone
// lives); set_frame() then costs O(faces + tiles). Not thread-safe.
#pragma once

#include "render/overlay_lines.h"
#include "visibility/camera.h"
#include "visibility/reference/mesh_tracer.h"
#include "visibility/zone.h"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <vector>

namespace pvs::ui {

// A point counts as hidden only when a drawn face lies nearer than (1 - kDepthBias) of its
// distance, less kDepthBiasUnits: walls are units thick, float error on a wall is far below both.
inline constexpr float kDepthBias = 0.01f;
inline constexpr float kDepthBiasUnits = 0.05f;
inline constexpr uint32_t kDepthTile = 8; // pixels

class PictureOcclusion final : public LineOcclusion {
public:
    explicit PictureOcclusion(const Zone& zone); // throws std::runtime_error when Embree fails

    // The picture's camera and size, and the regions it drew (ids out of range are ignored).
    void set_frame(const Zone& zone, const Camera& view, uint32_t width, uint32_t height,
                   std::span<const uint32_t> drawn_regions);
    bool hidden(const glm::vec3& point) const override;

    struct FaceHit {
        uint32_t face;
        float distance;
    };
    std::optional<FaceHit> face_under(const glm::vec3& direction) const;

    // Rays cast since the last set_frame (for the frame-time budget): tile corners and exact tests.
    uint64_t rays() const { return rays_; }

private:
    bool exact_hidden(const glm::vec3& point) const;
    float corner_depth(uint32_t cx, uint32_t cy) const; // view depth of the surface, +inf for none
    void trace_corner_row(uint32_t cy) const;

    MeshTracer tracer_;
    std::vector<uint8_t> drawn_faces_;
    MeshTracer::FaceFilter filter_;
    Camera view_;
    glm::vec3 forward_{1, 0, 0}, side_{0, -1, 0}, up_{0, 0, 1}; // the view's basis, side scaled to the image
    glm::mat4 view_projection_{1.0f};
    uint32_t width_ = 0, height_ = 0, corners_x_ = 0, corners_y_ = 0;
    mutable std::vector<float> corner_depths_;   // per corner, valid once its row is traced
    mutable std::vector<uint8_t> row_traced_;     // per corner row, this frame
    mutable std::vector<glm::vec3> row_directions_;
    mutable std::vector<MeshTracer::Hit> row_hits_;
    mutable uint64_t rays_ = 0;
};

} // namespace pvs::ui
