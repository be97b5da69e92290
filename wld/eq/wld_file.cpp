#include "wld/eq/wld_file.h"

#include "visibility/zone.h"
#include "wld/common/byte_reader.h"
#include "wld/eq/wld_body.h"
#include "wld/eq/wld_string_hash.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace pvs::eq {

namespace {

// ---- 0x22 parts ----

WldRenderInfo read_render_info(WldBodyReader& r, int64_t wall)
{
    WldRenderInfo info;
    info.flags = r.read<uint32_t>("wall render info flags", wall);
    if (info.flags & kWldRenderPen)
        info.pen = r.read<uint32_t>("wall pen", wall);
    if (info.flags & kWldRenderBrightness)
        info.brightness = r.read<float>("wall brightness", wall);
    if (info.flags & kWldRenderScaledAmbient)
        info.scaled_ambient = r.read<float>("wall scaled ambient", wall);
    if (info.flags & kWldRenderSprite)
        info.sprite_ref = r.fragment_ref("wall sprite reference", kWldAnyFragmentType, wall);
    if (info.flags & kWldRenderUvInfo) {
        info.uv_origin = r.vec3("wall uv origin", wall);
        info.u_axis = r.vec3("wall u axis", wall);
        info.v_axis = r.vec3("wall v axis", wall);
    }
    if (info.flags & kWldRenderUvMap) {
        const uint32_t count = r.count("wall uv map count", 8, wall);
        info.uv_map.reserve(count);
        for (uint32_t i = 0; i < count; ++i)
            info.uv_map.push_back(r.vec2("wall uv map", wall));
    }
    return info;
}

// Wall layout (LQ, LX): flags, vertex list, then the render data when flags bit 1 is set.
// Vertex indices are not checked against the region's own vertices: LQ's tanarus fixture has
// indices in the thousands, so they index something larger.
WldWall read_wall(WldBodyReader& r, int64_t index)
{
    WldWall wall;
    wall.flags = r.read<uint32_t>("wall flags", index);
    const uint32_t n = r.count("wall vertex count", 4, index);
    wall.vertices = r.u32s(n, "wall vertex list", index);
    if (wall.flags & kWldWallRenderData) {
        wall.render_method = r.read<uint32_t>("wall render method", index);
        wall.render_info = read_render_info(r, index);
        wall.normal = r.vec4("wall normal", index);
    }
    return wall;
}

bool known_obstacle_type(int32_t type)
{
    return (type >= 8 && type <= 14) || type == kWldObstacleEdgePolygonNormal || type == kWldObstacleEdgeWall;
}

WldObstacle read_obstacle(WldBodyReader& r, int64_t index, size_t wall_count)
{
    WldObstacle ob;
    ob.flags = r.read<uint32_t>("obstacle flags", index);
    ob.next_region = r.read<int32_t>("obstacle next region", index);
    const uint64_t type_at = r.at();
    ob.type = r.read<int32_t>("obstacle type", index);
    if (!known_obstacle_type(ob.type))
        r.fail(type_at, "obstacle " + std::to_string(index) + " has unknown type " + std::to_string(ob.type) +
                            " (the size of its data is not known)");
    if (ob.type == kWldObstacleEdgePolygon || ob.type == kWldObstacleEdgePolygonNormal) {
        const uint32_t n = r.count("obstacle vertex count", 4, index);
        ob.vertices = r.u32s(n, "obstacle vertex list", index);
    }
    if (ob.type == kWldObstacleEdgePolygonNormal)
        ob.normal = r.vec4("obstacle normal", index);
    if (ob.type == kWldObstacleEdgeWall) {
        const uint64_t wall_at = r.at();
        ob.edge_wall = r.read<uint32_t>("obstacle edge wall", index);
        if (ob.edge_wall >= wall_count)
            r.fail(wall_at, "obstacle " + std::to_string(index) + " names wall " + std::to_string(ob.edge_wall) +
                                " but the region has " + std::to_string(wall_count) + " walls");
    }
    if (ob.flags & kWldObstacleUserData) {
        const uint32_t size = r.count("obstacle user data size", 1, index);
        const auto data = r.bytes(size, "obstacle user data", index);
        ob.user_data.assign(data.begin(), data.end());
    }
    return ob;
}

WldVisNode read_vis_node(WldBodyReader& r, int64_t index, uint32_t node_count, uint32_t list_count)
{
    WldVisNode node;
    node.normal = r.vec4("vis node normal", index);
    const uint64_t fields_at = r.at();
    node.vis_list_index = r.read<uint32_t>("vis node list index", index);
    node.front = r.read<uint32_t>("vis node front", index);
    node.back = r.read<uint32_t>("vis node back", index);
    if (node.vis_list_index > list_count)
        r.fail(fields_at, "vis node " + std::to_string(index) + " names vis list " +
                              std::to_string(node.vis_list_index) + " but the region has " +
                              std::to_string(list_count));
    if (node.front > node_count || node.back > node_count)
        r.fail(fields_at + 4, "vis node " + std::to_string(index) + " child " +
                                  std::to_string(std::max(node.front, node.back)) +
                                  " is out of range (the region has " + std::to_string(node_count) + " vis nodes)");
    return node;
}

WldVisList read_vis_list(WldBodyReader& r, int64_t index, bool byte_form)
{
    WldVisList list;
    list.byte_form = byte_form;
    // u16 as LQ and QL read it; LX, WQ and ES read an i16, which agrees below 32768.
    const auto range_count = r.read<uint16_t>("vis list range count", index);
    const auto data = r.bytes(byte_form ? range_count : 2u * range_count, "vis list", index);
    list.data.assign(data.begin(), data.end());
    return list;
}

// The mesh reference must name a mesh: 0x36, or the legacy 0x2C LX reads for flag bit 6.
void check_mesh_target(const WldBodyReader& r, int32_t mesh_ref, uint64_t ref_at)
{
    if (mesh_ref <= 0)
        return;
    const uint32_t type = r.wld().fragments[uint32_t(mesh_ref) - 1].type;
    if (type != kWldMesh && type != kWldLegacyMesh)
        r.fail(ref_at, "mesh_ref " + std::to_string(mesh_ref) + " names " +
                           wld_fragment_label(uint32_t(mesh_ref), type) + ", not a mesh (0x36)");
}

// ---- 0x29 type strings (§5.2) ----

std::string lowercase(std::string_view text)
{
    std::string out(text);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z')
            c = static_cast<char>(c - 'A' + 'a');
    return out;
}

std::optional<int32_t> digits(std::string_view s, size_t pos, size_t n)
{
    if (pos + n > s.size())
        return std::nullopt;
    int32_t value = 0;
    for (size_t i = pos; i < pos + n; ++i) {
        if (s[i] < '0' || s[i] > '9')
            return std::nullopt;
        value = value * 10 + (s[i] - '0');
    }
    return value;
}

// A 6-character coordinate: six digits, or '-' and five digits (LX).
std::optional<int32_t> coordinate(std::string_view s, size_t pos)
{
    if (pos < s.size() && s[pos] == '-') {
        const auto value = digits(s, pos + 1, 5);
        return value ? std::optional<int32_t>(-*value) : std::nullopt;
    }
    return digits(s, pos, 6);
}

// Positions after lowercasing (§5.2): [0,5) prefix, [5,10) zone id; zone id 255: [10,16) zone
// point; otherwise [10,16) x, [16,22) y, [22,28) z, [28,31) heading. "drntp_zone" = point 0.
std::optional<WldZoneLineTarget> parse_zone_line(std::string_view lower)
{
    WldZoneLineTarget target;
    if (lower.substr(5) == "_zone")
        return target;
    const auto zone = digits(lower, 5, 5);
    if (!zone)
        return std::nullopt;
    target.zone_id = uint32_t(*zone);
    if (target.zone_id == 255) {
        const auto point = digits(lower, 10, 6);
        if (!point)
            return std::nullopt;
        target.zone_point = uint32_t(*point);
        return target;
    }
    const auto x = coordinate(lower, 10), y = coordinate(lower, 16), z = coordinate(lower, 22);
    const auto heading = digits(lower, 28, 3);
    if (!x || !y || !z || !heading)
        return std::nullopt;
    target.x = *x, target.y = *y, target.z = *z, target.heading = *heading;
    return target;
}

struct TypePrefix {
    std::string_view prefix;
    uint32_t flags;
    bool zone_line; // the string goes on with a zone-line destination
};

// First hit wins. The union of ZU's prefixes (WT, LA, DRNTP, DRP_, SL, DRN, VWA; case-insensitive
// here) and LX/ES's (wtntp and lantp are water/lava zone lines, vwn_ is vwater).
constexpr TypePrefix kTypePrefixes[] = {
    {"wtntp", kRegionWater | kRegionZoneLine, true},
    {"lantp", kRegionLava | kRegionZoneLine, true},
    {"drntp", kRegionZoneLine, true},
    {"drp_", kRegionPvp, false},
    {"drn", kRegionIce, false},
    {"wt", kRegionWater, false},
    {"la", kRegionLava, false},
    {"sl", kRegionSlime, false},
    {"vwa", kRegionVWater, false},
    {"vwn", kRegionVWater, false},
};

} // namespace

