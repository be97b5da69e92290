#include "wld/eq/wld_mesh.h"

#include "wld/eq/wld_body.h"
#include "wld/eq/wld_material.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace pvs::eq {

namespace {

// The nine u16 counts at body offset 0x4C, in file order.
enum Count { kVertices, kUvs, kNormals, kColors, kFaces, kSkinGroups, kFaceGroups, kVertexGroups, kMeshOps };
constexpr const char* kCountNames[9] = {"vertex_count",
                                        "uv_count",
                                        "normal_count",
                                        "color_count",
                                        "face_count",
                                        "skin_group_count",
                                        "face_material_group_count",
                                        "vertex_material_group_count",
                                        "meshop_count"};

// The palette size the face groups are checked against; nullopt when the reference leads to no
// fragment (0, or a name nothing carries).
std::optional<size_t> palette_size(WldBodyReader& r, int32_t ref, uint64_t ref_at)
{
    const uint32_t number = resolve_fragment_ref(r.wld(), ref);
    if (number == 0)
        return std::nullopt;
    // A positive reference was type-checked when read; a by-name one is checked here.
    const uint32_t type = r.wld().fragments[number - 1].type;
    if (type != kWldMaterialPalette)
        r.fail(ref_at, "material_palette_ref " + std::to_string(ref) + " names " +
                           wld_fragment_label(number, type) + ", not a 0x31 material palette");
    return parse_material_palette(r.wld(), number).materials.size();
}

// N values of T in a row (x, y[, z]), as stored.
template <glm::length_t N, class T>
glm::vec<N, T> read_components(WldBodyReader& r, const char* what, int64_t index)
{
    glm::vec<N, T> v(T{0});
    for (glm::length_t k = 0; k < N; ++k)
        v[k] = r.read<T>(what, index);
    return v;
}

// `count` elements of two u16 (skin groups, face and vertex material groups), in file order.
template <class Pair>
std::vector<Pair> read_u16_pairs(WldBodyReader& r, uint16_t count, const char* what)
{
    std::vector<Pair> pairs;
    pairs.reserve(count);
    for (uint16_t i = 0; i < count; ++i) {
        const auto first = r.read<uint16_t>(what, i);
        const auto second = r.read<uint16_t>(what, i);
        pairs.push_back({first, second});
    }
    return pairs;
}

float decode_coordinate(float center, int16_t raw, uint16_t scale)
{
    // In double, then rounded once to float.
    return static_cast<float>(double{center} + std::ldexp(static_cast<double>(raw), -int{scale}));
}

template <class Container>
uint16_t count16(const Container& items, const char* what)
{
    if (items.size() > 0xFFFF)
        throw std::invalid_argument(std::string("0x36 mesh: ") + std::to_string(items.size()) + " " + what +
                                    " (the count is a u16)");
    return static_cast<uint16_t>(items.size());
}

} // namespace

WldUvForm wld_uv_form(uint32_t version)
{
    // ZU/WQ: anything but the old version is the new form (parse_wld accepts only the two).
    return version == kWldVersionOld ? WldUvForm::I16 : WldUvForm::F32;
}

