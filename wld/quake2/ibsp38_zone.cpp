#include "wld/quake2/ibsp38_zone.h"

#include "visibility/bit_row.h"
#include "wld/common/byte_reader.h"
#include "wld/quake/changelevel_lines.h"
#include "wld/quake/entities.h"
#include "wld/quake2/ibsp38_file.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <set>
#include <tuple>

namespace pvs::quake2 {

namespace {

// Record sizes (Quake 2's qfiles.h).
constexpr uint32_t kPlaneBytes = 20, kVertexBytes = 12, kNodeBytes = 28, kTexinfoBytes = 76, kFaceBytes = 20,
                   kLeafFaceBytes = 2, kEdgeBytes = 4, kSurfedgeBytes = 4, kModelBytes = 48, kAreaBytes = 8,
                   kAreaPortalBytes = 8;
constexpr const char* kLumpNames[kIbsp38LumpCount] = {
    "entities", "planes", "vertexes", "visibility", "nodes", "texinfo", "faces", "lighting", "leafs", "leaffaces",
    "leafbrushes", "edges", "surfedges", "models", "brushes", "brushsides", "pop", "areas", "areaportals"};

// Contents and surface flags (Quake 2's q_shared.h).
constexpr int32_t kContentsSolid = 1, kContentsLava = 8, kContentsSlime = 16, kContentsWater = 32;
constexpr int32_t kContentsVisible = 0x7E; // window, aux, lava, slime, water, mist: what vis compares
constexpr int32_t kContentsDetail = 0x8000000, kContentsTranslucent = 0x10000000, kContentsAreaPortal = 0x8000;
constexpr int32_t kSurfSky = 0x4, kSurfWarp = 0x8, kSurfTrans33 = 0x10, kSurfTrans66 = 0x20, kSurfNodraw = 0x80;
constexpr uint32_t kMaxFaceEdges = 1024; // qbsp3's limit is 64; this only bounds bad files
constexpr float kNominalTextureSize = 64.0f;

struct Q2 {
    ByteReader in;
    Ibsp38File file;