const char* wld_fragment_type_name(uint32_t type)
{
    switch (type) {
    case kWldBitmapName: return "bitmap name";
    case kWldSpriteDef: return "sprite definition";
    case kWldSprite: return "sprite";
    case kWldBspTree: return "bsp tree";
    case kWldRegion: return "region";
    case kWldRegionFlag: return "region flag";
    case kWldLegacyMesh: return "legacy mesh";
    case kWldMaterial: return "material";
    case kWldMaterialPalette: return "material palette";
    case kWldAmbientLight: return "ambient light";
    case kWldMesh: return "mesh";
    default: return "";
    }
}

// ---- Container ----

const WldFragment& WldFile::fragment(uint32_t number) const
{
    if (number == 0 || number > fragments.size())
        throw std::out_of_range("WLD fragment " + std::to_string(number) + " does not exist (the file has " +
                                std::to_string(fragments.size()) + ")");
    return fragments[number - 1];
}

namespace {

WldHeader read_header(const ByteReader& in)
{
    if (in.size() >= 4 && in.read<uint32_t>(0, "magic") != kWldMagic) {
        char seen[16];
        std::snprintf(seen, sizeof seen, "0x%08X", in.read<uint32_t>(0, "magic"));
        in.fail(0, std::string("not a WLD file: magic is ") + seen + " (expected 0x54503D02)");
    }
    in.require(0, kWldHeaderSize, "WLD header");
    WldHeader h;
    h.version = in.read<uint32_t>(4, "version");
    if (h.version != kWldVersionOld && h.version != kWldVersionNew)
        in.fail(4, "unknown WLD version " + wld_hex(h.version) + " (known: 0x00015500 old, 0x1000C800 new)");
    h.fragment_count = in.read<uint32_t>(8, "fragment_count");
    h.region_count = in.read<uint32_t>(12, "region_count");
    h.max_object_bytes = in.read<uint32_t>(16, "max_object_bytes");
    h.string_hash_size = in.read<uint32_t>(20, "string_hash_size");
    h.string_count = in.read<uint32_t>(24, "string_count");
    return h;
}

void read_fragment_table(const ByteReader& in, WldFile& wld, uint64_t at)
{
    const uint64_t size = in.size();
    constexpr uint64_t kMinFragment = kWldFragmentHeaderSize + 4; // header + name_ref
    if (wld.header.fragment_count > (size - at) / kMinFragment)
        in.fail(8, "fragment_count " + std::to_string(wld.header.fragment_count) + " cannot fit in the " +
                       std::to_string(size - at) + " bytes after the string hash (at least 12 per fragment)");
    wld.fragments.reserve(wld.header.fragment_count);
    for (uint32_t n = 1; n <= wld.header.fragment_count; ++n) {
        if (size - at < kMinFragment)
            in.fail(at, "fragment " + std::to_string(n) + " of " + std::to_string(wld.header.fragment_count) +
                            " runs past the end of the file");
        WldFragment f;
        const auto body_size = in.read<uint32_t>(at, "fragment size");
        f.type = in.read<uint32_t>(at + 4, "fragment type");
        const auto label = [&] { return wld_fragment_label(n, f.type); }; // built only for an error
        if (body_size < 4)
            in.fail(at, label() + ": size " + std::to_string(body_size) + " is smaller than its 4-byte name_ref");
        if (body_size > size - at - kWldFragmentHeaderSize)
            in.fail(at, label() + ": size " + std::to_string(body_size) + " runs past the end of the file (" +
                            std::to_string(size - at - kWldFragmentHeaderSize) + " bytes left)");
        f.body_offset = at + kWldFragmentHeaderSize;
        f.body_size = body_size;
        f.name_ref = in.read<int32_t>(f.body_offset, "name_ref");
        if (f.type != kWldAmbientLight && !wld_string_at(wld.strings, f.name_ref))
            in.fail(f.body_offset, label() + ": name_ref " + std::to_string(f.name_ref) +
                                       " is outside the string hash (" + std::to_string(wld.strings.size()) +
                                       " bytes)");
        if (f.type == kWldRegion)
            wld.region_fragments.push_back(n);
        wld.fragments.push_back(f);
        at = f.body_offset + body_size;
    }
    wld.has_trailer = size - at >= 4 && in.read<uint32_t>(at, "trailer") == 0xFFFFFFFFu;
}

} // namespace

