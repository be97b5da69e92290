#include "wld/eq/eq_zone_writer.h"

#include "visibility/bit_row.h"
#include "visibility/codec/eq_vislist.h"
#include "wld/eq/pfs_archive.h"
#include "wld/eq/pfs_crc.h"
#include "wld/eq/stb_image_io.h"
#include "wld/eq/wld_material.h"
#include "wld/eq/wld_mesh.h"
#include "wld/eq/wld_string_hash.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

namespace pvs::eq {

namespace {

constexpr uint32_t kRenderDiffuse = 0x80000001;   // user defined, diffuse (§6.5)
constexpr uint32_t kRenderSkyDome = 0x8000000D;   // user defined, sky dome
constexpr uint32_t kRenderInvisible = 0x00000000; // WQ and ZU: invisible
constexpr uint32_t kMaterialPen = 0x004E4E4E;     // the typical rgb_pen (§6.4)
constexpr uint32_t kMaxZonePoint = 999999;        // six digits in a DRNTP name
constexpr size_t kMaxStem = 60;                   // member names stay short (limit 1023)

[[noreturn]] void refuse(const std::string& what) { throw std::invalid_argument("write_eq_zone: " + what); }

std::string region_label(uint32_t region) { return "region " + std::to_string(region); }

// ---- Names ----

std::string sanitize_stem(std::string_view name)
{
    std::string out;
    for (const char c : name.substr(0, kMaxStem)) {
        const char lower = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
        const bool keep = (lower >= 'a' && lower <= 'z') || (lower >= '0' && lower <= '9') || lower == '_' ||
                          lower == '-' || lower == '.';
        out += keep ? lower : '_';
    }
    return out;
}

std::string texture_stem(std::string_view material_name)
{
    std::string stem = sanitize_stem(material_name);
    if (stem.size() >= 4 && stem.ends_with(".bmp"))
        stem.resize(stem.size() - 4);
    return stem.empty() ? "texture" : stem;
}

std::string upper(std::string text)
{
    for (char& c : text)
        if (c >= 'a' && c <= 'z')
            c = static_cast<char>(c - 'a' + 'A');
    return text;
}

// ---- Checking the zone ----

void check_faces(const Zone& zone)
{
    const Mesh& mesh = zone.mesh;
    if (mesh.indices.size() % 3 != 0)
        refuse("the mesh has " + std::to_string(mesh.indices.size()) + " indices, not a multiple of 3");
    for (const uint32_t index : mesh.indices)
        if (index >= mesh.positions.size())
            refuse("a mesh index names vertex " + std::to_string(index) + " of " +
                   std::to_string(mesh.positions.size()));
    if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size())
        refuse("the mesh has " + std::to_string(mesh.uvs.size()) + " uvs for " +
               std::to_string(mesh.positions.size()) + " positions");
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        if (uint64_t{face.first_triangle} + face.triangle_count > mesh.triangle_count())
            refuse("face " + std::to_string(f) + " names triangles past the mesh's " +
                   std::to_string(mesh.triangle_count()));
        if (face.material >= zone.materials.size())
            refuse("face " + std::to_string(f) + " names material " + std::to_string(face.material) + " of " +
                   std::to_string(zone.materials.size()));
    }
}

void check_zone(const Zone& zone)
{
    const size_t regions = zone.regions.size();
    if (zone.region_face_offsets.size() != regions + 1 && !(regions == 0 && zone.region_face_offsets.empty()))
        refuse("region_face_offsets has " + std::to_string(zone.region_face_offsets.size()) + " entries for " +
               std::to_string(regions) + " regions");
    for (size_t r = 0; r < regions; ++r)
        if (zone.region_face_offsets[r] > zone.region_face_offsets[r + 1] ||
            zone.region_face_offsets[r + 1] > zone.region_faces.size())
            refuse(region_label(uint32_t(r)) + " has a face range outside region_faces");
    for (const uint32_t face : zone.region_faces)
        if (face >= zone.mesh.faces.size())
            refuse("a region lists face " + std::to_string(face) + " of " + std::to_string(zone.mesh.faces.size()));
    check_faces(zone);
    for (const Material& m : zone.materials)
        if (m.has_pixels() && m.pixels.texel_count() != uint64_t{m.width} * m.height)
            refuse("material '" + m.name + "' has " + std::to_string(m.pixels.texel_count()) + " texels for " +
                   std::to_string(m.width) + "x" + std::to_string(m.height));
    for (size_t r = 0; r < regions; ++r)
        if (zone.regions[r].zone_line >= int64_t(zone.zone_lines.size()))
            refuse(region_label(uint32_t(r)) + " names zone line " + std::to_string(zone.regions[r].zone_line) +
                   " of " + std::to_string(zone.zone_lines.size()));
    if (zone.materials.size() > 0xFFFF)
        refuse(std::to_string(zone.materials.size()) + " materials; a 0x36 face group names at most 65535");
    if (zone.baked_pvs && zone.baked_pvs->region_count() != regions)
        refuse("the baked PVS has " + std::to_string(zone.baked_pvs->region_count()) + " regions, the zone " +
               std::to_string(regions));
}