WldMesh parse_mesh(const WldFile& wld, uint32_t fragment_number)
{
    WldBodyReader r(wld, fragment_number, kWldMesh);
    WldMesh m;
    m.name_ref = r.read<int32_t>("name_ref");
    m.flags = r.read<uint32_t>("flags");
    const uint64_t palette_at = r.at();
    m.material_palette_ref = r.fragment_ref("material_palette_ref", kWldMaterialPalette);
    m.animation_ref = r.fragment_ref("animation_ref", kWldAnyFragmentType);
    m.fragment3 = r.read<int32_t>("fragment3");
    m.fragment4 = r.read<int32_t>("fragment4");
    const uint64_t center_at = r.at();
    m.center = r.vec3("center");
    if (!all_finite(m.center))
        r.fail(center_at, "center is not a finite number");
    for (uint32_t& p : m.params2)
        p = r.read<uint32_t>("params2");
    m.max_distance = r.read<float>("max_distance");
    m.min = r.vec3("min");
    m.max = r.vec3("max");
    const uint64_t counts_at = r.at();
    uint16_t counts[9];
    for (int k = 0; k < 9; ++k)
        counts[k] = r.read<uint16_t>(kCountNames[k]);
    const uint64_t scale_at = r.at();
    m.scale = r.read<uint16_t>("scale");
    if (m.scale > 0x7FFF)
        r.fail(scale_at, "scale " + std::to_string(m.scale) +
                             " is above 32767 (LQ/QL read it as a u16, ZU/WQ as an i16: they disagree)");
    m.uv_form = wld_uv_form(wld.header.version);

    // Each array's count is checked when its array is reached, against the bytes left then.
    const auto check = [&](Count k, uint64_t element_bytes) {
        r.check_count(counts[k], counts_at + 2 * uint64_t(k), element_bytes, kCountNames[k]);
        return counts[k];
    };

    const uint16_t nv = check(kVertices, 6);
    m.positions.reserve(nv);
    for (uint16_t i = 0; i < nv; ++i) {
        const auto raw = read_components<3, int16_t>(r, "vertex", i);
        m.positions.emplace_back(decode_coordinate(m.center.x, raw.x, m.scale),
                                 decode_coordinate(m.center.y, raw.y, m.scale),
                                 decode_coordinate(m.center.z, raw.z, m.scale));
    }

    const bool uv16 = m.uv_form == WldUvForm::I16;
    const uint16_t nt = check(kUvs, uv16 ? 4 : 8);
    m.uvs.reserve(nt);
    for (uint16_t i = 0; i < nt; ++i)
        m.uvs.push_back(uv16 ? glm::vec2(read_components<2, int16_t>(r, "uv", i)) / 256.0f
                             : read_components<2, float>(r, "uv", i));

    const uint16_t nn = check(kNormals, 3);
    m.normals.reserve(nn);
    for (uint16_t i = 0; i < nn; ++i)
        m.normals.push_back(glm::vec3(read_components<3, int8_t>(r, "normal", i)) / 127.0f);

    const uint16_t nc = check(kColors, 4);
    m.colors.reserve(nc);
    for (uint16_t i = 0; i < nc; ++i)
        m.colors.push_back(r.read<uint32_t>("color", i));

    const uint16_t nf = check(kFaces, 8);
    m.faces.reserve(nf);
    for (uint16_t i = 0; i < nf; ++i) {
        WldMeshFace& face = m.faces.emplace_back();
        face.flags = r.read<uint16_t>("face flags", i);
        for (int k = 0; k < 3; ++k) {
            const uint64_t index_at = r.at();
            face.vertices[k] = r.read<uint16_t>("face vertex", i);
            if (face.vertices[k] >= nv)
                r.fail(index_at, "face " + std::to_string(i) + " vertex " + std::to_string(k) + " is " +
                                     std::to_string(face.vertices[k]) + " but the mesh has " + std::to_string(nv) +
                                     " vertices");
        }
    }

    m.skin_groups = read_u16_pairs<WldSkinGroup>(r, check(kSkinGroups, 4), "skin group");

    const uint16_t ng = check(kFaceGroups, 4);
    const std::optional<size_t> materials = palette_size(r, m.material_palette_ref, palette_at);
    const uint64_t groups_at = r.at();
    m.face_groups = read_u16_pairs<WldMeshGroup>(r, ng, "face material group");
    uint64_t covered = 0;
    for (uint16_t i = 0; i < ng; ++i) {
        const WldMeshGroup group = m.face_groups[i];
        if (materials && group.material >= *materials)
            r.fail(groups_at + 4 * uint64_t{i} + 2,
                   "face material group " + std::to_string(i) + " names material " + std::to_string(group.material) +
                       " but the palette (fragment " +
                       std::to_string(resolve_fragment_ref(wld, m.material_palette_ref)) + ") has " +
                       std::to_string(*materials) + " materials");
        covered += group.count;
    }
    if (covered != nf)
        r.fail(counts_at + 2 * kFaceGroups, "the face material groups cover " + std::to_string(covered) +
                                                " faces but face_count is " + std::to_string(nf));

    m.vertex_groups = read_u16_pairs<WldMeshGroup>(r, check(kVertexGroups, 4), "vertex material group");

    const uint16_t nm = check(kMeshOps, 6);
    m.mesh_ops.reserve(nm);
    for (uint16_t i = 0; i < nm; ++i) {
        WldMeshOp& op = m.mesh_ops.emplace_back();
        const auto data = r.bytes(4, "mesh op", i);
        std::copy(data.begin(), data.end(), op.data.begin());
        op.param = r.read<uint8_t>("mesh op", i);
        op.type = r.read<uint8_t>("mesh op", i);
    }
    return m;
}

uint16_t mesh_scale_for(const WldMesh& mesh)
{
    if (!all_finite(mesh.center))
        throw std::invalid_argument("0x36 mesh: the center is not finite");
    double largest = 0.0; // the largest |position - center| over every axis
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3 p = mesh.positions[i];
        if (!all_finite(p))
            throw std::invalid_argument("0x36 mesh: position " + std::to_string(i) + " is not finite");
        for (int k = 0; k < 3; ++k)
            largest = std::max(largest, std::abs(double{p[k]} - double{mesh.center[k]}));
    }
    // Rounding is monotonic, so the largest offset decides for every vertex; llround gives at
    // most 32767 exactly below 32767.5 (halves round away from zero).
    for (int s = kWldMeshMaxScale; s >= 0; --s)
        if (std::ldexp(largest, s) < 32767.5)
            return static_cast<uint16_t>(s);
    throw std::invalid_argument("0x36 mesh: a position is " + std::to_string(largest) +
                                " units from the center on one axis; at most 32767 fit (move the center)");
}