WldFile parse_wld(std::span<const uint8_t> bytes, const std::string& name)
{
    WldFile wld;
    wld.name = name;
    wld.bytes = bytes;
    const ByteReader in(bytes, name);
    wld.header = read_header(in);
    wld.strings = decode_string_hash(in.bytes(kWldHeaderSize, wld.header.string_hash_size, "string hash"));
    read_fragment_table(in, wld, kWldHeaderSize + wld.header.string_hash_size);
    // §7.3: region numbering is the 0x22 order; a header that disagrees truncates or disables
    // WQ's PVS and makes QL refuse the file.
    if (wld.header.region_count != wld.region_fragments.size())
        in.fail(12, "header region_count " + std::to_string(wld.header.region_count) + " but the file has " +
                        std::to_string(wld.region_fragments.size()) + " 0x22 region fragments");
    return wld;
}

std::string_view fragment_name(const WldFile& wld, const WldFragment& fragment)
{
    if (fragment.type == kWldAmbientLight)
        return {};
    return wld_string_at(wld.strings, fragment.name_ref).value_or(std::string_view{});
}

uint32_t resolve_fragment_ref(const WldFile& wld, int32_t ref)
{
    if (ref > 0)
        return uint32_t(ref) <= wld.fragments.size() ? uint32_t(ref) : 0;
    if (ref == 0)
        return 0;
    const auto name = wld_string_at(wld.strings, ref);
    if (!name || name->empty())
        return 0;
    for (uint32_t n = 1; n <= wld.fragments.size(); ++n)
        if (fragment_name(wld, wld.fragments[n - 1]) == *name)
            return n;
    return 0;
}