// ---- The file being assembled ----

struct WldBuilder {
    WldStringTable strings;
    std::vector<WldFragmentBytes> fragments;

    // Appends a fragment; returns its 1-based number.
    int32_t add(uint32_t type, std::vector<uint8_t> body)
    {
        fragments.push_back({type, std::move(body)});
        return static_cast<int32_t>(fragments.size());
    }
};

// ---- Materials (§6.3-§6.6, §7.4.7) ----

uint32_t render_method_of(const Material& m)
{
    if (m.flags & kMaterialInvisible)
        return kRenderInvisible;
    return (m.flags & kMaterialSky) ? kRenderSkyDome : kRenderDiffuse;
}

// Each type grouped (§7.2: 0x03... 0x04... 0x05... 0x30... 0x31). Returns the palette's number.
int32_t write_materials(WldBuilder& b, const Zone& zone, const std::vector<std::string>& files)
{
    const size_t n = zone.materials.size();
    std::vector<int32_t> bitmaps(n), defs(n), sprites(n), materials(n);
    for (size_t i = 0; i < n; ++i)
        bitmaps[i] = b.add(kWldBitmapName, write_bitmap_name({0, {files[i]}}));
    for (size_t i = 0; i < n; ++i) {
        WldSpriteDef def;
        def.name_ref = b.strings.add(upper(texture_stem(files[i])) + "_SPRITE");
        def.frames = {bitmaps[i]};
        defs[i] = b.add(kWldSpriteDef, write_sprite_def(def));
    }
    for (size_t i = 0; i < n; ++i)
        sprites[i] = b.add(kWldSprite, write_sprite({0, defs[i], 0x50}));
    for (size_t i = 0; i < n; ++i) {
        WldMaterial m;
        m.name_ref = b.strings.add(upper(texture_stem(files[i])) + "_MDF");
        m.render_method = render_method_of(zone.materials[i]);
        m.rgb_pen = kMaterialPen;
        m.scaled_ambient = 0.75f;
        m.sprite_ref = sprites[i];
        materials[i] = b.add(kWldMaterial, write_material(m));
    }
    WldMaterialPalette palette;
    palette.name_ref = b.strings.add("ZONE_MP");
    palette.materials = materials;
    return b.add(kWldMaterialPalette, write_material_palette(palette));
}

// ---- Region meshes (§6.1, §6.2, §7.4.6) ----

// What write_mesh stores and parse_mesh gives back for one coordinate.
float on_grid(float p, float center, int scale)
{
    const double raw = static_cast<double>(std::llround(std::ldexp(double{p} - double{center}, scale)));
    return static_cast<float>(double{center} + std::ldexp(raw, -scale));
}

glm::vec3 rounded_middle(const std::vector<glm::vec3>& positions)
{
    Aabb box;
    for (const glm::vec3& p : positions)
        box.grow(p);
    glm::vec3 c;
    for (int k = 0; k < 3; ++k)
        c[k] = static_cast<float>(std::round((double{box.min[k]} + double{box.max[k]}) * 0.5));
    return c;
}

// Moves the positions onto the grid the file will store, with the center they will be stored
// with, until they stay put: the mesh then writes, reads back and writes again to the same bytes.
// Whole-unit centers keep a grid point a grid point when the center moves by a unit.
void settle_positions(WldMesh& m)
{
    for (int pass = 0; pass < 8; ++pass) {
        m.center = rounded_middle(m.positions);
        const int scale = mesh_scale_for(m);
        bool moved = false;
        for (glm::vec3& p : m.positions)
            for (int k = 0; k < 3; ++k) {
                const float q = on_grid(p[k], m.center[k], scale);
                moved = moved || q != p[k];
                p[k] = q;
            }
        if (!moved)
            return;
    }
}

