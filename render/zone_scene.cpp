#include "render/zone_scene.h"

#include <IImage.h>
#include <ITexture.h>
#include <IVideoDriver.h>
#include <SMaterial.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <string>

namespace pvs::ui {

namespace {

using irr::video::SColor;

constexpr uint32_t kMaxBatchVertices = 65535;

// The alpha a material is drawn with: Quake 2's 0.33 and 0.66 for its translucent surfaces,
// opaque otherwise.
constexpr uint8_t kTranslucentAlpha = 168, kFaintAlpha = 84; // SURF_TRANS66, SURF_TRANS33

uint8_t translucent_alpha(const Material* material)
{
    if (!material || !(material->flags & kMaterialTranslucent))
        return 255;
    return material->flags & kMaterialFaint ? kFaintAlpha : kTranslucentAlpha;
}

// FNV-1a of a material name: the flat colour of a material without pixels.
SColor flat_material_color(const std::string& name)
{
    uint32_t h = 2166136261u;
    for (unsigned char c : name)
        h = (h ^ c) * 16777619u;
    return SColor(255, 96 + (h & 0x7F), 96 + ((h >> 8) & 0x7F), 96 + ((h >> 16) & 0x7F));
}

// A fixed fake light from above and to one side, so walls facing different ways stay apart in
// the textured picture (Quake's lightmaps are not used). Returns a factor in [0.62, 1].
float fake_light(const glm::vec3& normal)
{
    const glm::vec3 light = glm::normalize(glm::vec3(0.4f, 0.3f, 0.85f));
    return 0.62f + 0.38f * (0.5f + 0.5f * glm::dot(normal, light));
}

// A material of one colour, or none: a stand-in where the texture is not at hand (Quake 2 keeps
// its .wal textures outside the map). Nothing on such a face tells a wall from the floor or the
// ceiling but its light, so it is shaded more strongly by its normal: a factor in [0.35, 1]
// (a floor near 0.95, a ceiling 0.4, walls 0.5 to 0.85 by the way they face).
bool one_colour(const Material* material)
{
    return !material || material->pixels.empty() ||
           (material->pixels.palettized() && material->pixels.palette_size() == 1);
}

float flat_light(const glm::vec3& normal)
{
    const glm::vec3 light = glm::normalize(glm::vec3(0.45f, 0.3f, 0.84f));
    return 0.35f + 0.65f * (0.5f + 0.5f * glm::dot(normal, light));
}

SColor scaled(SColor c, float factor)
{
    auto channel = [factor](uint32_t v) { return uint32_t(std::lround(std::clamp(float(v) * factor, 0.0f, 255.0f))); };
    return SColor(255, channel(c.getRed()), channel(c.getGreen()), channel(c.getBlue()));
}

// An A8R8G8B8 texture of the material's pixels, each blended by `blend` (0xRRGGBB -> 0xRRGGBB).
template <typename Blend>
irr::video::ITexture* make_texture(irr::video::IVideoDriver& driver, const Material& material, const std::string& name,
                                   Blend blend)
{
    const uint32_t alpha = translucent_alpha(&material); // 255 unless translucent: texels keep theirs
    const std::vector<uint8_t> rgba = material_rgba(material);
    if (material.width == 0 || material.height == 0 || rgba.size() != size_t(material.width) * material.height * 4)
        return nullptr;
    std::vector<uint32_t> argb(size_t(material.width) * material.height);
    for (size_t p = 0; p < argb.size(); ++p) {
        const uint8_t* px = &rgba[4 * p];
        argb[p] = (uint32_t(px[3]) * alpha / 255u) << 24 | blend(uint32_t(px[0]) << 16 | uint32_t(px[1]) << 8 | px[2]);
    }
    irr::video::IImage* image = driver.createImageFromData(
        irr::video::ECF_A8R8G8B8, irr::core::dimension2d<irr::u32>(material.width, material.height), argb.data(), false,
        true);
    if (!image)
        return nullptr;
    irr::video::ITexture* texture = driver.addTexture(name.c_str(), image);
    image->drop();
    return texture;
}

} // namespace

ZoneScene::ZoneScene(const Zone& zone, irr::video::IVideoDriver& driver) : zone_(&zone), driver_(&driver)
{
    fingerprint_[0] = &zone;
    fingerprint_[1] = zone.mesh.positions.data();
    fingerprint_[2] = zone.mesh.indices.data();
    fingerprint_[3] = zone.mesh.faces.data();
    fingerprint_[4] = zone.materials.data();
    fingerprint_[5] = zone.region_faces.data();
    fingerprint_sizes_[0] = zone.regions.size();
    fingerprint_sizes_[1] = zone.mesh.positions.size();
    fingerprint_sizes_[2] = zone.mesh.indices.size();
    fingerprint_sizes_[3] = zone.mesh.faces.size();
    fingerprint_sizes_[4] = zone.materials.size();
    fingerprint_sizes_[5] = zone.region_faces.size();
    upload_textures();
    build_faces();
    face_stamp_.assign(zone.mesh.faces.size(), 0);
}

ZoneScene::~ZoneScene()
{
    for (irr::video::ITexture* texture : textures_)
        if (texture)
            driver_->removeTexture(texture);
    for (irr::video::ITexture* texture : tinted_textures_)
        if (texture)
            driver_->removeTexture(texture);
    for (irr::video::ITexture* texture : white_textures_)
        if (texture)
            driver_->removeTexture(texture);
}

bool ZoneScene::built_from(const Zone& zone) const
{
    const void* pointers[6] = {&zone, zone.mesh.positions.data(), zone.mesh.indices.data(), zone.mesh.faces.data(),
                               zone.materials.data(), zone.region_faces.data()};
    const size_t sizes[6] = {zone.regions.size(), zone.mesh.positions.size(), zone.mesh.indices.size(),
                             zone.mesh.faces.size(), zone.materials.size(), zone.region_faces.size()};
    return std::equal(pointers, pointers + 6, fingerprint_) && std::equal(sizes, sizes + 6, fingerprint_sizes_);
}

void ZoneScene::upload_textures()
{
    textures_.assign(zone_->materials.size(), nullptr);
    tinted_textures_.assign(zone_->materials.size() * kTintPaletteSize, nullptr);
    tinted_made_.assign(tinted_textures_.size(), 0);
    for (size_t m = 0; m < zone_->materials.size(); ++m) {
        // Unique within the driver: several scenes (zones) may share one driver over time.
        const std::string name = "pvscope/" + std::to_string(reinterpret_cast<uintptr_t>(this)) + "/" +
                                 std::to_string(m) + "/" + zone_->materials[m].name;
        textures_[m] = make_texture(*driver_, zone_->materials[m], name, [](uint32_t rgb) { return rgb; });
    }
    // Burning's Video (Irrlicht 1.8) blends "over" only by a texture's alpha channel (its vertex
    // alpha mode adds, and untextured triangles take its opaque Gouraud path): translucent faces
    // without pixels are drawn with a white texture of their alpha, tinted by the vertex colour.
    const bool any_translucent = std::any_of(zone_->materials.begin(), zone_->materials.end(),
                                             [](const Material& m) { return translucent_alpha(&m) < 255; });
    for (int faint = 0; faint < 2 && any_translucent; ++faint) {
        Material white{"white", 2, 2, {}, kMaterialTranslucent | (faint ? kMaterialFaint : 0u)};
        set_material_rgba(white, 2, 2, std::vector<uint8_t>(16, 255));
        white_textures_[faint] =
            make_texture(*driver_, white,
                         "pvscope/" + std::to_string(reinterpret_cast<uintptr_t>(this)) + "/white" + std::to_string(faint),
                         [](uint32_t rgb) { return rgb; });
    }
}

irr::video::ITexture* ZoneScene::tinted_texture(uint32_t material, uint32_t tint)
{
    if (material >= zone_->materials.size() || tint >= kTintPaletteSize)
        return nullptr;
    const size_t slot = size_t(material) * kTintPaletteSize + tint;
    if (!tinted_made_[slot]) {
        tinted_made_[slot] = 1;
        const std::string name = "pvscope/" + std::to_string(reinterpret_cast<uintptr_t>(this)) + "/" +
                                 std::to_string(material) + "/tint" + std::to_string(tint) + "/" +
                                 zone_->materials[material].name;
        const uint32_t tint_rgb = tint_palette_rgb(tint);
        tinted_textures_[slot] = make_texture(*driver_, zone_->materials[material], name,
                                              [tint_rgb](uint32_t rgb) { return blend_tint(rgb, tint_rgb); });
    }
    return tinted_textures_[slot];
}

void ZoneScene::build_faces()
{
    const Mesh& mesh = zone_->mesh;
    faces_.assign(mesh.faces.size(), FaceSlot{});
    std::vector<uint32_t> open_batch(zone_->materials.size() + 1, kNoBatch); // per material (+1: out of range)
    std::vector<uint32_t> used;                                            // the face's vertices, sorted
    const size_t triangle_count = mesh.triangle_count();
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        bool valid = face.triangle_count > 0 && size_t(face.first_triangle) + face.triangle_count <= triangle_count;
        used.clear();
        for (uint32_t t = 0; valid && t < face.triangle_count; ++t)
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t index = mesh.indices[3 * (size_t(face.first_triangle) + t) + k];
                valid = valid && index < mesh.positions.size();
                used.push_back(index);
            }
        if (valid) {
            std::sort(used.begin(), used.end());
            used.erase(std::unique(used.begin(), used.end()), used.end());
            valid = used.size() <= kMaxBatchVertices;
        }
        const uint32_t material_index = std::min<uint32_t>(face.material, uint32_t(zone_->materials.size()));
        const Material* material = material_index < zone_->materials.size() ? &zone_->materials[material_index] : nullptr;
        if (material && (material->flags & kMaterialInvisible))
            valid = false; // never drawn, in any mode: it must not hide what is behind it either
        if (!valid) {
            ++skipped_faces_;
            continue;
        }