// ---- 0x21 ----

WldBspTree parse_bsp_tree(const WldFile& wld, uint32_t number)
{
    WldBodyReader r(wld, number, kWldBspTree);
    WldBspTree tree;
    tree.name_ref = r.read<int32_t>("name_ref");
    const uint32_t count = r.count("node_count", 28);
    tree.nodes.resize(count);
    const uint64_t nodes_at = r.at();
    for (uint32_t i = 0; i < count; ++i) {
        WldBspNode& node = tree.nodes[i];
        const uint64_t at = r.at();
        const int64_t n = int64_t{i} + 1;
        node.normal = r.vec3("node normal", n);
        node.d = r.read<float>("node d", n);
        if (!all_finite(node.normal) || !std::isfinite(node.d))
            r.fail(at, "node " + std::to_string(n) + " plane is not a finite number");
        const auto region = r.read<int32_t>("node region", n);
        const auto front = r.read<int32_t>("node front", n);
        const auto back = r.read<int32_t>("node back", n);
        if (region < 0 || uint32_t(region) > wld.region_count())
            r.fail(at + 16, "node " + std::to_string(n) + " region " + std::to_string(region) +
                                " is out of range (the file has " + std::to_string(wld.region_count()) + " regions)");
        for (const int32_t child : {front, back})
            if (child < 0 || uint32_t(child) > count)
                r.fail(at + (child == front ? 20 : 24), "node " + std::to_string(n) + " child " +
                                                            std::to_string(child) + " is out of range (the tree has " +
                                                            std::to_string(count) + " nodes)");
        node.region = uint32_t(region);
        node.front = uint32_t(front);
        node.back = uint32_t(back);
    }

    // Every walk must end: no node may be reached twice from the root (node 1). All non-zero
    // children are followed, whichever leaf rule (§3.2) a reader applies.
    std::vector<uint8_t> seen(count, 0);
    std::vector<uint32_t> stack;
    if (count > 0)
        stack.push_back(1);
    while (!stack.empty()) {
        const uint32_t n = stack.back();
        stack.pop_back();
        if (seen[n - 1]++)
            r.fail(nodes_at + uint64_t{n - 1} * 28, "node " + std::to_string(n) +
                                                        " is reached twice from the root (the tree has a cycle)");
        for (const uint32_t child : {tree.nodes[n - 1].front, tree.nodes[n - 1].back})
            if (child != 0)
                stack.push_back(child);
    }
    return tree;
}