bool fits_i16_uv(float u)
{
    const double raw = std::round(double{u} * 256.0);
    return raw >= -32768.0 && raw <= 32767.0;
}

// What the file stores for one vertex: the grid position (three i16) and the uv (two i16 in the
// old form, two float bit patterns in the new).
struct StoredVertex {
    uint64_t position = 0;
    uint64_t uv = 0;
    bool operator==(const StoredVertex&) const = default;
};
struct StoredVertexHash {
    size_t operator()(const StoredVertex& v) const
    {
        return std::hash<uint64_t>()(v.position * 0x9E3779B97F4A7C15ull ^ v.uv);
    }
};

StoredVertex stored_vertex(const WldMesh& m, size_t i, int scale)
{
    StoredVertex key;
    for (int k = 0; k < 3; ++k) {
        const auto raw = std::llround(std::ldexp(double{m.positions[i][k]} - double{m.center[k]}, scale));
        key.position = key.position << 16 | uint16_t(int16_t(raw));
    }
    const glm::vec2 uv = m.uvs[i];
    const double raw_u = std::round(double{uv.x} * 256.0), raw_v = std::round(double{uv.y} * 256.0);
    if (m.uv_form == WldUvForm::I16 && fits_i16_uv(uv.x) && fits_i16_uv(uv.y))
        key.uv = uint64_t{uint16_t(int16_t(raw_u))} << 16 | uint16_t(int16_t(raw_v));
    else // the new form; and old-form uvs that write_mesh will refuse anyway
        key.uv = uint64_t{std::bit_cast<uint32_t>(uv.x)} << 32 | std::bit_cast<uint32_t>(uv.y) | (1ull << 63);
    return key;
}

// Merges the vertices the file would store identically. The zone's faces each carry their own
// corners (a Quake face clipped into pieces repeats every corner of every piece), while a 0x36
// mesh needs each (position, uv) once: e1m1 converted drops from 55 150 to 29 734 vertices.
// Vertices stay in order of first use, so a file read back writes the same bytes.
void merge_stored_duplicates(WldMesh& m)
{
    const int scale = mesh_scale_for(m);
    std::unordered_map<StoredVertex, uint16_t, StoredVertexHash> first;
    first.reserve(m.positions.size());
    std::vector<uint16_t> remap(m.positions.size());
    size_t kept = 0;
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const auto [it, added] = first.try_emplace(stored_vertex(m, i, scale), static_cast<uint16_t>(kept));
        if (added) {
            m.positions[kept] = m.positions[i];
            m.uvs[kept] = m.uvs[i];
            ++kept;
        }
        remap[i] = it->second;
    }
    m.positions.resize(kept);
    m.uvs.resize(kept);
    for (WldMeshFace& f : m.faces)
        for (uint16_t& v : f.vertices)
            v = remap[v];
}

// A normal per vertex: the sum of its triangles' (area-weighted) normals, normalised.
void add_normals(WldMesh& m)
{
    std::vector<glm::vec3> sum(m.positions.size(), glm::vec3(0.0f));
    for (const WldMeshFace& f : m.faces) {
        const glm::vec3 a = m.positions[f.vertices[0]], b = m.positions[f.vertices[1]], c = m.positions[f.vertices[2]];
        const glm::vec3 n = glm::cross(b - a, c - a);
        for (const uint16_t v : f.vertices)
            sum[v] += n;
    }
    m.normals.resize(sum.size());
    for (size_t i = 0; i < sum.size(); ++i) {
        const float length = glm::length(sum[i]);
        m.normals[i] = length > 0.0f && std::isfinite(length) ? sum[i] / length : glm::vec3(0.0f);
    }
}

// The range of a face's uvs (indices out of range are skipped: the writer refuses them).
struct UvRange {
    glm::vec2 lo{std::numeric_limits<float>::max()}, hi{std::numeric_limits<float>::lowest()};
};
UvRange face_uv_range(const Mesh& mesh, const Face& face)
{
    UvRange range;
    for (size_t i = size_t(face.first_triangle) * 3; i < size_t(face.first_triangle + face.triangle_count) * 3; ++i)
        if (i < mesh.indices.size() && mesh.indices[i] < mesh.uvs.size()) {
            range.lo = glm::min(range.lo, mesh.uvs[mesh.indices[i]]);
            range.hi = glm::max(range.hi, mesh.uvs[mesh.indices[i]]);
        }
    return range;
}