std::vector<uint8_t> write_mesh(const WldMesh& m)
{
    const uint16_t scale = mesh_scale_for(m);
    const uint16_t counts[9] = {count16(m.positions, "positions"),     count16(m.uvs, "uvs"),
                                count16(m.normals, "normals"),         count16(m.colors, "colors"),
                                count16(m.faces, "faces"),             count16(m.skin_groups, "skin groups"),
                                count16(m.face_groups, "face groups"), count16(m.vertex_groups, "vertex groups"),
                                count16(m.mesh_ops, "mesh ops")};
    for (size_t i = 0; i < m.faces.size(); ++i)
        for (const uint16_t v : m.faces[i].vertices)
            if (v >= m.positions.size())
                throw std::invalid_argument("0x36 mesh: face " + std::to_string(i) + " names vertex " +
                                            std::to_string(v) + " of " + std::to_string(m.positions.size()));
    uint64_t covered = 0;
    for (const WldMeshGroup& g : m.face_groups)
        covered += g.count;
    if (covered != m.faces.size())
        throw std::invalid_argument("0x36 mesh: the face groups cover " + std::to_string(covered) + " faces of " +
                                    std::to_string(m.faces.size()));

    WldByteWriter w;
    w.put(m.name_ref);
    w.put(m.flags);
    w.put(m.material_palette_ref);
    w.put(m.animation_ref);
    w.put(m.fragment3);
    w.put(m.fragment4);
    w.put(m.center);
    w.put_each(m.params2);
    w.put(m.max_distance);
    w.put(m.min);
    w.put(m.max);
    w.put_each(counts);
    w.put(scale);

    for (const glm::vec3 p : m.positions)
        for (int k = 0; k < 3; ++k) // in [-32767, 32767] by the choice of scale
            w.put(static_cast<int16_t>(std::llround(std::ldexp(double{p[k]} - double{m.center[k]}, scale))));
    for (const glm::vec2 uv : m.uvs) {
        if (m.uv_form == WldUvForm::F32) {
            w.put(uv);
            continue;
        }
        for (int k = 0; k < 2; ++k) {
            const double raw = std::round(double{uv[k]} * 256.0);
            if (!(raw >= -32768.0 && raw <= 32767.0)) // also refuses NaN
                throw std::invalid_argument("0x36 mesh: uv component " + std::to_string(uv[k]) +
                                            " does not fit the old form (i16 / 256: [-128, 128))");
            w.put(static_cast<int16_t>(raw));
        }
    }
    for (const glm::vec3 n : m.normals)
        for (int k = 0; k < 3; ++k) {
            const double raw = std::round(double{n[k]} * 127.0);
            if (!(raw >= -128.0 && raw <= 127.0))
                throw std::invalid_argument("0x36 mesh: normal component " + std::to_string(n[k]) +
                                            " does not fit an i8 / 127");
            w.put(static_cast<int8_t>(raw));
        }
    w.put_each(m.colors);
    for (const WldMeshFace& f : m.faces) {
        w.put(f.flags);
        w.put_each(f.vertices);
    }
    for (const WldSkinGroup& g : m.skin_groups) {
        w.put(g.vertex_count);
        w.put(g.bone);
    }
    for (const auto* groups : {&m.face_groups, &m.vertex_groups})
        for (const WldMeshGroup& g : *groups) {
            w.put(g.count);
            w.put(g.material);
        }
    for (const WldMeshOp& op : m.mesh_ops) {
        w.put_bytes(op.data);
        w.put(op.param);
        w.put(op.type);
    }
    return w.finish();
}

std::vector<uint16_t> face_materials(const WldMesh& mesh)
{
    std::vector<uint16_t> out;
    out.reserve(mesh.faces.size());
    for (const WldMeshGroup& g : mesh.face_groups)
        out.insert(out.end(), g.count, g.material);
    return out;
}

WldMeshBounds mesh_bounds(const WldMesh& mesh)
{
    WldMeshBounds b;
    if (mesh.positions.empty())
        return b;
    b.min = b.max = mesh.positions.front();
    for (const glm::vec3 p : mesh.positions) {
        for (int k = 0; k < 3; ++k) {
            b.min[k] = std::min(b.min[k], p[k]);
            b.max[k] = std::max(b.max[k], p[k]);
        }
        const glm::vec3 d = p - mesh.center;
        b.max_distance = std::max(b.max_distance, std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z));
    }
    return b;
}

} // namespace pvs::eq