std::vector<uint8_t> write_bsp_tree(const WldBspTree& tree)
{
    WldByteWriter w;
    w.put(tree.name_ref);
    w.put_count(tree.nodes, "0x21 nodes");
    for (const WldBspNode& node : tree.nodes) {
        w.put(node.normal);
        w.put(node.d);
        for (const uint32_t field : {node.region, node.front, node.back}) {
            if (field > uint32_t(std::numeric_limits<int32_t>::max()))
                throw std::invalid_argument("0x21 node field " + std::to_string(field) + " does not fit an i32");
            w.put(field);
        }
    }
    return w.finish();
}

// ---- 0x22 ----

WldRegion parse_region(const WldFile& wld, uint32_t number)
{
    WldBodyReader r(wld, number, kWldRegion);
    WldRegion region;
    region.name_ref = r.read<int32_t>("name_ref");
    region.flags = r.read<uint32_t>("flags");
    region.ambient_light = r.fragment_ref("ambient_light", kWldAnyFragmentType);
    // NV NP NR NW NO NC NN NL come first; each is checked against the bytes left when its part
    // is read.
    uint32_t counts[8];
    const uint64_t counts_at = r.at();
    for (uint32_t& c : counts)
        c = r.read<uint32_t>("region counts");
    const auto check = [&](int k, uint64_t min_bytes, const char* what) {
        r.check_count(counts[k], counts_at + 4 * uint64_t(k), min_bytes, what);
        return counts[k];
    };
    region.vertices = r.vec3s(check(0, 12, "num_region_vertices"), "region vertex");
    const uint32_t np = check(1, 8, "num_proximal_regions");
    region.proximal_regions.reserve(np);
    for (uint32_t i = 0; i < np; ++i) {
        WldProximalRegion& p = region.proximal_regions.emplace_back();
        p.region = r.read<uint32_t>("proximal region", i);
        p.distance = r.read<float>("proximal region distance", i);
    }
    // Render vertices are read whatever NW is (LX/QL; LQ reads them only when NW == 0, by its
    // own admission a guess).
    region.render_vertices = r.vec3s(check(2, 12, "num_render_vertices"), "render vertex");
    const uint32_t nw = check(3, 8, "num_walls");
    region.walls.reserve(nw);
    for (uint32_t i = 0; i < nw; ++i)
        region.walls.push_back(read_wall(r, i));
    const uint32_t no = check(4, 12, "num_obstacles");
    region.obstacles.reserve(no);
    for (uint32_t i = 0; i < no; ++i)
        region.obstacles.push_back(read_obstacle(r, i, region.walls.size()));
    region.cutting_obstacle_count = counts[5]; // no payload known (LQ/LX/WQ read none)
    const uint32_t nn = check(6, 28, "num_vis_nodes");
    region.vis_nodes.reserve(nn);
    for (uint32_t i = 0; i < nn; ++i)
        region.vis_nodes.push_back(read_vis_node(r, int64_t{i} + 1, nn, counts[7]));
    const uint32_t nl = check(7, 2, "num_vis_lists");
    region.vis_lists.reserve(nl);
    for (uint32_t i = 0; i < nl; ++i)
        region.vis_lists.push_back(read_vis_list(r, int64_t{i} + 1, (region.flags & kWldRegionVislistBytes) != 0));

    if (region.flags & kWldRegionSphere)
        region.sphere = r.vec4("sphere");
    if (region.flags & kWldRegionReverbVolume)
        region.reverb_volume = r.read<float>("reverb_volume");
    if (region.flags & kWldRegionReverbOffset)
        region.reverb_offset = r.read<int32_t>("reverb_offset");
    const uint32_t user_size = r.count("user_data_size", 1);
    const auto user = r.bytes(user_size, "user data");
    region.user_data.assign(user.begin(), user.end());
    if ((region.flags & kWldRegionMeshRef) || ((region.flags & kWldRegionLegacyMeshRef) && r.left() >= 4)) {
        const uint64_t ref_at = r.at();
        region.mesh_ref = r.fragment_ref("mesh_ref", kWldAnyFragmentType);
        check_mesh_target(r, region.mesh_ref, ref_at);
    }
    return region;
}