// The whole number of texture repeats a face's uvs move by so that the old form (i16 / 256,
// about [-128, 128)) holds them: 0 when they fit as they are (so a written file writes back
// unchanged), else the rounded middle of their range; nothing when no whole shift makes them
// fit. The picture is the same.
std::optional<glm::vec2> old_form_uv_shift(const UvRange& range)
{
    glm::vec2 shift(0.0f);
    for (int k = 0; k < 2; ++k) {
        if (range.lo[k] > range.hi[k] || (fits_i16_uv(range.lo[k]) && fits_i16_uv(range.hi[k])))
            continue; // no uv, or they fit
        const double middle = std::round((double{range.lo[k]} + double{range.hi[k]}) * 0.5);
        shift[k] = static_cast<float>(middle);
        if (!std::isfinite(middle) || !fits_i16_uv(range.lo[k] - shift[k]) || !fits_i16_uv(range.hi[k] - shift[k]))
            return std::nullopt;
    }
    return shift;
}

glm::vec2 uv_shift(const Zone& zone, const Face& face, WldUvForm form, uint32_t face_index)
{
    if (form == WldUvForm::F32 || zone.mesh.uvs.empty())
        return glm::vec2(0.0f);
    const UvRange range = face_uv_range(zone.mesh, face);
    const std::optional<glm::vec2> shift = old_form_uv_shift(range);
    if (!shift)
        refuse("face " + std::to_string(face_index) + "'s uvs span [" + std::to_string(range.lo.x) + ", " +
               std::to_string(range.hi.x) + "] x [" + std::to_string(range.lo.y) + ", " + std::to_string(range.hi.y) +
               "]: more than the old WLD form's 256 repeats (write the new version)");
    return *shift;
}

// Copies the region's faces into a mesh: faces sorted by material (stable), each face's
// triangles in order, each (zone vertex, uv shift) copied once, in order of first use.
class RegionMeshBuilder {
public:
    RegionMeshBuilder(const Zone& zone, uint32_t region, WldUvForm form) : zone_(zone), region_(region), form_(form) {}

    WldMesh build()
    {
        std::vector<uint32_t> faces(zone_.faces_of_region(region_).begin(), zone_.faces_of_region(region_).end());
        std::stable_sort(faces.begin(), faces.end(), [&](uint32_t a, uint32_t b) {
            return zone_.mesh.faces[a].material < zone_.mesh.faces[b].material;
        });
        mesh_.uv_form = form_;
        for (const uint32_t f : faces)
            add_face(f);
        if (mesh_.positions.size() > 0xFFFF || mesh_.faces.size() > 0xFFFF)
            refuse(region_label(region_) + "'s mesh needs " + std::to_string(mesh_.positions.size()) +
                   " vertices and " + std::to_string(mesh_.faces.size()) +
                   " triangles; a 0x36 holds at most 65535 of each (u16 counts)");
        return std::move(mesh_);
    }

private:
    void add_face(uint32_t f)
    {
        const Face& face = zone_.mesh.faces[f];
        if (face.triangle_count == 0)
            return;
        const glm::vec2 shift = uv_shift(zone_, face, form_, f);
        if (mesh_.face_groups.empty() || mesh_.face_groups.back().material != face.material)
            mesh_.face_groups.push_back({0, static_cast<uint16_t>(face.material)});
        for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t) {
            WldMeshFace tri;
            for (int k = 0; k < 3; ++k)
                tri.vertices[k] = vertex(zone_.mesh.indices[3 * t + k], shift);
            mesh_.faces.push_back(tri);
            ++mesh_.face_groups.back().count; // wraps past 65535 only when build() refuses anyway
        }
    }

    uint16_t vertex(uint32_t zone_vertex, glm::vec2 shift)
    {
        const auto key = std::make_tuple(zone_vertex, shift.x, shift.y);
        const auto [it, added] = local_.try_emplace(key, static_cast<uint32_t>(mesh_.positions.size()));
        if (added) {
            mesh_.positions.push_back(zone_.mesh.positions[zone_vertex]);
            mesh_.uvs.push_back((zone_.mesh.uvs.empty() ? glm::vec2(0.0f) : zone_.mesh.uvs[zone_vertex]) - shift);
        }
        return static_cast<uint16_t>(it->second); // > 65535 is refused in build()
    }

    const Zone& zone_;
    uint32_t region_;
    WldUvForm form_;
    WldMesh mesh_;
    std::map<std::tuple<uint32_t, float, float>, uint32_t> local_;
};

