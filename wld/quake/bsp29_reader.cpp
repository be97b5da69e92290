#include "wld/quake/bsp29_reader.h"

#include "visibility/bit_row.h"
#include "visibility/codec/quake_rle.h"
#include "wld/common/byte_reader.h"
#include "wld/quake/bsp_lumps.h"
#include "wld/quake/changelevel_lines.h"
#include "wld/quake/entities.h"
#include "wld/quake/quake_palette.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <limits>
#include <cmath>
#include <glm/geometric.hpp>

namespace pvs::quake {

namespace {

// Lump names as the rest of this file spells them.
constexpr BspLump kEntities = kLumpEntities, kPlanes = kLumpPlanes, kTextures = kLumpTextures,
                  kVertexes = kLumpVertexes, kVisibility = kLumpVisibility, kNodes = kLumpNodes,
                  kTexinfo = kLumpTexinfo, kFaces = kLumpFaces, kLeafs = kLumpLeafs,
                  kMarksurfaces = kLumpMarksurfaces, kEdges = kLumpEdges, kSurfedges = kLumpSurfedges,
                  kModels = kLumpModels;

enum Contents : int32_t { kEmpty = -1, kSolid = -2, kWater = -3, kSlime = -4, kLava = -5, kSky = -6 };
constexpr uint32_t kMaxFaceEdges = 1024; // qbsp's limit is far lower; this only bounds bad files

// Everything the loading steps share: the reader and the parsed lump table of the file's variant.
struct Bsp {
    ByteReader in;
    BspLumps table;
    const BspLumpSpan* lumps = table.lumps;
    const BspLayout& layout() const { return table.layout; }
    uint64_t record(BspLump lump, uint32_t index) const { return table.record(lump, index); }
    void check_index(BspLump lump, int64_t index, uint64_t at, const char* what) const
    {
        table.check_index(in, lump, index, at, what);
    }
    // A count or index field that is 16-bit in BSP 29 and 32-bit in the wide variants.
    uint32_t read_u(uint64_t at, const char* what) const
    {
        return layout().wide ? in.read<uint32_t>(at, what) : in.read<uint16_t>(at, what);
    }
};

struct Model {
    glm::vec3 mins, maxs;
    int32_t headnode0;
    int32_t visleafs;
    int32_t firstface, numfaces;
};

glm::vec3 read_vec3(const Bsp& bsp, uint64_t at, const char* what)
{
    glm::vec3 v{bsp.in.read<float>(at, what), bsp.in.read<float>(at + 4, what), bsp.in.read<float>(at + 8, what)};
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        bsp.in.fail(at, std::string(what) + " is not a finite number");
    return v;
}

glm::vec3 read_short3(const Bsp& bsp, uint64_t at, const char* what)
{
    return {bsp.in.read<int16_t>(at, what), bsp.in.read<int16_t>(at + 2, what), bsp.in.read<int16_t>(at + 4, what)};
}

Model read_model(const Bsp& bsp, uint32_t index)
{
    const uint64_t at = bsp.record(kModels, index);
    Model m;
    m.mins = read_vec3(bsp, at, "model mins");
    m.maxs = read_vec3(bsp, at + 12, "model maxs");
    m.headnode0 = bsp.in.read<int32_t>(at + 36, "model headnode");
    m.visleafs = bsp.in.read<int32_t>(at + 52, "model visleafs");
    m.firstface = bsp.in.read<int32_t>(at + 56, "model firstface");
    m.numfaces = bsp.in.read<int32_t>(at + 60, "model numfaces");
    return m;
}

// Node children: read as u16 (the QuakeSpasm extension for > 32767 nodes): a value below the
// node count is a node, anything else is leaf 65535 - value. For ordinary maps this equals the
// signed rule (c >= 0 node, else leaf -1 - c).
int32_t decode_child(const Bsp& bsp, uint16_t raw, uint64_t at)
{
    if (raw < bsp.lumps[kNodes].count)
        return raw;
    const int32_t leaf = 65535 - raw;
    bsp.check_index(kLeafs, leaf, at, "node child leaf");
    return ~leaf;
}

// BSP2 and 2PSB children: i32, a node when >= 0, else leaf -(c + 1) = ~c.
int32_t decode_wide_child(const Bsp& bsp, int32_t raw, uint64_t at)
{
    if (raw >= 0) {
        bsp.check_index(kNodes, raw, at, "node child");
        return raw;
    }
    bsp.check_index(kLeafs, int64_t{~raw}, at, "node child leaf");
    return raw;
}

void read_tree(const Bsp& bsp, const Model& world, Zone& zone)
{
    BspTree& tree = zone.tree;
    tree.tie_rule = TieRule::OnPlaneGoesBack;
    tree.nodes.resize(bsp.lumps[kNodes].count);
    for (uint32_t i = 0; i < tree.nodes.size(); ++i) {
        const uint64_t at = bsp.record(kNodes, i);
        const auto planenum = bsp.in.read<int32_t>(at, "node planenum");
        bsp.check_index(kPlanes, planenum, at, "node plane");
        const uint64_t plane_at = bsp.record(kPlanes, uint32_t(planenum));
        BspNode& node = tree.nodes[i];
        node.normal = read_vec3(bsp, plane_at, "plane normal");
        node.dist = bsp.in.read<float>(plane_at + 12, "plane dist");
        if (!std::isfinite(node.dist))
            bsp.in.fail(plane_at + 12, "plane dist is not a finite number");
        if (bsp.layout().wide) {
            node.children[0] = decode_wide_child(bsp, bsp.in.read<int32_t>(at + 4, "node child"), at + 4);
            node.children[1] = decode_wide_child(bsp, bsp.in.read<int32_t>(at + 8, "node child"), at + 8);
        } else {
            node.children[0] = decode_child(bsp, bsp.in.read<uint16_t>(at + 4, "node child"), at + 4);
            node.children[1] = decode_child(bsp, bsp.in.read<uint16_t>(at + 6, "node child"), at + 6);
        }
    }
    if (bsp.lumps[kNodes].count == 0)
        tree.root = ~0; // a tree with no node: everything is the solid leaf 0
    else {
        bsp.check_index(kNodes, world.headnode0, bsp.record(kModels, 0) + 36, "world head node");
        tree.root = world.headnode0;
    }

    // The walk must end: every node reachable from the root is reached exactly once.
    if (const int32_t twice = node_reached_twice(tree); twice >= 0)
        bsp.in.fail(bsp.record(kNodes, uint32_t(twice)),
                    "node " + std::to_string(twice) + " is reached twice from the root (the tree has a cycle)");
}

uint32_t contents_flags(int32_t contents)
{
    switch (contents) {
    case kWater: return kRegionWater;
    case kSlime: return kRegionSlime;
    case kLava: return kRegionLava;
    case kSky: return kRegionSky;
    default: return 0;
    }
}

void count_contents(const Bsp& bsp, Zone& zone)
{
    uint64_t counts[7] = {}; // empty, solid, water, slime, lava, sky, other
    for (uint32_t i = 0; i < bsp.lumps[kLeafs].count; ++i) {
        const auto contents = bsp.in.read<int32_t>(bsp.record(kLeafs, i), "leaf contents");
        ++counts[(contents <= kEmpty && contents >= kSky) ? -1 - contents : 6];
    }
    const char* names[7] = {"leaves.empty", "leaves.solid", "leaves.water", "leaves.slime",
                            "leaves.lava",  "leaves.sky",   "leaves.other_contents"};
    for (int i = 0; i < 7; ++i)
        zone.source.counts.emplace_back(names[i], counts[i]);
}

void read_regions(const Bsp& bsp, uint32_t visleafs, Zone& zone)
{
    zone.tree.leaf_region.assign(bsp.lumps[kLeafs].count, kLeafSolid);
    zone.regions.resize(visleafs);
    zone.region_face_offsets.assign(visleafs + 1, 0);
    for (uint32_t r = 0; r < visleafs; ++r) {
        const uint32_t leaf = r + 1;
        const uint64_t at = bsp.record(kLeafs, leaf);
        Region& region = zone.regions[r];
        region.flags = contents_flags(bsp.in.read<int32_t>(at, "leaf contents"));
        if (bsp.layout().float_bounds) {
            region.bounds.grow(read_vec3(bsp, at + 8, "leaf mins"));
            region.bounds.grow(read_vec3(bsp, at + 20, "leaf maxs"));
        } else {
            region.bounds.grow(read_short3(bsp, at + 8, "leaf mins"));
            region.bounds.grow(read_short3(bsp, at + 14, "leaf maxs"));
        }
        zone.tree.leaf_region[leaf] = static_cast<int32_t>(r);
    }
    count_contents(bsp, zone);
}

// World faces -> mesh, one fan per face. Returns nothing; fills zone.mesh.
void read_faces(const Bsp& bsp, const Model& world, Zone& zone)
{
    const uint64_t models_at = bsp.record(kModels, 0);
    if (world.firstface < 0 || world.numfaces < 0 ||
        int64_t{world.firstface} + world.numfaces > int64_t{bsp.lumps[kFaces].count})
        bsp.in.fail(models_at + 56, "world model's face range is outside the faces lump");

    Mesh& mesh = zone.mesh;
    mesh.faces.resize(uint32_t(world.numfaces));
    std::vector<glm::vec3> polygon;
    for (uint32_t f = 0; f < uint32_t(world.numfaces); ++f) {
        const uint64_t at = bsp.record(kFaces, uint32_t(world.firstface) + f);
        const BspLayout& l = bsp.layout();
        const int64_t planenum = l.wide ? int64_t{bsp.in.read<int32_t>(at, "face planenum")}
                                        : int64_t{bsp.in.read<uint16_t>(at, "face planenum")};
        const int64_t side = l.wide ? int64_t{bsp.in.read<int32_t>(at + l.face_side, "face side")}
                                    : int64_t{bsp.in.read<int16_t>(at + l.face_side, "face side")};
        const auto firstedge = bsp.in.read<int32_t>(at + l.face_first_edge, "face firstedge");
        const int64_t numedges = l.wide ? int64_t{bsp.in.read<int32_t>(at + l.face_edge_count, "face numedges")}
                                        : int64_t{bsp.in.read<uint16_t>(at + l.face_edge_count, "face numedges")};
        const int64_t texinfo = l.wide ? int64_t{bsp.in.read<int32_t>(at + l.face_texinfo, "face texinfo")}
                                       : int64_t{bsp.in.read<uint16_t>(at + l.face_texinfo, "face texinfo")};
        bsp.check_index(kPlanes, planenum, at, "face plane");
        bsp.check_index(kTexinfo, texinfo, at + l.face_texinfo, "face texinfo");
        if (numedges < 3 || numedges > kMaxFaceEdges)
            bsp.in.fail(at + l.face_edge_count, "face has " + std::to_string(numedges) + " edges (3.." +
                                                    std::to_string(kMaxFaceEdges) + " expected)");
        if (firstedge < 0 || int64_t{firstedge} + numedges > int64_t{bsp.lumps[kSurfedges].count})
            bsp.in.fail(at + l.face_first_edge, "face edge range is outside the surfedges lump");

        polygon.clear();
        for (uint32_t k = 0; k < numedges; ++k) {
            const uint64_t se_at = bsp.record(kSurfedges, uint32_t(firstedge) + k);
            const auto e = bsp.in.read<int32_t>(se_at, "surfedge");
            if (e == std::numeric_limits<int32_t>::min())
                bsp.in.fail(se_at, "surfedge value is out of range");
            const int32_t edge = e >= 0 ? e : -e;
            bsp.check_index(kEdges, edge, se_at, "surfedge edge");
            const uint64_t edge_at = bsp.record(kEdges, uint32_t(edge));
            const uint32_t v = bsp.read_u(edge_at + (e >= 0 ? 0 : bsp.layout().edge_size / 2), "edge vertex");
            bsp.check_index(kVertexes, v, bsp.record(kEdges, uint32_t(edge)), "edge vertex");
            polygon.push_back(read_vec3(bsp, bsp.record(kVertexes, v), "vertex"));
        }

        // Texture axes -> uv in repeats of the texture.
        const uint64_t ti = bsp.record(kTexinfo, uint32_t(texinfo));
        float axes[8];
        for (int k = 0; k < 8; ++k) {
            axes[k] = bsp.in.read<float>(ti + 4 * uint64_t(k), "texinfo vector");
            if (!std::isfinite(axes[k]))
                bsp.in.fail(ti + 4 * uint64_t(k), "texinfo vector is not a finite number");
        }
        const auto miptex = bsp.in.read<int32_t>(ti + 32, "texinfo miptex");
        if (miptex < 0 || size_t(miptex) >= zone.materials.size())
            bsp.in.fail(ti + 32, "texinfo names miptex " + std::to_string(miptex) + " but the texture lump has " +
                                     std::to_string(zone.materials.size()));
        const Material& material = zone.materials[size_t(miptex)];
        const float inv_w = 1.0f / float(material.width ? material.width : 64);
        const float inv_h = 1.0f / float(material.height ? material.height : 64);

        // Winding: make the fan counter-clockwise seen from the face's front (plane normal, negated when side != 0).
        glm::vec3 face_normal = read_vec3(bsp, bsp.record(kPlanes, uint32_t(planenum)), "plane normal");
        if (side != 0)
            face_normal = -face_normal;
        glm::vec3 newell{0.0f};
        for (size_t k = 0; k < polygon.size(); ++k)
            newell += glm::cross(polygon[k], polygon[(k + 1) % polygon.size()]);
        const bool reverse = glm::dot(newell, face_normal) < 0.0f;

        const auto base = static_cast<uint32_t>(mesh.positions.size());
        for (const glm::vec3& p : polygon) {
            mesh.positions.push_back(p);
            const float s = p.x * axes[0] + p.y * axes[1] + p.z * axes[2] + axes[3];
            const float t = p.x * axes[4] + p.y * axes[5] + p.z * axes[6] + axes[7];
            mesh.uvs.emplace_back(s * inv_w, t * inv_h);
        }
        Face& face = mesh.faces[f];
        face.first_triangle = static_cast<uint32_t>(mesh.indices.size() / 3);
        face.triangle_count = uint32_t(numedges - 2);
        face.material = uint32_t(miptex);
        for (uint32_t k = 1; k + 1 < numedges; ++k) {
            const uint32_t b = reverse ? k + 1 : k, c = reverse ? k : k + 1;
            mesh.indices.insert(mesh.indices.end(), {base, base + b, base + c});
        }
    }
}

void read_textures(const Bsp& bsp, Zone& zone)
{
    const BspLumpSpan& lump = bsp.lumps[kTextures];
    if (lump.length == 0)
        return; // no textures: every texinfo reference will be out of range and reported there
    if (lump.length < 4) // the count check below subtracts 4 from the length
        bsp.in.fail(lump.offset, "texture lump is " + std::to_string(lump.length) +
                                     " bytes, too short for its miptex count");
    const auto count = bsp.in.read<int32_t>(lump.offset, "miptex count");
    if (count < 0 || uint64_t(count) > (lump.length - 4) / 4)
        bsp.in.fail(lump.offset, "miptex count " + std::to_string(count) + " does not fit the texture lump");
    zone.materials.resize(uint32_t(count));
    for (uint32_t i = 0; i < uint32_t(count); ++i) {
        const uint64_t dir_at = lump.offset + 4 + 4 * uint64_t(i);
        const auto ofs = bsp.in.read<int32_t>(dir_at, "miptex offset");
        Material& m = zone.materials[i];
        if (ofs == -1) {
            m.name = "(missing)";
            continue;
        }
        if (ofs < 0 || uint64_t(ofs) + 40 > lump.length)
            bsp.in.fail(dir_at, "miptex " + std::to_string(i) + " offset is outside the texture lump");
        const uint64_t at = lump.offset + uint64_t(ofs);
        const auto name_bytes = bsp.in.bytes(at, 16, "miptex name");
        const auto name_end = std::find(name_bytes.begin(), name_bytes.end(), uint8_t{0});
        m.name.assign(name_bytes.begin(), name_end);
        m.width = bsp.in.read<uint32_t>(at + 16, "miptex width");
        m.height = bsp.in.read<uint32_t>(at + 20, "miptex height");
        if (m.width > 16384 || m.height > 16384)
            bsp.in.fail(at + 16, "miptex '" + m.name + "' is " + std::to_string(m.width) + "x" +
                                     std::to_string(m.height) + " (at most 16384 on a side)");
        if (m.name.rfind("sky", 0) == 0)
            m.flags |= kMaterialSky;
        if (!m.name.empty() && m.name[0] == '*')
            m.flags |= kMaterialLiquid;
        const auto mip0 = bsp.in.read<uint32_t>(at + 24, "miptex mip offset");
        const uint64_t texels = uint64_t{m.width} * m.height;
        if (mip0 == 0 || texels == 0)
            continue; // header-only texture: no pixels in the file
        if (uint64_t(ofs) + mip0 + texels > lump.length)
            bsp.in.fail(at + 24, "miptex '" + m.name + "' pixels run past the end of the texture lump");
        const auto pixels = bsp.in.bytes(at + mip0, texels, "miptex pixels");
        const bool fence = m.name[0] == '{';
        std::vector<uint8_t> rgba(texels * 4);
        for (uint64_t p = 0; p < texels; ++p) {
            const uint8_t index = pixels[p];
            std::copy_n(kQuakePalette.begin() + 3 * index, 3, rgba.begin() + static_cast<std::ptrdiff_t>(4 * p));
            rgba[4 * p + 3] = (fence && index == 255) ? 0 : 255;
        }
        set_material_rgba(m, m.width, m.height, rgba); // 256 palette entries at most: kept palettized
    }
}

void read_marksurfaces(const Bsp& bsp, const Model& world, Zone& zone)
{
    const auto visleafs = static_cast<uint32_t>(zone.regions.size());
    uint64_t dropped = 0;
    for (uint32_t r = 0; r < visleafs; ++r) {
        const uint64_t at = bsp.record(kLeafs, r + 1);
        const uint32_t first = bsp.read_u(at + bsp.layout().leaf_first_marksurface, "leaf firstmarksurface");
        const uint32_t count = bsp.read_u(at + bsp.layout().leaf_marksurface_count, "leaf nummarksurfaces");
        if (uint64_t{first} + count > bsp.lumps[kMarksurfaces].count)
            bsp.in.fail(at + bsp.layout().leaf_first_marksurface,
                        "leaf " + std::to_string(r + 1) + " marksurface range is outside the lump");
        for (uint32_t k = 0; k < count; ++k) {
            const uint64_t ms_at = bsp.record(kMarksurfaces, first + k);
            const uint32_t face = bsp.read_u(ms_at, "marksurface");
            bsp.check_index(kFaces, face, ms_at, "marksurface face");
            const int64_t world_face = int64_t{face} - world.firstface;
            if (world_face < 0 || world_face >= world.numfaces) {
                ++dropped; // a brush-entity face listed by a world leaf: not part of the world mesh
                continue;
            }
            zone.region_faces.push_back(uint32_t(world_face));
        }
        zone.region_face_offsets[r + 1] = static_cast<uint32_t>(zone.region_faces.size());
    }
    if (dropped)
        zone.source.notes.push_back(std::to_string(dropped) + " marksurfaces name faces outside the world model");
}

void read_visibility(const Bsp& bsp, uint32_t visleafs, Zone& zone)
{
    const BspLumpSpan& lump = bsp.lumps[kVisibility];
    const std::span<const uint8_t> vis = bsp.in.bytes(lump.offset, lump.length, "visibility lump");
    std::vector<int32_t> visofs(visleafs);
    uint32_t rows = 0;
    for (uint32_t r = 0; r < visleafs; ++r) {
        const uint64_t at = bsp.record(kLeafs, r + 1) + 4;
        visofs[r] = bsp.in.read<int32_t>(at, "leaf visofs");
        if (visofs[r] == -1)
            continue;
        if (visofs[r] < 0 || uint64_t(visofs[r]) >= lump.length)
            bsp.in.fail(at, "leaf " + std::to_string(r + 1) + " visofs " + std::to_string(visofs[r]) +
                                " is outside the visibility lump (" + std::to_string(lump.length) + " bytes)");
        ++rows;
    }
    zone.source.counts.emplace_back("pvs.row_bytes", bits::bytes_for(visleafs));
    zone.source.counts.emplace_back("pvs.rows_in_file", rows);
    if (rows == 0) {
        zone.source.notes.push_back("no PVS: the map was not vised (every leaf has visofs -1)");
        return;
    }
    zone.baked_pvs = Pvs::build(visleafs, [&](uint32_t r, std::span<uint64_t> row) {
        if (visofs[r] == -1)
            return false;
        const QuakeRleResult result = decode_quake_rle(vis.subspan(size_t(visofs[r])), visleafs, row);
        if (!result.complete)
            bsp.in.fail(lump.offset + uint64_t(visofs[r]), "PVS row of leaf " + std::to_string(r + 1) +
                                                              " runs past the end of the visibility lump");
        return true;
    });
}

void read_entities(const Bsp& bsp, Zone& zone)
{
    const BspLumpSpan& lump = bsp.lumps[kEntities];
    const auto entities = parse_entities(bsp.in.bytes(lump.offset, lump.length, "entities lump"), bsp.in.file(),
                                         lump.offset);
    zone.source.counts.emplace_back("entities", entities.size());
    add_changelevel_zone_lines(
        entities,
        [&](int32_t index) -> std::optional<ModelBox> {
            if (uint32_t(index) >= bsp.lumps[kModels].count)
                return std::nullopt;
            const Model m = read_model(bsp, uint32_t(index));
            return ModelBox{m.mins, m.maxs};
        },
        zone);
}

} // namespace

bool looks_like_bsp29(std::span<const uint8_t> bytes) { return detect_bsp_variant(bytes).has_value(); }

Zone load_bsp29(std::span<const uint8_t> bytes, const std::string& file)
{
    ByteReader in(bytes, file);
    const BspLumps table = read_bsp_lumps(in);
    const Bsp bsp{std::move(in), table};
    if (bsp.lumps[kModels].count == 0)
        bsp.in.fail(bsp.lumps[kModels].offset, "the models lump is empty (no world model)");
    if (bsp.lumps[kLeafs].count == 0)
        bsp.in.fail(bsp.lumps[kLeafs].offset, "the leafs lump is empty (not even the solid leaf 0)");
    const Model world = read_model(bsp, 0);
    if (world.visleafs < 0 || uint32_t(world.visleafs) >= std::max<uint32_t>(bsp.lumps[kLeafs].count, 1))
        bsp.in.fail(bsp.record(kModels, 0) + 52, "world visleafs " + std::to_string(world.visleafs) +
                                                     " must be below the leaf count " +
                                                     std::to_string(bsp.lumps[kLeafs].count));
    const auto visleafs = uint32_t(world.visleafs);

    Zone zone;
    zone.source.path = file;
    zone.source.format = "Quake BSP";
    zone.source.version = bsp.layout().variant == BspVariant::Bsp29 ? "29" : bsp_variant_name(bsp.layout().variant);
    zone.source.counts.emplace_back("leaves", bsp.lumps[kLeafs].count);
    zone.source.counts.emplace_back("leaves.visleafs", visleafs);
    zone.source.counts.emplace_back("planes", bsp.lumps[kPlanes].count);
    zone.source.counts.emplace_back("models", bsp.lumps[kModels].count);

    read_tree(bsp, world, zone);
    read_regions(bsp, visleafs, zone);
    read_textures(bsp, zone);
    read_faces(bsp, world, zone);
    read_marksurfaces(bsp, world, zone);
    read_visibility(bsp, visleafs, zone);
    read_entities(bsp, zone);
    zone.shrink_to_fit(); // loaders grow their vectors; keep only what the zone needs
    return zone;
}

} // namespace pvs::quake