namespace {

void write_render_info(WldByteWriter& w, const WldRenderInfo& info)
{
    w.put(info.flags);
    if (info.flags & kWldRenderPen)
        w.put(info.pen);
    if (info.flags & kWldRenderBrightness)
        w.put(info.brightness);
    if (info.flags & kWldRenderScaledAmbient)
        w.put(info.scaled_ambient);
    if (info.flags & kWldRenderSprite)
        w.put(info.sprite_ref);
    if (info.flags & kWldRenderUvInfo) {
        w.put(info.uv_origin);
        w.put(info.u_axis);
        w.put(info.v_axis);
    }
    if (info.flags & kWldRenderUvMap) {
        w.put_count(info.uv_map, "0x22 wall uv map");
        w.put_each(info.uv_map);
    }
}

void write_obstacle(WldByteWriter& w, const WldObstacle& ob, size_t wall_count)
{
    if (!known_obstacle_type(ob.type))
        throw std::invalid_argument("0x22 obstacle type " + std::to_string(ob.type) + " has no known layout");
    if (ob.type == kWldObstacleEdgeWall && ob.edge_wall >= wall_count)
        throw std::invalid_argument("0x22 obstacle names wall " + std::to_string(ob.edge_wall) + " of " +
                                    std::to_string(wall_count));
    w.put(ob.flags);
    w.put(ob.next_region);
    w.put(ob.type);
    if (ob.type == kWldObstacleEdgePolygon || ob.type == kWldObstacleEdgePolygonNormal) {
        w.put_count(ob.vertices, "0x22 obstacle vertices");
        w.put_each(ob.vertices);
    }
    if (ob.type == kWldObstacleEdgePolygonNormal)
        w.put(ob.normal);
    if (ob.type == kWldObstacleEdgeWall)
        w.put(ob.edge_wall);
    if (ob.flags & kWldObstacleUserData) {
        w.put_count(ob.user_data, "0x22 obstacle user data");
        w.put_bytes(ob.user_data);
    }
}

void write_vis_list(WldByteWriter& w, const WldVisList& list, bool byte_form)
{
    if (list.byte_form != byte_form)
        throw std::invalid_argument("0x22 vis list form differs from the region's flag bit 7");
    if (!byte_form && list.data.size() % 2 != 0)
        throw std::invalid_argument("0x22 word-form vis list has an odd number of bytes");
    if (list.range_count() > 0xFFFF)
        throw std::invalid_argument("0x22 vis list has " + std::to_string(list.range_count()) +
                                    " elements (range_count is a u16)");
    w.put(static_cast<uint16_t>(list.range_count()));
    w.put_bytes(list.data);
}

} // namespace

std::vector<uint8_t> write_region(const WldRegion& region)
{
    const bool byte_form = (region.flags & kWldRegionVislistBytes) != 0;
    for (const WldVisNode& node : region.vis_nodes)
        if (node.vis_list_index > region.vis_lists.size() || node.front > region.vis_nodes.size() ||
            node.back > region.vis_nodes.size())
            throw std::invalid_argument("0x22 vis node names a list or node the region does not have");
    WldByteWriter w;
    w.put(region.name_ref);
    w.put(region.flags);
    w.put(region.ambient_light);
    w.put_count(region.vertices, "0x22 vertices");
    w.put_count(region.proximal_regions, "0x22 proximal regions");
    w.put_count(region.render_vertices, "0x22 render vertices");
    w.put_count(region.walls, "0x22 walls");
    w.put_count(region.obstacles, "0x22 obstacles");
    w.put(region.cutting_obstacle_count);
    w.put_count(region.vis_nodes, "0x22 vis nodes");
    w.put_count(region.vis_lists, "0x22 vis lists");
    w.put_each(region.vertices);
    for (const WldProximalRegion& p : region.proximal_regions) {
        w.put(p.region);
        w.put(p.distance);
    }
    w.put_each(region.render_vertices);
    for (const WldWall& wall : region.walls) {
        w.put(wall.flags);
        w.put_count(wall.vertices, "0x22 wall vertices");
        w.put_each(wall.vertices);
        if (wall.flags & kWldWallRenderData) {
            w.put(wall.render_method);
            write_render_info(w, wall.render_info);
            w.put(wall.normal);
        }
    }
    for (const WldObstacle& ob : region.obstacles)
        write_obstacle(w, ob, region.walls.size());
    for (const WldVisNode& node : region.vis_nodes) {
        w.put(node.normal);
        w.put(node.vis_list_index);
        w.put(node.front);
        w.put(node.back);
    }
    for (const WldVisList& list : region.vis_lists)
        write_vis_list(w, list, byte_form);
    if (region.flags & kWldRegionSphere)
        w.put(region.sphere);
    if (region.flags & kWldRegionReverbVolume)
        w.put(region.reverb_volume);
    if (region.flags & kWldRegionReverbOffset)
        w.put(region.reverb_offset);
    w.put_count(region.user_data, "0x22 user data");
    w.put_bytes(region.user_data);
    if (region.flags & (kWldRegionMeshRef | kWldRegionLegacyMeshRef))
        w.put(region.mesh_ref);
    return w.finish();
}