// A bounding sphere of the mesh's vertices: the middle of their box and the farthest vertex.
glm::vec4 vertex_sphere(const std::vector<glm::vec3>& positions)
{
    Aabb box;
    for (const glm::vec3& p : positions)
        box.grow(p);
    const glm::vec3 c = box.center();
    float radius = 0.0f;
    for (const glm::vec3& p : positions)
        radius = std::max(radius, glm::length(p - c));
    return glm::vec4(c, radius);
}

// A sphere whose bounding box holds `box`, with center and radius on a 1/64 grid, so that the
// reader's box (center ± radius) comes back to the same sphere. Empty box: all zero.
glm::vec4 box_sphere(const Aabb& box)
{
    if (box.empty())
        return glm::vec4(0.0f);
    glm::vec3 c;
    double radius = 0.0;
    for (int k = 0; k < 3; ++k) {
        c[k] = static_cast<float>(std::round(double{box.center()[k]} * 64.0) / 64.0);
        radius = std::max({radius, double{c[k]} - double{box.min[k]}, double{box.max[k]} - double{c[k]}});
    }
    return glm::vec4(c, static_cast<float>(std::ceil(radius * 64.0) / 64.0));
}

struct WrittenMesh {
    int32_t fragment = 0; // 0: the region has no mesh
    glm::vec4 sphere{0.0f};
};

WrittenMesh write_region_mesh(WldBuilder& b, const Zone& zone, uint32_t r, int32_t palette, WldUvForm form)
{
    WldMesh mesh = RegionMeshBuilder(zone, r, form).build();
    if (mesh.faces.empty())
        return {0, box_sphere(zone.regions[r].bounds)};
    try {
        settle_positions(mesh);
        merge_stored_duplicates(mesh);
    } catch (const std::invalid_argument& e) {
        refuse(region_label(r) + ": " + e.what());
    }
    add_normals(mesh);
    char name[48];
    std::snprintf(name, sizeof name, "R%06u_DMSPRITEDEF", r + 1);
    mesh.name_ref = b.strings.add(name);
    mesh.material_palette_ref = palette;
    // The box as min/max relative to the centre, as WillEQ reads them (it adds the centre; the
    // spec's open question 7: LanternExtractor's notes call them absolute). Readers that build
    // distance boxes from these need them; zero (what many original zone meshes hold) gives none.
    const WldMeshBounds bounds = mesh_bounds(mesh);
    mesh.max_distance = bounds.max_distance;
    mesh.min = bounds.min - mesh.center;
    mesh.max = bounds.max - mesh.center;
    return {b.add(kWldMesh, write_mesh(mesh)), vertex_sphere(mesh.positions)};
}

// ---- The tree (§3, §7.4.8) ----