        uint32_t& batch_index = open_batch[material_index];
        if (batch_index == kNoBatch || batches_[batch_index].vertices.size() + used.size() > kMaxBatchVertices) {
            batch_index = uint32_t(batches_.size());
            Batch& batch = batches_.emplace_back();
            batch.material = material_index;
            batch.texture = material ? textures_[material_index] : nullptr;
            batch.alpha = translucent_alpha(material);
        }
        Batch& batch = batches_[batch_index];

        // Face normal (zone frame) from its first non-degenerate triangle, for the fake light.
        glm::vec3 normal(0.0f, 0.0f, 1.0f);
        for (uint32_t t = 0; t < face.triangle_count; ++t) {
            const uint32_t* tri = &mesh.indices[3 * (size_t(face.first_triangle) + t)];
            const glm::vec3 n = glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                           mesh.positions[tri[2]] - mesh.positions[tri[0]]);
            if (glm::dot(n, n) > 0.0f) {
                normal = glm::normalize(n);
                break;
            }
        }
        // Shift the uvs by whole repeats so the face's smallest uv is in [0, 1): the picture is
        // the same (textures repeat) and Burning's fixed-point texture coordinates stay small.
        glm::vec2 uv_min(0.0f);
        if (mesh.uvs.size() == mesh.positions.size()) {
            uv_min = glm::vec2(std::numeric_limits<float>::infinity());
            for (uint32_t v : used)
                uv_min = glm::min(uv_min, mesh.uvs[v]);
            uv_min = glm::floor(uv_min);
            if (!std::isfinite(uv_min.x) || !std::isfinite(uv_min.y))
                uv_min = glm::vec2(0.0f);
        }

        FaceSlot& slot = faces_[f];
        slot.batch = batch_index;
        slot.first_vertex = uint32_t(batch.vertices.size());
        slot.vertex_count = uint32_t(used.size());
        slot.first_index = uint32_t(batch.indices.size());
        slot.index_count = 3 * face.triangle_count;
        slot.light = one_colour(material) ? flat_light(normal) : fake_light(normal);
        slot.base_color =
            batch.texture ? SColor(255, 255, 255, 255) : flat_material_color(material ? material->name : "");
        slot.textured_color = scaled(slot.base_color, slot.light);
        const irr::core::vector3df irr_normal = to_irrlicht(normal);
        for (uint32_t v : used) {
            const glm::vec2 uv = mesh.uvs.size() == mesh.positions.size() ? mesh.uvs[v] - uv_min : glm::vec2(0.0f);
            batch.vertices.emplace_back(to_irrlicht(mesh.positions[v]), irr_normal, slot.textured_color,
                                        irr::core::vector2df(uv.x, uv.y));
        }
        auto local = [&](uint32_t index) {
            return uint16_t(slot.first_vertex + (std::lower_bound(used.begin(), used.end(), index) - used.begin()));
        };
        for (uint32_t t = 0; t < face.triangle_count; ++t) {
            const uint32_t* tri = &mesh.indices[3 * (size_t(face.first_triangle) + t)];
            // (a, b, c) -> (a, c, b): see the winding note in the header.
            batch.indices.push_back(local(tri[0]));
            batch.indices.push_back(local(tri[2]));
            batch.indices.push_back(local(tri[1]));
        }
    }
}