WldRegion make_interoperable_region(int32_t name_ref, std::vector<uint8_t> vislist_bytes, glm::vec4 sphere,
                                    int32_t mesh_ref)
{
    if (mesh_ref < 0)
        throw std::invalid_argument("a written mesh_ref must be a positive fragment number (or 0 for none)");
    WldRegion region;
    region.name_ref = name_ref;
    region.flags = kWldRegionSphere | kWldRegionVislistBytes | (mesh_ref > 0 ? kWldRegionMeshRef : 0u);
    region.vis_nodes.push_back(WldVisNode{glm::vec4(0.0f), 1, 0, 0});
    region.vis_lists.push_back(WldVisList{true, std::move(vislist_bytes)});
    region.sphere = sphere;
    region.mesh_ref = mesh_ref;
    return region;
}

bool is_interoperable_region(const WldRegion& region)
{
    const bool with_mesh = region.flags == 0x181u;
    return (with_mesh || region.flags == 0x81u) && region.ambient_light == 0 && region.vertices.empty() &&
           region.proximal_regions.empty() && region.render_vertices.empty() && region.walls.empty() &&
           region.obstacles.empty() && region.cutting_obstacle_count == 0 && region.vis_nodes.size() == 1 &&
           region.vis_nodes[0] == WldVisNode{glm::vec4(0.0f), 1, 0, 0} && region.vis_lists.size() == 1 &&
           region.vis_lists[0].byte_form && region.vis_lists[0].data.size() <= 0xFFFF && region.user_data.empty() &&
           (with_mesh ? region.mesh_ref > 0 : region.mesh_ref == 0);
}

EqVislistResult decode_vis_list(const WldVisList& list, size_t region_count, std::span<uint64_t> out)
{
    return list.byte_form ? decode_eq_vislist_bytes(list.data, region_count, out)
                          : decode_eq_vislist_words(list.data, region_count, out);
}

// ---- 0x29 ----

WldRegionType classify_region_type(std::string_view text)
{
    const std::string lower = lowercase(text);
    for (const TypePrefix& p : kTypePrefixes) {
        if (!lower.starts_with(p.prefix))
            continue;
        WldRegionType type{p.flags, std::nullopt};
        if (p.zone_line)
            type.zone_line = parse_zone_line(lower);
        return type;
    }
    return {};
}

WldRegionFlag parse_region_flag(const WldFile& wld, uint32_t number)
{
    WldBodyReader r(wld, number, kWldRegionFlag);
    WldRegionFlag flag;
    flag.name_ref = r.read<int32_t>("name_ref");
    flag.flags = r.read<uint32_t>("flags");
    const uint32_t count = r.count("region_count", 4);
    flag.regions.reserve(count);
    for (uint32_t i = 0; i < count; ++i) {
        const uint64_t at = r.at();
        const auto value = r.read<uint32_t>("region list entry", i);
        if (value >= wld.region_count())
            r.fail(at, "region list entry " + std::to_string(i) + " is region " + std::to_string(value) +
                           " (0-based) but the file has " + std::to_string(wld.region_count()) + " regions");
        flag.regions.push_back(value);
    }
    const uint32_t user_size = r.count("user_data_size", 1);
    flag.user_data = decode_wld_string(r.bytes(user_size, "user data"));

    // ZU's order: the name decides; only a name that names no type defers to the user data.
    flag.type = classify_region_type(fragment_name(wld, wld.fragments[number - 1]));
    flag.type_source = WldTypeSource::Name;
    if (flag.type.flags == 0) {
        flag.type = classify_region_type(flag.user_data);
        flag.type_source = flag.type.flags ? WldTypeSource::UserData : WldTypeSource::None;
    }
    return flag;
}

std::vector<uint8_t> write_region_flag(const WldRegionFlag& flag)
{
    WldByteWriter w;
    w.put(flag.name_ref);
    w.put(flag.flags);
    w.put_count(flag.regions, "0x29 regions");
    w.put_each(flag.regions);
    if (flag.user_data.empty()) {
        w.put(uint32_t{0});
    } else {
        const std::vector<uint8_t> encoded = encode_wld_string(flag.user_data);
        w.put_count(encoded, "0x29 user data");
        w.put_bytes(encoded);
    }
    return w.finish();
}