// Node numbers in preorder, front child first; solid and outside leaves become child 0.
WldBspTree build_tree(const Zone& zone)
{
    const BspTree& tree = zone.tree;
    WldBspTree out;
    std::vector<uint32_t> leaves_of_region(zone.regions.size(), 0);
    std::vector<uint8_t> seen(tree.nodes.size(), 0);
    struct Pending {
        int32_t child;
        uint32_t parent; // 1-based EQ node, 0 for the root
        int side;
    };
    std::vector<Pending> stack{{tree.root, 0, 0}};
    while (!stack.empty()) {
        const Pending p = stack.back();
        stack.pop_back();
        uint32_t number = 0;
        if (BspTree::is_leaf(p.child)) {
            const int32_t leaf = BspTree::leaf_index(p.child);
            if (leaf < 0 || size_t(leaf) >= tree.leaf_region.size())
                refuse("the tree names leaf " + std::to_string(leaf) + " of " +
                       std::to_string(tree.leaf_region.size()));
            const int32_t region = tree.leaf_region[size_t(leaf)];
            if (region >= int64_t(zone.regions.size()))
                refuse("leaf " + std::to_string(leaf) + " names region " + std::to_string(region) + " of " +
                       std::to_string(zone.regions.size()));
            if (region >= 0) {
                ++leaves_of_region[size_t(region)];
                out.nodes.push_back({glm::vec3(0.0f), 0.0f, uint32_t(region) + 1, 0, 0});
                number = uint32_t(out.nodes.size());
            }
        } else {
            if (size_t(p.child) >= tree.nodes.size() || seen[size_t(p.child)]++)
                refuse("the tree names node " + std::to_string(p.child) + " out of range or twice (a cycle)");
            const BspNode& node = tree.nodes[size_t(p.child)];
            out.nodes.push_back({node.normal, -node.dist, 0, 0, 0});
            number = uint32_t(out.nodes.size());
            stack.push_back({node.children[1], number, 1});
            stack.push_back({node.children[0], number, 0});
        }
        if (p.parent != 0)
            (p.side == 0 ? out.nodes[p.parent - 1].front : out.nodes[p.parent - 1].back) = number;
    }
    for (size_t r = 0; r < leaves_of_region.size(); ++r)
        if (leaves_of_region[r] != 1)
            refuse(region_label(uint32_t(r)) + " is " + std::to_string(leaves_of_region[r]) +
                   " leaves of the tree; an EverQuest region is exactly one leaf (§3.2)");
    return out;
}

// ---- Regions (§4.7) ----

std::vector<uint8_t> vislist_of(const Zone& zone, uint32_t r, std::vector<uint64_t>& row)
{
    std::vector<uint8_t> bytes;
    if (!zone.baked_pvs)
        return bytes; // range_count 0: "no PVS data" (readers show everything)
    const auto n = static_cast<uint32_t>(zone.regions.size());
    zone.baked_pvs->decode_row(r, row); // a missing row decodes as every region
    bits::set(row, r);
    encode_eq_vislist_bytes(row, n, bytes);
    if (bytes.size() > 0xFFFF)
        refuse(region_label(r) + "'s VISLIST takes " + std::to_string(bytes.size()) +
               " bytes; range_count is a u16 (at most 65535)");
    return bytes;
}

void write_regions(WldBuilder& b, const Zone& zone, const std::vector<WrittenMesh>& meshes)
{
    std::vector<uint64_t> row(bits::words_for(zone.regions.size()));
    for (uint32_t r = 0; r < zone.regions.size(); ++r) {
        char name[16];
        std::snprintf(name, sizeof name, "R%06u", r + 1);
        const int32_t name_ref = b.strings.add(name);
        const WldRegion region =
            make_interoperable_region(name_ref, vislist_of(zone, r, row), meshes[r].sphere, meshes[r].fragment);
        b.add(kWldRegion, write_region(region));
    }
}

// ---- Region flags (§5) ----

struct FlagType {
    uint32_t flag;
    const char* name;
};
// ZU's SL and LX's sln_ both read SLN_ZONE as slime; VWN_ZONE is LX/ES's vwater (ZU wants VWA).
constexpr FlagType kFlagTypes[] = {{kRegionWater, "WT_ZONE"},  {kRegionLava, "LA_ZONE"}, {kRegionSlime, "SLN_ZONE"},
                                   {kRegionPvp, "DRP_ZONE"},   {kRegionIce, "DRN_ZONE"}, {kRegionVWater, "VWN_ZONE"}};

void add_flag(WldBuilder& b, const std::string& name, std::vector<uint32_t> regions)
{
    WldRegionFlag flag;
    flag.name_ref = b.strings.add(name);
    flag.regions = std::move(regions);
    b.add(kWldRegionFlag, write_region_flag(flag));
}

// The zone line each region is in: its own, or for a region flagged as a zone line without
// one, an extra line after the zone's (so the flag survives). Returns the number of lines.
size_t zone_line_of_regions(const Zone& zone, std::vector<int64_t>& line_of)
{
    const size_t extra = zone.zone_lines.size();
    bool any_extra = false;
    line_of.assign(zone.regions.size(), -1);
    for (size_t r = 0; r < zone.regions.size(); ++r) {
        const Region& region = zone.regions[r];
        if (region.zone_line >= 0)
            line_of[r] = region.zone_line;
        else if (region.flags & kRegionZoneLine) {
            line_of[r] = int64_t(extra);
            any_extra = true;
        }
    }
    return extra + (any_extra ? 1 : 0);
}