    uint32_t count(Ibsp38Lump lump, uint32_t record_bytes) const
    {
        const Ibsp38LumpSpan& span = file.lumps[lump];
        if (span.length % record_bytes != 0)
            in.fail(8 + 8 * uint64_t(lump), std::string("the ") + kLumpNames[lump] + " lump is " +
                                                std::to_string(span.length) + " bytes, not a whole number of " +
                                                std::to_string(record_bytes) + "-byte records");
        return span.length / record_bytes;
    }
    uint64_t record(Ibsp38Lump lump, uint32_t record_bytes, uint32_t index) const
    {
        return file.lumps[lump].offset + uint64_t(index) * record_bytes;
    }
    void check_index(Ibsp38Lump lump, uint32_t record_bytes, int64_t index, uint64_t at, const char* what) const
    {
        const uint32_t n = count(lump, record_bytes);
        if (index < 0 || index >= int64_t{n})
            in.fail(at, std::string(what) + " " + std::to_string(index) + " is outside the " + kLumpNames[lump] +
                            " lump (" + std::to_string(n) + " records)");
    }
    glm::vec3 vec3(uint64_t at, const char* what) const
    {
        glm::vec3 v;
        for (int k = 0; k < 3; ++k) {
            v[k] = in.read<float>(at + 4 * uint64_t(k), what);
            if (!std::isfinite(v[k]))
                in.fail(at + 4 * uint64_t(k), std::string(what) + " is not a finite number");
        }
        return v;
    }
};

struct Model {
    glm::vec3 mins, maxs;
    int32_t headnode, firstface, numfaces;
};

Model read_model(const Q2& q, uint32_t index)
{
    const uint64_t at = q.record(kQ2LumpModels, kModelBytes, index);
    return {q.vec3(at, "model mins"), q.vec3(at + 12, "model maxs"), q.in.read<int32_t>(at + 36, "model headnode"),
            q.in.read<int32_t>(at + 40, "model firstface"), q.in.read<int32_t>(at + 44, "model numfaces")};
}

// A node child: >= 0 a node, < 0 the leaf -(child + 1) (the zone's encoding: ~leaf, the same bits).
int32_t read_child(const Q2& q, uint64_t at, uint32_t nodes, uint32_t leaves)
{
    const int32_t raw = q.in.read<int32_t>(at, "node child");
    if (raw >= 0 ? uint32_t(raw) >= nodes : uint32_t(~raw) >= leaves)
        q.in.fail(at, "node child " + std::to_string(raw) + " names a " + (raw >= 0 ? "node" : "leaf") +
                          " outside its lump (" + std::to_string(raw >= 0 ? nodes : leaves) + ")");
    return raw;
}

void read_tree(const Q2& q, const Model& world, Zone& zone)
{
    BspTree& tree = zone.tree;
    tree.tie_rule = TieRule::OnPlaneGoesFront;
    const uint32_t nodes = q.count(kQ2LumpNodes, kNodeBytes), leaves = uint32_t(q.file.leaves.size());
    q.count(kQ2LumpPlanes, kPlaneBytes);
    tree.nodes.resize(nodes);
    for (uint32_t i = 0; i < nodes; ++i) {
        const uint64_t at = q.record(kQ2LumpNodes, kNodeBytes, i);
        const int32_t planenum = q.in.read<int32_t>(at, "node planenum");
        q.check_index(kQ2LumpPlanes, kPlaneBytes, planenum, at, "node plane");
        const uint64_t plane_at = q.record(kQ2LumpPlanes, kPlaneBytes, uint32_t(planenum));
        BspNode& node = tree.nodes[i];
        node.normal = q.vec3(plane_at, "plane normal");
        node.dist = q.in.read<float>(plane_at + 12, "plane dist");
        if (!std::isfinite(node.dist))
            q.in.fail(plane_at + 12, "plane dist is not a finite number");
        node.children[0] = read_child(q, at + 4, nodes, leaves);
        node.children[1] = read_child(q, at + 8, nodes, leaves);
    }
    if (nodes == 0) {
        tree.root = ~0; // no node: the whole world is leaf 0
    } else {
        if (world.headnode < 0 || uint32_t(world.headnode) >= nodes)
            q.in.fail(q.record(kQ2LumpModels, kModelBytes, 0) + 36,
                      "world head node " + std::to_string(world.headnode) + " is outside the nodes lump");
        tree.root = world.headnode;
    }
    // The walk must end: every node reachable from the root is reached exactly once.
    if (const int32_t twice = node_reached_twice(tree); twice >= 0)
        q.in.fail(q.record(kQ2LumpNodes, kNodeBytes, uint32_t(twice)),
                  "node " + std::to_string(twice) + " is reached twice from the root (the tree has a cycle)");
}

// The leaves the world's tree reaches, in leaf order.
std::vector<uint8_t> world_leaves(const BspTree& tree, size_t leaves)
{
    std::vector<uint8_t> reached(leaves, 0);
    std::vector<int32_t> stack{tree.root};
    while (!stack.empty()) {
        const int32_t child = stack.back();
        stack.pop_back();
        if (BspTree::is_leaf(child)) {
            reached[size_t(BspTree::leaf_index(child))] = 1;
            continue;
        }
        stack.push_back(tree.nodes[size_t(child)].children[0]);
        stack.push_back(tree.nodes[size_t(child)].children[1]);
    }
    return reached;
}

// A leaf's bounds: two corners of three shorts after its contents, cluster and area.
Aabb leaf_box(const Q2& q, uint32_t leaf)
{
    const uint64_t at = q.record(kQ2LumpLeafs, kQ2LeafBytes, leaf);
    Aabb box;
    for (uint64_t corner : {at + 8, at + 14}) {
        glm::vec3 p;
        for (int k = 0; k < 3; ++k)
            p[k] = float(q.in.read<int16_t>(corner + 2 * uint64_t(k), "leaf bounds"));
        box.grow(p);
    }
    return box;
}

uint32_t contents_flags(int32_t contents)
{
    return (contents & kContentsWater ? kRegionWater : 0u) | (contents & kContentsSlime ? kRegionSlime : 0u) |
           (contents & kContentsLava ? kRegionLava : 0u);
}

// Regions (leaves with a cluster that the world reaches) and their clusters.
std::vector<int32_t> read_regions(const Q2& q, Zone& zone)
{
    const std::vector<Q2Leaf>& leaves = q.file.leaves;
    const std::vector<uint8_t> reached = world_leaves(zone.tree, leaves.size());
    zone.tree.leaf_region.assign(leaves.size(), kLeafSolid);
    // Vis compares clusters, not leaves: a cluster's contents are those of all its leaves ORed
    // (qbsp's ClusterContents), so one translucent leaf makes its whole cluster clear. Clusters
    // as the leaves number them (an unvised map has no count in its visibility lump).
    int32_t highest_cluster = -1;
    for (const Q2Leaf& leaf : leaves)
        highest_cluster = std::max<int32_t>(highest_cluster, leaf.cluster);
    std::vector<int32_t> cluster_contents(size_t(highest_cluster + 1), 0);
    for (const Q2Leaf& leaf : leaves)
        if (leaf.cluster >= 0)
            cluster_contents[size_t(leaf.cluster)] |= leaf.contents;
    std::vector<int32_t> cluster_of_region;
    uint64_t solid = 0, without_cluster = 0; // leaves that are not regions
    for (uint32_t i = 0; i < leaves.size(); ++i) {
        const Q2Leaf& leaf = leaves[i];
        const bool is_solid = (leaf.contents & kContentsSolid) != 0;
        if (leaf.cluster < 0 || is_solid || !reached[i]) { // detail solid leaves keep a cluster
            zone.tree.leaf_region[i] = is_solid ? kLeafSolid : kLeafOutside;
            solid += is_solid;
            without_cluster += !is_solid && leaf.cluster < 0;
            continue;
        }
        zone.tree.leaf_region[i] = int32_t(zone.regions.size());
        Region region;
        region.flags = contents_flags(leaf.contents);
        const int32_t contents = cluster_contents[size_t(leaf.cluster)];
        const int32_t visible = contents & kContentsVisible;
        const int32_t clear = contents & (kContentsTranslucent | kContentsDetail) ? 0 : visible;
        region.vis_contents = uint16_t(visible | clear << 8);
        region.bounds = leaf_box(q, i);
        zone.regions.push_back(region);
        cluster_of_region.push_back(leaf.cluster);
        zone.region_areas.push_back(leaf.area);
        zone.region_names.push_back("leaf " + std::to_string(i) + ", cluster " + std::to_string(leaf.cluster) +
                                    ", area " + std::to_string(leaf.area));
    }
    zone.source.counts.emplace_back("leaves", leaves.size());
    zone.source.counts.emplace_back("leaves.solid", solid);
    zone.source.counts.emplace_back("leaves.without_cluster", without_cluster);
    return cluster_of_region;
}

// One material per (texture name, surface kind); the texinfo -> material map.
std::vector<uint32_t> read_materials(const Q2& q, Zone& zone)
{
    const uint32_t count = q.count(kQ2LumpTexinfo, kTexinfoBytes);
    std::vector<uint32_t> material_of(count);
    std::map<std::pair<std::string, uint32_t>, uint32_t> known;
    for (uint32_t i = 0; i < count; ++i) {
        const uint64_t at = q.record(kQ2LumpTexinfo, kTexinfoBytes, i);
        const int32_t surface = q.in.read<int32_t>(at + 32, "texinfo flags");
        const std::span<const uint8_t> raw = q.in.bytes(at + 40, 32, "texinfo texture name");
        const std::string name(reinterpret_cast<const char*>(raw.data()),
                               size_t(std::find(raw.begin(), raw.end(), uint8_t(0)) - raw.begin()));
        const uint32_t flags = (surface & kSurfSky ? kMaterialSky : 0u) | (surface & kSurfWarp ? kMaterialLiquid : 0u) |
                               (surface & kSurfNodraw ? kMaterialInvisible : 0u) |
                               (surface & (kSurfTrans33 | kSurfTrans66) ? kMaterialTranslucent : 0u) |
                               (surface & kSurfTrans33 ? kMaterialFaint : 0u); // Quake 2 draws it at 0.33
        const auto [it, fresh] = known.try_emplace({name, flags}, uint32_t(zone.materials.size()));
        if (fresh) {
            Material m;
            m.name = name;
            m.flags = flags;
            // No pixels ship in the map: a flat colour from the name, so walls of one texture match.
            uint32_t hash = 2166136261u;
            for (char c : name)
                hash = (hash ^ uint8_t(c)) * 16777619u;
            const uint8_t rgba[4] = {uint8_t(96 + (hash & 0x7F)), uint8_t(96 + ((hash >> 8) & 0x7F)),
                                     uint8_t(96 + ((hash >> 16) & 0x7F)), 255};
            std::vector<uint8_t> pixels(size_t(kNominalTextureSize) * size_t(kNominalTextureSize) * 4);
            for (size_t p = 0; p < pixels.size(); p += 4)
                std::memcpy(pixels.data() + p, rgba, 4);
            set_material_rgba(m, uint32_t(kNominalTextureSize), uint32_t(kNominalTextureSize), pixels);
            zone.materials.push_back(std::move(m));
        }
        material_of[i] = it->second;
    }
    zone.source.counts.emplace_back("texinfo", count);
    return material_of;
}

void read_faces(const Q2& q, const Model& world, const std::vector<uint32_t>& material_of, Zone& zone)
{
    const uint32_t faces = q.count(kQ2LumpFaces, kFaceBytes), surfedges = q.count(kQ2LumpSurfEdges, kSurfedgeBytes);
    q.count(kQ2LumpEdges, kEdgeBytes);
    q.count(kQ2LumpVertexes, kVertexBytes);
    if (world.firstface < 0 || world.numfaces < 0 || int64_t{world.firstface} + world.numfaces > int64_t{faces})
        q.in.fail(q.record(kQ2LumpModels, kModelBytes, 0) + 40, "the world model's face range is outside the faces lump");
    Mesh& mesh = zone.mesh;
    mesh.faces.resize(uint32_t(world.numfaces));
    std::vector<glm::vec3> polygon;
    for (uint32_t f = 0; f < uint32_t(world.numfaces); ++f) {
        const uint64_t at = q.record(kQ2LumpFaces, kFaceBytes, uint32_t(world.firstface) + f);
        const uint16_t planenum = q.in.read<uint16_t>(at, "face planenum");
        const int16_t side = q.in.read<int16_t>(at + 2, "face side");
        const int32_t firstedge = q.in.read<int32_t>(at + 4, "face firstedge");
        const int16_t numedges = q.in.read<int16_t>(at + 8, "face numedges");
        const int16_t texinfo = q.in.read<int16_t>(at + 10, "face texinfo");
        q.check_index(kQ2LumpPlanes, kPlaneBytes, planenum, at, "face plane");
        q.check_index(kQ2LumpTexinfo, kTexinfoBytes, texinfo, at + 10, "face texinfo");
        if (numedges < 3 || uint32_t(numedges) > kMaxFaceEdges)
            q.in.fail(at + 8, "face has " + std::to_string(numedges) + " edges (3.." + std::to_string(kMaxFaceEdges) +
                                  " expected)");
        if (firstedge < 0 || int64_t{firstedge} + numedges > int64_t{surfedges})
            q.in.fail(at + 4, "face edge range is outside the surfedges lump");
        polygon.clear();
        for (uint32_t k = 0; k < uint32_t(numedges); ++k) {
            const uint64_t se_at = q.record(kQ2LumpSurfEdges, kSurfedgeBytes, uint32_t(firstedge) + k);
            const int32_t e = q.in.read<int32_t>(se_at, "surfedge");
            if (e == std::numeric_limits<int32_t>::min())
                q.in.fail(se_at, "surfedge value is out of range");
            const int32_t edge = e >= 0 ? e : -e;
            q.check_index(kQ2LumpEdges, kEdgeBytes, edge, se_at, "surfedge edge");
            const uint64_t edge_at = q.record(kQ2LumpEdges, kEdgeBytes, uint32_t(edge));
            const uint16_t v = q.in.read<uint16_t>(edge_at + (e >= 0 ? 0 : 2), "edge vertex");
            q.check_index(kQ2LumpVertexes, kVertexBytes, v, edge_at, "edge vertex");
            polygon.push_back(q.vec3(q.record(kQ2LumpVertexes, kVertexBytes, v), "vertex"));
        }
        const uint64_t ti = q.record(kQ2LumpTexinfo, kTexinfoBytes, uint32_t(texinfo));
        float axes[8];
        for (int k = 0; k < 8; ++k) {
            axes[k] = q.in.read<float>(ti + 4 * uint64_t(k), "texinfo vector");
            if (!std::isfinite(axes[k]))
                q.in.fail(ti + 4 * uint64_t(k), "texinfo vector is not a finite number");
        }
        // Winding: counter-clockwise seen from the face's front (the plane's normal, negated for side 1).
        glm::vec3 normal = q.vec3(q.record(kQ2LumpPlanes, kPlaneBytes, planenum), "plane normal");
        if (side != 0)
            normal = -normal;
        glm::vec3 newell{0.0f};
        for (size_t k = 0; k < polygon.size(); ++k)
            newell += glm::cross(polygon[k], polygon[(k + 1) % polygon.size()]);
        const bool reverse = glm::dot(newell, normal) < 0.0f;
        const auto base = uint32_t(mesh.positions.size());
        for (const glm::vec3& p : polygon) {
            mesh.positions.push_back(p);
            const float s = p.x * axes[0] + p.y * axes[1] + p.z * axes[2] + axes[3];
            const float t = p.x * axes[4] + p.y * axes[5] + p.z * axes[6] + axes[7];
            mesh.uvs.emplace_back(s / kNominalTextureSize, t / kNominalTextureSize);
        }
        Face& face = mesh.faces[f];
        face.first_triangle = uint32_t(mesh.indices.size() / 3);
        face.triangle_count = uint32_t(numedges - 2);
        face.material = material_of[size_t(texinfo)];
        for (uint32_t k = 1; k + 1 < uint32_t(numedges); ++k) {
            const uint32_t b = reverse ? k + 1 : k, c = reverse ? k : k + 1;
            mesh.indices.insert(mesh.indices.end(), {base, base + b, base + c});
        }
    }
    zone.source.counts.emplace_back("faces.world", uint32_t(world.numfaces));
}

void read_leaf_faces(const Q2& q, const Model& world, Zone& zone)
{
    const uint32_t leaf_faces = q.count(kQ2LumpLeafFaces, kLeafFaceBytes);
    zone.region_face_offsets.assign(zone.regions.size() + 1, 0);
    uint64_t dropped = 0;
    for (uint32_t i = 0; i < q.file.leaves.size(); ++i) {
        const int32_t region = zone.tree.leaf_region[i];
        if (region < 0)
            continue;
        const uint64_t at = q.record(kQ2LumpLeafs, kQ2LeafBytes, i);
        const uint16_t first = q.in.read<uint16_t>(at + 20, "leaf firstleafface");
        const uint16_t count = q.in.read<uint16_t>(at + 22, "leaf numleaffaces");
        if (uint32_t(first) + count > leaf_faces)
            q.in.fail(at + 20, "leaf " + std::to_string(i) + " leaf-face range is outside the leaffaces lump");
        for (uint32_t k = 0; k < count; ++k) {
            const uint64_t lf_at = q.record(kQ2LumpLeafFaces, kLeafFaceBytes, first + k);
            const uint16_t face = q.in.read<uint16_t>(lf_at, "leaf face");
            q.check_index(kQ2LumpFaces, kFaceBytes, face, lf_at, "leaf face");
            const int64_t world_face = int64_t{face} - world.firstface;
            if (world_face < 0 || world_face >= world.numfaces) {
                ++dropped; // a brush model's face listed by a world leaf: not in the world mesh
                continue;
            }
            zone.region_faces.push_back(uint32_t(world_face));
        }
        zone.region_face_offsets[size_t(region) + 1] = uint32_t(zone.region_faces.size());
    }
    if (dropped)
        zone.source.notes.push_back(std::to_string(dropped) + " leaf faces name faces outside the world model");
}

// The file's rows over clusters, expanded to the regions (leaves) of each cluster.
void read_visibility(const Q2& q, const std::vector<int32_t>& cluster_of_region, Zone& zone)
{
    const Ibsp38File& f = q.file;
    zone.source.counts.emplace_back("clusters", f.clusters);
    if (f.clusters == 0) {
        zone.source.notes.push_back("no PVS: the map was not vised (empty visibility lump)");
        return;
    }
    std::vector<std::vector<uint32_t>> regions_of_cluster(f.clusters);
    for (uint32_t r = 0; r < cluster_of_region.size(); ++r)
        regions_of_cluster[size_t(cluster_of_region[r])].push_back(r); // read_ibsp38 checked the range
    const size_t words = bits::words_for(f.clusters);
    zone.baked_pvs = Pvs::build(uint32_t(zone.regions.size()), [&](uint32_t r, std::span<uint64_t> row) {
        const std::span<const uint64_t> clusters(f.pvs_rows.data() + size_t(cluster_of_region[r]) * words, words);
        bits::for_each_set(clusters, [&](size_t c) {
            for (uint32_t s : regions_of_cluster[c])
                bits::set(row, s);
        });
        return true;
    });
}

// Areas and areaportals: per area its list of (portal number, other area); the portal's brush is
// the leaves of CONTENTS_AREAPORTAL that qbsp left of it, each given to the portal whose two
// areas are those of the open leaves around it. The counts a user sees are the map's: the areas
// its leaves are in (qbsp keeps area 0 as an unused entry) and its func_areaportals (the links
// lump holds each twice, once per side, after an unused entry 0).
void read_areas(const Q2& q, Zone& zone)
{
    const uint32_t areas = q.count(kQ2LumpAreas, kAreaBytes), links = q.count(kQ2LumpAreaPortals, kAreaPortalBytes);
    std::map<uint32_t, size_t> portal_of_number;
    for (uint32_t a = 0; a < areas; ++a) {
        const uint64_t at = q.record(kQ2LumpAreas, kAreaBytes, a);
        const int32_t count = q.in.read<int32_t>(at, "area numareaportals");
        const int32_t first = q.in.read<int32_t>(at + 4, "area firstareaportal");
        if (count < 0 || first < 0 || int64_t{first} + count > int64_t{links})
            q.in.fail(at, "area " + std::to_string(a) + "'s areaportal range is outside the areaportals lump");
        for (int32_t k = 0; k < count; ++k) {
            const uint64_t link_at = q.record(kQ2LumpAreaPortals, kAreaPortalBytes, uint32_t(first + k));
            const int32_t number = q.in.read<int32_t>(link_at, "areaportal portalnum");
            const int32_t other = q.in.read<int32_t>(link_at + 4, "areaportal otherarea");
            if (number < 0 || other < 0 || uint32_t(other) >= areas)
                q.in.fail(link_at, "areaportal " + std::to_string(number) + " links to area " + std::to_string(other) +
                                       " of " + std::to_string(areas));
            const auto [it, fresh] = portal_of_number.try_emplace(uint32_t(number), zone.area_portals.size());
            if (fresh) {
                AreaPortal portal;
                portal.number = uint32_t(number);
                portal.areas[0] = int32_t(std::min<uint32_t>(a, uint32_t(other)));
                portal.areas[1] = int32_t(std::max<uint32_t>(a, uint32_t(other)));
                zone.area_portals.push_back(portal);
            }
        }
    }
    std::set<int32_t> leaf_areas;
    for (const auto& leaf : q.file.leaves)
        if (leaf.area > 0)
            leaf_areas.insert(leaf.area);
    zone.source.counts.emplace_back("areas", leaf_areas.size());
    zone.source.counts.emplace_back("areaportals", zone.area_portals.size());
    std::vector<int32_t> touching;
    for (size_t i = 0; i < q.file.leaves.size(); ++i) {
        if (!(q.file.leaves[i].contents & kContentsAreaPortal))
            continue;
        const Aabb box = leaf_box(q, uint32_t(i));
        touching.clear();
        quake::leaves_touching_box(zone.tree, Aabb{box.min - 1.0f, box.max + 1.0f}, touching);
        std::set<int32_t> around;
        for (int32_t leaf : touching)
            if (size_t(leaf) < q.file.leaves.size() && !(q.file.leaves[size_t(leaf)].contents & (kContentsSolid | kContentsAreaPortal)))
                around.insert(q.file.leaves[size_t(leaf)].area);
        for (AreaPortal& portal : zone.area_portals)
            if (around.count(portal.areas[0]) && around.count(portal.areas[1]))
                portal.bounds.grow(box);
    }
}

void read_entities(const Q2& q, Zone& zone)
{
    const Ibsp38LumpSpan& lump = q.file.lumps[kQ2LumpEntities];
    const auto entities =
        quake::parse_entities(q.in.bytes(lump.offset, lump.length, "entities lump"), q.in.file(), lump.offset);
    zone.source.counts.emplace_back("entities", entities.size());
    const uint32_t models = q.count(kQ2LumpModels, kModelBytes);
    quake::add_changelevel_zone_lines(
        entities,
        [&](int32_t index) -> std::optional<quake::ModelBox> {
            if (uint32_t(index) >= models)
                return std::nullopt;
            const Model m = read_model(q, uint32_t(index));
            return quake::ModelBox{m.mins, m.maxs};
        },
        zone);
}

} // namespace

Zone load_ibsp38(std::span<const uint8_t> bytes, const std::string& file)
{
    Q2 q{ByteReader(bytes, file), read_ibsp38(bytes, file)};
    if (q.count(kQ2LumpModels, kModelBytes) == 0)
        q.in.fail(q.file.lumps[kQ2LumpModels].offset, "the models lump is empty (no world model)");
    if (q.file.leaves.empty())
        q.in.fail(q.file.lumps[kQ2LumpLeafs].offset, "the leafs lump is empty");
    const Model world = read_model(q, 0);

    Zone zone;
    zone.source.path = file;
    zone.source.format = "Quake 2 BSP";
    zone.source.version = "IBSP 38";
    zone.source.counts.emplace_back("planes", q.count(kQ2LumpPlanes, kPlaneBytes));
    zone.source.counts.emplace_back("models", q.count(kQ2LumpModels, kModelBytes));
    read_tree(q, world, zone);
    const std::vector<int32_t> cluster_of_region = read_regions(q, zone);
    const std::vector<uint32_t> material_of = read_materials(q, zone);
    read_faces(q, world, material_of, zone);
    read_leaf_faces(q, world, zone);
    read_visibility(q, cluster_of_region, zone);
    read_areas(q, zone);
    read_entities(q, zone);
    zone.source.notes.push_back("regions are leaves; the file's PVS rows are over its clusters, each leaf takes its "
                                "cluster's row");
    zone.shrink_to_fit();
    return zone;
}

} // namespace pvs::quake2