// ---- Assembling ----

namespace {

// §7.2: the tree before any region, every region before any region flag, the tree before the
// flags (ZU skips flags seen before it), one tree.
void check_order(std::span<const WldFragmentBytes> fragments)
{
    bool tree = false, flag = false;
    for (size_t i = 0; i < fragments.size(); ++i) {
        const uint32_t type = fragments[i].type;
        const auto where = [&] { return "WLD fragment " + std::to_string(i + 1) + " (" + wld_hex(type) + ")"; };
        if (type == kWldBspTree && tree)
            throw std::invalid_argument(where() + ": a second 0x21 bsp tree (readers keep only one)");
        if ((type == kWldRegion || type == kWldRegionFlag) && !tree)
            throw std::invalid_argument(where() + ": comes before the 0x21 bsp tree");
        if (type == kWldRegion && flag)
            throw std::invalid_argument(where() + ": a 0x22 region after a 0x29 region flag");
        tree = tree || type == kWldBspTree;
        flag = flag || type == kWldRegionFlag;
    }
}

} // namespace

std::vector<uint8_t> write_wld(uint32_t version, std::span<const char> strings,
                               std::span<const WldFragmentBytes> fragments)
{
    if (version != kWldVersionOld && version != kWldVersionNew)
        throw std::invalid_argument("unknown WLD version " + wld_hex(version));
    static const char kEmpty[1] = {'\0'};
    if (strings.empty())
        strings = kEmpty;
    if (strings.front() != '\0' || strings.back() != '\0')
        throw std::invalid_argument("the WLD string hash must start and end with a NUL");
    if (fragments.size() > std::numeric_limits<uint32_t>::max())
        throw std::invalid_argument("too many WLD fragments");
    check_order(fragments);

    const std::vector<uint8_t> hash = encode_string_hash(strings);
    if (hash.size() > std::numeric_limits<int32_t>::max())
        throw std::invalid_argument("the WLD string hash passes 2^31 - 1 bytes (name_refs are i32)");
    uint64_t max_size = 0, total = kWldHeaderSize + hash.size() + 4;
    uint32_t regions = 0;
    for (size_t i = 0; i < fragments.size(); ++i) {
        const WldFragmentBytes& f = fragments[i];
        const auto where = [&] { return "WLD fragment " + std::to_string(i + 1) + " (" + wld_hex(f.type) + ")"; };
        if (f.body.size() < 4)
            throw std::invalid_argument(where() + ": a body holds at least its name_ref");
        const uint64_t padded = (uint64_t{f.body.size()} + 3) / 4 * 4;
        if (padded > std::numeric_limits<uint32_t>::max() - 8)
            throw std::invalid_argument(where() + ": body too large");
        int32_t name_ref;
        std::memcpy(&name_ref, f.body.data(), 4);
        if (f.type != kWldAmbientLight && (name_ref > 0 || !wld_string_at(strings, name_ref)))
            throw std::invalid_argument(where() + ": name_ref " + std::to_string(name_ref) +
                                        " is positive or outside the string hash");
        max_size = std::max(max_size, padded);
        total += kWldFragmentHeaderSize + padded;
        regions += f.type == kWldRegion;
    }

    const auto string_count = static_cast<uint32_t>(std::count(strings.begin(), strings.end(), '\0') - 1);
    WldByteWriter out;
    out.reserve(total);
    out.put(kWldMagic);
    out.put(version);
    out.put(static_cast<uint32_t>(fragments.size()));
    out.put(regions);
    out.put(static_cast<uint32_t>(std::min<uint64_t>(max_size + 8, std::numeric_limits<uint32_t>::max())));
    out.put(static_cast<uint32_t>(hash.size()));
    out.put(string_count);
    out.put_bytes(hash); // padded to 4 by encode_string_hash
    for (const WldFragmentBytes& f : fragments) {
        out.put(static_cast<uint32_t>((uint64_t{f.body.size()} + 3) / 4 * 4));
        out.put(f.type);
        out.put_bytes(f.body);
        out.pad4();
    }
    out.put(0xFFFFFFFFu);
    return out.finish(); // every part is a multiple of 4: adds nothing
}

} // namespace pvs::eq