// A zone line in water or lava is one 0x29 named WTNTP... or LANTP... (the combined names real
// zones use, read as water or lava + zone line by LX, ES and WillEQ, as water or lava by ZU's
// two-letter prefixes), not a WT_ZONE plus a DRNTP list: a reader that keeps one type per
// region would keep only the last one it read.
uint32_t combined_liquid(const Region& region, int64_t line)
{
    if (line < 0)
        return 0;
    if (region.flags & kRegionWater)
        return kRegionWater;
    if (region.flags & kRegionLava)
        return kRegionLava;
    return 0;
}

void write_flags(WldBuilder& b, const Zone& zone)
{
    std::vector<int64_t> line_of;
    const size_t lines = zone_line_of_regions(zone, line_of);
    if (lines > size_t{kMaxZonePoint} + 1)
        refuse(std::to_string(lines) + " zone lines; a DRNTP name holds zone points up to 999999");
    for (const FlagType& type : kFlagTypes) {
        std::vector<uint32_t> regions;
        for (uint32_t r = 0; r < zone.regions.size(); ++r)
            if ((zone.regions[r].flags & type.flag) && combined_liquid(zone.regions[r], line_of[r]) != type.flag)
                regions.push_back(r);
        if (!regions.empty())
            add_flag(b, type.name, std::move(regions));
    }
    struct LineKind {
        uint32_t liquid;
        const char* prefix;
    };
    for (size_t line = 0; line < lines; ++line)
        for (const LineKind kind : {LineKind{0, "DRNTP"}, LineKind{kRegionWater, "WTNTP"}, LineKind{kRegionLava, "LANTP"}}) {
            std::vector<uint32_t> regions;
            for (uint32_t r = 0; r < zone.regions.size(); ++r)
                if (line_of[r] == int64_t(line) && combined_liquid(zone.regions[r], line_of[r]) == kind.liquid)
                    regions.push_back(r);
            if (kind.liquid != 0 && regions.empty())
                continue;
            char name[32];
            std::snprintf(name, sizeof name, "%s00255%06zu_ZONE", kind.prefix, line);
            add_flag(b, name, std::move(regions)); // DRNTP even when empty: the line's index survives
        }
}

// ---- What the archive cannot keep ----

void note_flags(const Zone& zone, std::vector<std::string>& notes)
{
    size_t sky = 0, orphan_lines = 0;
    for (const Region& r : zone.regions) {
        sky += (r.flags & kRegionSky) != 0;
        orphan_lines += (r.flags & kRegionZoneLine) && r.zone_line < 0;
    }
    if (sky)
        notes.push_back(std::to_string(sky) + " sky regions: EverQuest has no sky region type, the flag is dropped");
    if (orphan_lines)
        notes.push_back(std::to_string(orphan_lines) +
                        " regions are flagged as zone lines without one: they share an extra zone line");
    // Zone line i is written as zone 255, zone point i: a target read from such a file (the reader
    // names it "zone 255 point i") is kept; any other is not.
    size_t lost = 0;
    const std::string* example = nullptr;
    for (size_t i = 0; i < zone.zone_lines.size(); ++i) {
        const std::string& target = zone.zone_lines[i].target;
        if (target.empty() || target == "zone 255 point " + std::to_string(i))
            continue;
        ++lost;
        if (!example)
            example = &target;
    }
    if (lost)
        notes.push_back(std::to_string(lost) + " zone-line targets (e.g. '" + *example +
                        "') are not representable: zone line i is written as zone 255, zone point i");
}

void note_materials(const Zone& zone, std::vector<std::string>& notes)
{
    size_t no_pixels = 0, alpha = 0, liquid = 0;
    for (const Material& m : zone.materials) {
        no_pixels += !m.has_pixels();
        liquid += (m.flags & kMaterialLiquid) != 0;
        for (size_t i = 0; i < m.pixels.texel_count(); ++i)
            if ((m.pixels.texel(i) >> 24) != 255) {
                ++alpha;
                break;
            }
    }
    if (no_pixels)
        notes.push_back(std::to_string(no_pixels) + " materials have no pixels: their 0x03 names a file the archive "
                                                    "does not hold");
    if (alpha)
        notes.push_back(std::to_string(alpha) + " materials have transparent pixels: 24-bit BMPs drop alpha");
    if (liquid)
        notes.push_back(std::to_string(liquid) + " liquid materials: EverQuest materials have no liquid flag");
}