uint32_t ZoneScene::next_stamp()
{
    if (++stamp_ == 0) { // wrapped after 2^32 frames: forget every old stamp
        std::fill(face_stamp_.begin(), face_stamp_.end(), 0u);
        stamp_ = 1;
    }
    return stamp_;
}

ZoneScene::DrawStats ZoneScene::draw(const std::vector<uint32_t>& visible_regions, RenderMode mode,
                                     std::span<const uint32_t> region_tints, bool opaque_only)
{
    DrawStats stats;
    const uint32_t stamp = next_stamp();
    touched_.clear();
    const size_t region_count = zone_->region_count();
    for (uint32_t region : visible_regions) {
        if (region >= region_count)
            continue;
        const SColor region_colour(0xFF000000u | region_color(region));
        const bool tints_given = region < region_tints.size() && mode != RenderMode::RegionColors &&
                                 mode != RenderMode::IdBuffer;
        const uint32_t tint = tints_given                  ? region_tints[region]
                              : mode == RenderMode::Flags ? flag_tint_index(zone_->regions[region].flags)
                                                          : kNoTint;
        for (uint32_t f : zone_->faces_of_region(region)) {
            if (f >= faces_.size() || face_stamp_[f] == stamp)
                continue;
            face_stamp_[f] = stamp;
            const FaceSlot& slot = faces_[f];
            if (slot.batch == kNoBatch)
                continue;
            Batch& batch = batches_[slot.batch];
            if (opaque_only && batch.alpha < 255)
                continue;
            SColor colour = slot.textured_color;
            size_t list = 0;
            if (mode == RenderMode::RegionColors)
                colour = region_colour;
            else if (mode == RenderMode::IdBuffer)
                colour = SColor(0xFF000000u | encode_id(f + 1));
            else if (tint != kNoTint) {
                list = 1 + tint;
                if (!batch.texture) { // no pixels to tint: tint the flat colour before the light
                    const uint32_t tinted = blend_tint(slot.base_color.color & 0xFFFFFFu, tint_palette_rgb(tint));
                    colour = scaled(SColor(0xFF000000u | tinted), slot.light);
                }
            }
            for (uint32_t v = 0; v < slot.vertex_count; ++v)
                batch.vertices[slot.first_vertex + v].Color = colour;
            if (!batch.in_frame) {
                batch.in_frame = true;
                touched_.push_back(slot.batch);
            }
            std::vector<uint16_t>& frame = batch.frame_indices[list];
            frame.insert(frame.end(), batch.indices.begin() + slot.first_index,
                         batch.indices.begin() + slot.first_index + slot.index_count);
            ++stats.faces;
            stats.triangles += slot.index_count / 3;
        }
    }

    // Batch order (= material order) keeps the frame independent of the regions' order.
    std::sort(touched_.begin(), touched_.end());
    irr::video::SMaterial material;
    material.MaterialType = irr::video::EMT_SOLID;
    material.Lighting = false;
    material.FogEnable = false;
    material.AntiAliasing = irr::video::EAAM_OFF;
    material.BackfaceCulling = true;
    material.FrontfaceCulling = false;
    material.ZBuffer = irr::video::ECFN_LESSEQUAL;
    material.ZWriteEnable = true;
    material.GouraudShading = true;
    const bool textured_mode = mode == RenderMode::Textured || mode == RenderMode::Flags;
    // Translucent batches last, blended by their textures' alpha over what is drawn and writing no
    // depth, so everything behind them shows (as Quake 2 draws its SURF_TRANS33/66 surfaces).
    const auto translucent = [&](const Batch& batch) { return batch.alpha < 255 && mode != RenderMode::IdBuffer; };
    std::stable_partition(touched_.begin(), touched_.end(), [&](uint32_t b) { return !translucent(batches_[b]); });
    for (uint32_t b : touched_) {
        Batch& batch = batches_[b];
        material.MaterialType = translucent(batch) ? irr::video::EMT_TRANSPARENT_ALPHA_CHANNEL : irr::video::EMT_SOLID;
        material.ZWriteEnable = !translucent(batch);
        for (size_t list = 0; list < kTintSlots; ++list) {
            std::vector<uint16_t>& frame = batch.frame_indices[list];
            if (frame.empty())
                continue;
            irr::video::ITexture* texture = nullptr;
            if (textured_mode && batch.texture) {
                texture = list == 0 ? batch.texture : tinted_texture(batch.material, uint32_t(list - 1));
                if (!texture) // the tinted copy could not be made: the plain texture, untinted
                    texture = batch.texture;
            }
            if (!texture && translucent(batch))
                texture = white_textures_[batch.alpha == kFaintAlpha ? 1 : 0];
            material.setTexture(0, texture);
            material.UseMipMaps = texture != nullptr;
            material.TextureLayer[0].BilinearFilter = false; // nearest texel, like Quake's own renderer
            material.TextureLayer[0].TrilinearFilter = false;
            material.TextureLayer[0].AnisotropicFilter = 0;
            driver_->setMaterial(material);
            driver_->drawVertexPrimitiveList(batch.vertices.data(), uint32_t(batch.vertices.size()), frame.data(),
                                             uint32_t(frame.size() / 3), irr::video::EVT_STANDARD,
                                             irr::scene::EPT_TRIANGLES, irr::video::EIT_16BIT);
            frame.clear();
        }
        batch.in_frame = false;
    }
    return stats;
}

} // namespace pvs::ui
