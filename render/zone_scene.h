// The Irrlicht form of a zone: vertex buffers grouped by material, the materials' textures, and
// a draw(visible_regions, mode) that draws only the faces of the regions a culler kept.
//
// Axis mapping (the only place in pvscope that converts): the zone is z-up and right-handed,
// Irrlicht is y-up and left-handed. Irrlicht (X, Y, Z) = zone (x, z, y): swapping y and z is a
// reflection, which turns the right-handed frame into a left-handed one, so the picture is the
// same as a right-handed renderer would draw (not mirrored): a face the zone winds counter-
// clockwise seen from the front still appears counter-clockwise on screen. Irrlicht's rule is
// the Direct3D one, front faces appear clockwise, so each triangle (a, b, c) is emitted as
// (a, c, b) and back-face culling stays on and keeps the zone's front faces.
//
// Buffers: each face gets its own copy of the vertices its triangles use (positions converted,
// uvs shifted by whole repeats towards 0 for fixed-point precision), appended to a batch of its
// material; a batch holds at most 65535 vertices so it draws with 16-bit indices. Faces with
// no triangles, out-of-range indices or more than 65535 vertices are skipped and counted.
//
// Why per-material batches with a per-frame "drawn" stamp, not per-region buffers: a face may
// be listed by several regions (Quake marksurfaces list a face in every leaf it touches), so
// per-region buffers would duplicate it and still need a stamp to draw it once; per-face draw
// calls would mean one setMaterial + draw per face (thousands per frame). Instead draw() walks
// the visible regions' face lists, stamps each face the first time it is met (so each face is
// drawn once however many visible regions list it), writes the face's colour for the mode into
// its own vertices and appends its indices to its batch's frame list; then each touched batch
// is one draw call. The first visible region (in list order) that lists a face owns it for
// RegionColors and Flags. Nothing is allocated per frame once the frame lists have grown.
//
// Flags mode: each batch keeps one frame list per tint (kFlagTints) besides the untinted one,
// and a tinted list is drawn with a tinted copy of the material's texture (texels blended with
// the tint, blend_tint), made the first time that material is drawn with that tint and kept
// with the scene; a material without pixels gets its flat colour blended in its vertex colour
// instead. The vertices, vertex colours (fake light) and rasteriser are the Textured ones, so an
// untinted face is exactly its Textured pixels. Within a batch the untinted faces are drawn
// first, then each tint in table order (only coplanar overlapping faces could tell).
//
// Not thread-safe. Borrows the zone (which must outlive the scene and stay unchanged) and the
// driver; the textures it adds to the driver are removed when the scene is destroyed.
#pragma once

#include "render/colour_codes.h"
#include "render/image.h"
#include "render/render_mode.h"
#include "visibility/zone.h"

#include <S3DVertex.h>
#include <SColor.h>
#include <vector3d.h>

#include <array>
#include <span>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace irr::video {
class IVideoDriver;
class ITexture;
} // namespace irr::video

namespace pvs::ui {

// Zone point (z-up) -> Irrlicht point (y-up). Also right for directions.
inline irr::core::vector3df to_irrlicht(const glm::vec3& p) { return {p.x, p.z, p.y}; }

class ZoneScene {
public:
    // Converts the mesh and uploads every material with pixels as a texture to `driver`.
    ZoneScene(const Zone& zone, irr::video::IVideoDriver& driver);
    ~ZoneScene();
    ZoneScene(const ZoneScene&) = delete;
    ZoneScene& operator=(const ZoneScene&) = delete;

    // True when `zone` is the object this scene was built from, with the same buffers and sizes.
    bool built_from(const Zone& zone) const;

    struct DrawStats {
        uint32_t faces = 0;
        uint64_t triangles = 0;
    };
    // Draws the faces of `visible_regions` (ids >= region count are ignored) with the driver's
    // current render target and transforms (world = identity). In IdBuffer mode the zone must
    // have at most kMaxIdFaces faces (the caller checks).
    // region_tints: one tint palette index (or kNoTint) per region, replacing Flags mode's.
    // opaque_only: translucent faces are left out (what shows through them).
    DrawStats draw(const std::vector<uint32_t>& visible_regions, RenderMode mode,
                   std::span<const uint32_t> region_tints = {}, bool opaque_only = false);

    uint32_t skipped_faces() const { return skipped_faces_; }
    uint32_t batch_count() const { return uint32_t(batches_.size()); }

private:
    static constexpr uint32_t kNoBatch = 0xFFFFFFFFu;
    struct FaceSlot {
        uint32_t batch = kNoBatch;
        uint32_t first_vertex = 0, vertex_count = 0; // in the batch's vertices
        uint32_t first_index = 0, index_count = 0;   // in the batch's indices
        irr::video::SColor base_color;               // unlit: white with a texture, else the flat colour
        float light = 1.0f;                          // fake light factor
        irr::video::SColor textured_color;           // base_color x light
    };
    // Frame lists per batch: [0] untinted, [1 + i] tinted with kFlagTints[i].
    static constexpr size_t kTintSlots = kTintPaletteSize + 1;
    struct Batch {
        uint32_t material = 0;
        irr::video::ITexture* texture = nullptr; // null: the material has no pixels
        uint8_t alpha = 255; // below 255: a translucent material (Quake 2 glass), drawn last and blended
        std::vector<irr::video::S3DVertex> vertices;
        std::vector<uint16_t> indices;       // every face's triangles, already in Irrlicht winding
        std::array<std::vector<uint16_t>, kTintSlots> frame_indices; // this frame's visible faces
        bool in_frame = false;                                        // listed in touched_
    };

    void build_faces();
    void upload_textures();
    uint32_t next_stamp();
    // The material's texture blended with kFlagTints[tint], made on first use; null when the
    // material has no pixels or the driver cannot make it.
    irr::video::ITexture* tinted_texture(uint32_t material, uint32_t tint);

    const Zone* zone_;
    irr::video::IVideoDriver* driver_;
    // What built_from compares.
    const void* fingerprint_[6];
    size_t fingerprint_sizes_[6];

    std::vector<irr::video::ITexture*> textures_; // per material, or null
    // Per material x tint: the tinted copy, once made; tinted_made_ says it was tried.
    std::vector<irr::video::ITexture*> tinted_textures_;
    // White textures of Quake 2's two translucent alphas (two thirds, a third), bound to translucent
    // faces without pixels.
    std::array<irr::video::ITexture*, 2> white_textures_{};
    std::vector<uint8_t> tinted_made_;
    std::vector<FaceSlot> faces_;
    std::vector<Batch> batches_;
    std::vector<uint32_t> face_stamp_;
    uint32_t stamp_ = 0;
    std::vector<uint32_t> touched_; // batches with frame indices, this frame
    uint32_t skipped_faces_ = 0;
};

} // namespace pvs::ui