void note_geometry(const Zone& zone, std::vector<std::string>& notes)
{
    if (zone.tree.tie_rule == TieRule::OnPlaneGoesBack)
        notes.push_back("the zone sends points on a split plane to the back child; EverQuest readers send them "
                        "front: points exactly on a plane may change region");
    std::vector<uint32_t> listings(zone.mesh.faces.size(), 0);
    for (const uint32_t f : zone.region_faces)
        ++listings[f];
    const auto repeated = std::count_if(listings.begin(), listings.end(), [](uint32_t n) { return n > 1; });
    if (repeated)
        notes.push_back(std::to_string(repeated) +
                        " faces are listed by several regions: each is written into every listing region's mesh");
    if (!zone.baked_pvs)
        notes.push_back("no baked PVS: every region's VISLIST is empty (range_count 0, readers show everything)");
}

// ---- Assembling ----

std::vector<PfsMember> texture_members(const Zone& zone, const std::vector<std::string>& files)
{
    std::vector<PfsMember> members;
    for (size_t i = 0; i < zone.materials.size(); ++i) {
        const Material& m = zone.materials[i];
        if (m.has_pixels())
            members.push_back({files[i], encode_bmp(m.width, m.height, material_rgba(m))});
    }
    return members;
}

std::vector<uint8_t> build_wld(const Zone& zone, const std::vector<std::string>& files, const EqWriteOptions& options)
{
    WldBuilder b;
    const int32_t palette = write_materials(b, zone, files);
    std::vector<WrittenMesh> meshes;
    for (uint32_t r = 0; r < zone.regions.size(); ++r)
        meshes.push_back(write_region_mesh(b, zone, r, palette, wld_uv_form(options.wld_version)));
    b.add(kWldBspTree, write_bsp_tree(build_tree(zone)));
    write_regions(b, zone, meshes);
    write_flags(b, zone);
    return write_wld(options.wld_version, b.strings.data(), b.fragments);
}

} // namespace

std::string eq_zone_wld_name(const std::string& zone_name)
{
    std::string stem = sanitize_stem(zone_name);
    return (stem.empty() ? "zone" : stem) + ".wld";
}

std::vector<std::string> eq_texture_file_names(const Zone& zone)
{
    std::vector<std::string> files;
    std::unordered_set<std::string> taken;
    std::unordered_set<uint32_t> crcs{kPfsNameListCrc};
    for (const Material& m : zone.materials) {
        const std::string stem = texture_stem(m.name);
        std::string file = stem + ".bmp";
        for (int n = 2; taken.count(file) || crcs.count(pfs_filename_crc(file)); ++n)
            file = stem + "_" + std::to_string(n) + ".bmp";
        taken.insert(file);
        crcs.insert(pfs_filename_crc(file));
        files.push_back(file);
    }
    return files;
}

EqZoneArchive write_eq_zone_archive(const Zone& zone, const std::string& zone_name, const EqWriteOptions& options)
{
    if (options.wld_version != kWldVersionOld && options.wld_version != kWldVersionNew)
        refuse("unknown WLD version " + std::to_string(options.wld_version));
    check_zone(zone);
    const std::vector<std::string> files = eq_texture_file_names(zone);
    std::vector<PfsMember> members{{eq_zone_wld_name(zone_name), build_wld(zone, files, options)}};
    for (PfsMember& texture : texture_members(zone, files))
        members.push_back(std::move(texture));

    EqZoneArchive out;
    PfsWriteOptions pfs;
    pfs.zlib_level = options.zlib_level;
    out.bytes = write_pfs(members, pfs);
    note_flags(zone, out.notes);
    note_materials(zone, out.notes);
    note_geometry(zone, out.notes);
    return out;
}

std::optional<uint32_t> face_beyond_old_wld_form(const Zone& zone)
{
    if (zone.mesh.uvs.empty())
        return std::nullopt;
    for (uint32_t f = 0; f < zone.mesh.faces.size(); ++f)
        if (!old_form_uv_shift(face_uv_range(zone.mesh, zone.mesh.faces[f])))
            return f;
    return std::nullopt;
}

std::vector<uint8_t> write_eq_zone(const Zone& zone, const std::string& zone_name, const EqWriteOptions& options)
{
    return write_eq_zone_archive(zone, zone_name, options).bytes;
}

} // namespace pvs::eq
