#include "wld/eq/eq_zone_reader.h"

#include "visibility/bit_row.h"
#include "visibility/file_error.h"
#include "wld/common/quote.h"
#include "wld/eq/pfs_archive.h"
#include "wld/eq/stb_image_io.h"
#include "wld/eq/convex_face_builder.h"
#include "wld/eq/dds_decode.h"
#include "wld/eq/wld_file.h"
#include "wld/eq/wld_material.h"
#include "wld/eq/wld_mesh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>

namespace pvs::eq {

namespace {

constexpr size_t kNamesShown = 8; // how many names a note or error lists before "..."

std::string lower(std::string_view text)
{
    std::string out(text);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z')
            c = static_cast<char>(c - 'A' + 'a');
    return out;
}

std::string member_label(const std::string& file, const std::string& member)
{
    return file + ": member " + quote_for_message(member, 64);
}

std::string name_list(const std::vector<std::string>& names)
{
    std::string out;
    for (size_t i = 0; i < names.size() && i < kNamesShown; ++i)
        out += (i ? ", " : "") + quote_for_message(names[i], 64);
    if (names.size() > kNamesShown)
        out += ", ... (" + std::to_string(names.size()) + " in all)";
    return out.empty() ? "none" : out;
}

std::string hex32(uint32_t value)
{
    char text[16];
    std::snprintf(text, sizeof text, "0x%08X", value);
    return text;
}

std::vector<uint32_t> fragments_of_type(const WldFile& wld, uint32_t type)
{
    std::vector<uint32_t> out;
    for (uint32_t n = 1; n <= wld.fragments.size(); ++n)
        if (wld.fragments[n - 1].type == type)
            out.push_back(n);
    return out;
}

// ---- Which member is the zone WLD ----

bool holds_tree(const PfsArchive& archive, const std::string& member)
{
    try {
        const std::vector<uint8_t> bytes = archive.read(member);
        return !fragments_of_type(parse_wld(bytes, member), kWldBspTree).empty();
    } catch (const FileError&) {
        return false; // a broken WLD that is not the zone's is not our concern
    }
}

// `<stem>.wld`, else the only .wld with a 0x21.
std::string find_zone_wld(const PfsArchive& archive, const std::string& file)
{
    const std::string wanted = lower(std::filesystem::path(file).stem().string()) + ".wld";
    for (const std::string& member : archive.members())
        if (lower(member) == wanted)
            return member;
    std::vector<std::string> with_tree;
    for (const std::string& member : archive.members())
        if (lower(member).ends_with(".wld") && holds_tree(archive, member))
            with_tree.push_back(member);
    if (with_tree.size() == 1)
        return with_tree.front();
    throw FileError(file, 0,
                    "no zone WLD: there is no member " + quote_for_message(wanted, 64) +
                        (with_tree.empty() ? " and no .wld member holds a 0x21 bsp tree"
                                           : " and several .wld members hold a 0x21 bsp tree (" +
                                                 name_list(with_tree) + ")") +
                        "; members: " + name_list(archive.members()));
}

// ---- Where a region's first VISLIST starts (for error offsets) ----

uint64_t render_info_size(const WldRenderInfo& info)
{
    uint64_t size = 4;
    size += (info.flags & kWldRenderPen) ? 4 : 0;
    size += (info.flags & kWldRenderBrightness) ? 4 : 0;
    size += (info.flags & kWldRenderScaledAmbient) ? 4 : 0;
    size += (info.flags & kWldRenderSprite) ? 4 : 0;
    size += (info.flags & kWldRenderUvInfo) ? 36 : 0;
    size += (info.flags & kWldRenderUvMap) ? 4 + 8 * uint64_t{info.uv_map.size()} : 0;
    return size;
}

uint64_t wall_size(const WldWall& wall)
{
    const uint64_t render = (wall.flags & kWldWallRenderData) ? 4 + render_info_size(wall.render_info) + 16 : 0;
    return 8 + 4 * uint64_t{wall.vertices.size()} + render;
}

uint64_t obstacle_size(const WldObstacle& ob)
{
    uint64_t size = 12;
    if (ob.type == kWldObstacleEdgePolygon || ob.type == kWldObstacleEdgePolygonNormal)
        size += 4 + 4 * uint64_t{ob.vertices.size()};
    size += ob.type == kWldObstacleEdgePolygonNormal ? 16 : 0;
    size += ob.type == kWldObstacleEdgeWall ? 4 : 0;
    size += (ob.flags & kWldObstacleUserData) ? 4 + uint64_t{ob.user_data.size()} : 0;
    return size;
}

// Body offset of the first list's elements: the §4.1 parts before it, as parse_region read them.
uint64_t first_vis_list_data(const WldRegion& region)
{
    uint64_t at = 12 + 32; // name_ref, flags, ambient_light, the eight counts
    at += 12 * uint64_t{region.vertices.size()} + 8 * uint64_t{region.proximal_regions.size()} +
          12 * uint64_t{region.render_vertices.size()};
    for (const WldWall& wall : region.walls)
        at += wall_size(wall);
    for (const WldObstacle& ob : region.obstacles)
        at += obstacle_size(ob);
    return at + 28 * uint64_t{region.vis_nodes.size()} + 2; // + the list's range_count
}

// ---- The loader ----

// Zone vertices by exact value (bit patterns of position and uv), so that equal vertices of
// different meshes become one. Open addressing over flat arrays: nothing is allocated per vertex.
class ZoneVertexIndex {
public:
    uint32_t find_or_add(const glm::vec3& position, const glm::vec2& uv, Mesh& mesh)
    {
        if (2 * (mesh.positions.size() + 1) > slots_.size())
            grow(mesh);
        const std::array<uint32_t, 5> key = bits_of(position, uv);
        for (size_t slot = hash(key) & (slots_.size() - 1);; slot = (slot + 1) & (slots_.size() - 1)) {
            const uint32_t held = slots_[slot];
            if (held == kEmpty) {
                const auto added = static_cast<uint32_t>(mesh.positions.size());
                slots_[slot] = added;
                mesh.positions.push_back(position);
                mesh.uvs.push_back(uv);
                return added;
            }
            if (bits_of(mesh.positions[held], mesh.uvs[held]) == key)
                return held;
        }
    }

private:
    static constexpr uint32_t kEmpty = 0xFFFFFFFFu;

    static std::array<uint32_t, 5> bits_of(const glm::vec3& p, const glm::vec2& uv)
    {
        return {std::bit_cast<uint32_t>(p.x), std::bit_cast<uint32_t>(p.y), std::bit_cast<uint32_t>(p.z),
                std::bit_cast<uint32_t>(uv.x), std::bit_cast<uint32_t>(uv.y)};
    }
    static size_t hash(const std::array<uint32_t, 5>& key)
    {
        uint64_t h = 0x9E3779B97F4A7C15ull;
        for (const uint32_t k : key) { // splitmix64's finalizer per word: every bit reaches the low ones
            h ^= k;
            h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
            h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
            h ^= h >> 31;
        }
        return size_t(h);
    }
    void grow(const Mesh& mesh)
    {
        slots_.assign(std::max<size_t>(1024, slots_.size() * 2), kEmpty);
        for (uint32_t v = 0; v < mesh.positions.size(); ++v) {
            const std::array<uint32_t, 5> key = bits_of(mesh.positions[v], mesh.uvs[v]);
            size_t slot = hash(key) & (slots_.size() - 1);
            while (slots_[slot] != kEmpty)
                slot = (slot + 1) & (slots_.size() - 1);
            slots_[slot] = v;
        }
    }

    std::vector<uint32_t> slots_; // zone vertex, or kEmpty; a power of two, at most half full
};

struct MaterialKey {
    std::string file_lower;
    bool visible;
    auto operator<=>(const MaterialKey&) const = default;
};

class EqZoneLoader {
public:
    EqZoneLoader(const PfsArchive& archive, const WldFile& wld, Zone& zone)
        : archive_(archive), wld_(wld), zone_(zone)
    {
    }

    void load()
    {
        describe_file();
        for (const uint32_t number : wld_.region_fragments)
            regions_.push_back(parse_region(wld_, number));
        zone_.regions.resize(regions_.size());
        read_tree();
        read_materials();
        read_faces();
        read_textures();
        read_pvs();
        read_flags();
        zone_.source.counts.emplace_back("zone_lines", zone_.zone_lines.size());
    }

private:
    [[noreturn]] void fail(uint64_t offset, const std::string& reason) const
    {
        throw FileError(wld_.name, offset, reason);
    }
    void note(std::string text) { zone_.source.notes.push_back(std::move(text)); }

    void describe_file();
    void read_tree();
    int32_t tree_child(const WldBspTree& eq, uint32_t number, std::vector<uint32_t>& leaves_of_region);
    void note_tree(const WldBspTree& eq, const std::vector<uint32_t>& leaves_of_region);
    void read_materials();
    uint32_t intern_material(const std::string& file, bool visible, bool sky);
    void read_faces();
    void copy_mesh(uint32_t number);
    void read_textures();
    void read_pvs();
    bool pvs_row(uint32_t r, std::span<uint64_t> row) const;
    void read_flags();
    void add_zone_line(const WldRegionFlag& flag);

    const PfsArchive& archive_;
    const WldFile& wld_;
    Zone& zone_;
    std::vector<WldRegion> regions_;
    std::map<MaterialKey, uint32_t> materials_;
    std::map<uint32_t, std::vector<uint32_t>> palettes_; // 0x31 number -> zone material per entry
    std::map<uint32_t, std::pair<uint32_t, uint32_t>> meshes_; // 0x36 number -> first face, face count
    std::map<uint32_t, Aabb> mesh_box_;                        // 0x36 number -> its vertices' box
    ZoneVertexIndex vertices_;
    std::vector<uint32_t> mesh_vertex_; // the current mesh's vertex -> zone vertex
};

void EqZoneLoader::describe_file()
{
    ZoneSource& s = zone_.source;
    s.format = "EverQuest S3D/WLD";
    s.version = hex32(wld_.header.version) + (wld_.header.version == kWldVersionOld ? " (old)" : " (new)");
    s.counts.emplace_back("fragments", wld_.fragments.size());
    std::map<uint32_t, uint64_t> by_type;
    for (const WldFragment& f : wld_.fragments)
        ++by_type[f.type];
    for (const auto& [type, count] : by_type) {
        char name[24];
        std::snprintf(name, sizeof name, "fragments.0x%02X", type);
        s.counts.emplace_back(name, count);
    }
    s.counts.emplace_back("regions", wld_.region_count());
    note("triangle winding is kept as stored (EverQuest readers disagree on it; draw two-sided)");
}

// ---- Tree ----

void EqZoneLoader::read_tree()
{
    const std::vector<uint32_t> trees = fragments_of_type(wld_, kWldBspTree);
    if (trees.empty())
        fail(0, "the zone WLD has no 0x21 bsp tree");
    if (trees.size() > 1)
        note(std::to_string(trees.size()) + " 0x21 bsp trees: the first (fragment " + std::to_string(trees.front()) +
             ") is used");
    const WldBspTree eq = parse_bsp_tree(wld_, trees.front());
    zone_.tree.tie_rule = TieRule::OnPlaneGoesFront;
    std::vector<uint32_t> leaves_of_region(zone_.regions.size(), 0);
    zone_.tree.root = tree_child(eq, eq.nodes.empty() ? 0 : 1, leaves_of_region);
    note_tree(eq, leaves_of_region);
}

// Converts the subtree at EQ node `number` (0: missing child) in preorder, front first, with an
// explicit stack: zone trees can be deep. Returns the zone child encoding of its root.
int32_t EqZoneLoader::tree_child(const WldBspTree& eq, uint32_t number, std::vector<uint32_t>& leaves_of_region)
{
    BspTree& tree = zone_.tree;
    struct Pending {
        uint32_t eq_node;
        int32_t parent; // zone node, -1 for the root
        int side;
    };
    int32_t root = 0;
    std::vector<Pending> stack{{number, -1, 0}};
    while (!stack.empty()) {
        const Pending p = stack.back();
        stack.pop_back();
        int32_t child;
        const WldBspNode* node = p.eq_node ? &eq.nodes[p.eq_node - 1] : nullptr;
        if (node && node->region == 0 && (node->front || node->back)) {
            child = static_cast<int32_t>(tree.nodes.size());
            tree.nodes.push_back({node->normal, -node->d, {0, 0}});
            stack.push_back({node->back, child, 1});
            stack.push_back({node->front, child, 0});
        } else {
            const bool region = node && node->region > 0;
            if (region)
                ++leaves_of_region[node->region - 1];
            child = ~static_cast<int32_t>(tree.leaf_region.size());
            tree.leaf_region.push_back(region ? static_cast<int32_t>(node->region - 1) : kLeafOutside);
        }
        if (p.parent < 0)
            root = child;
        else
            tree.nodes[size_t(p.parent)].children[p.side] = child;
    }
    return root;
}

void EqZoneLoader::note_tree(const WldBspTree& eq, const std::vector<uint32_t>& leaves_of_region)
{
    const auto none = std::count(leaves_of_region.begin(), leaves_of_region.end(), 0u);
    const auto several =
        std::count_if(leaves_of_region.begin(), leaves_of_region.end(), [](uint32_t n) { return n > 1; });
    const auto with_children = std::count_if(eq.nodes.begin(), eq.nodes.end(), [](const WldBspNode& n) {
        return n.region > 0 && (n.front || n.back);
    });
    if (none)
        note(std::to_string(none) + " regions are no leaf of the tree (no point lies in them)");
    if (several)
        note(std::to_string(several) + " regions are several leaves of the tree (ZU marks only the first)");
    if (with_children)
        note(std::to_string(with_children) + " tree nodes have a region and children: read as leaves (WQ's rule)");
    zone_.source.counts.emplace_back("tree.nodes", eq.nodes.size());
}

// ---- Materials and faces ----

uint32_t EqZoneLoader::intern_material(const std::string& file, bool visible, bool sky)
{
    const auto [it, added] = materials_.try_emplace(MaterialKey{lower(file), visible},
                                                    static_cast<uint32_t>(zone_.materials.size()));
    if (added) {
        Material& m = zone_.materials.emplace_back();
        m.name = file;
        m.flags = visible ? 0u : kMaterialInvisible;
    }
    if (sky)
        zone_.materials[it->second].flags |= kMaterialSky;
    return it->second;
}

void EqZoneLoader::read_materials()
{
    for (const uint32_t number : fragments_of_type(wld_, kWldMaterialPalette)) {
        const WldMaterialPalette palette = parse_material_palette(wld_, number);
        std::vector<uint32_t>& entries = palettes_[number];
        for (uint32_t i = 0; i < palette.materials.size(); ++i) {
            const uint32_t material = material_fragment_of(wld_, number, i);
            const bool sky = material != 0 && decode_render_method(parse_material(wld_, material).render_method).type ==
                                                  WldMaterialType::SkyDome;
            const bool visible = material_is_visible(wld_, number, i);
            entries.push_back(intern_material(texture_file_of(wld_, number, i), visible, sky));
        }
    }
}

// Appends the mesh's triangles and records where they went. A run of triangles of one material
// that forms a convex planar polygon becomes one face (convex_face_builder.h). Its vertices join
// the zone's shared vertex list: each (position, uv) is one zone vertex however many meshes hold
// it (neighbouring regions repeat the corners they share).
void EqZoneLoader::copy_mesh(uint32_t number)
{
    const WldMesh m = parse_mesh(wld_, number);
    Mesh& mesh = zone_.mesh;
    const bool has_uvs = m.uvs.size() == m.positions.size();
    mesh_vertex_.resize(m.positions.size());
    for (size_t v = 0; v < m.positions.size(); ++v)
        mesh_vertex_[v] = vertices_.find_or_add(m.positions[v], has_uvs ? m.uvs[v] : glm::vec2(0.0f), mesh);
    const auto first_face = static_cast<uint32_t>(mesh.faces.size());
    const uint32_t palette = resolve_fragment_ref(wld_, m.material_palette_ref);
    const auto found = palettes_.find(palette);
    const std::vector<uint16_t> materials = face_materials(m);
    ConvexFaceBuilder polygon;
    for (size_t f = 0; f < m.faces.size(); ++f) {
        const uint32_t material =
            found != palettes_.end() ? found->second[materials[f]] : intern_material("", false, false);
        const bool joins =
            f > 0 && material == mesh.faces.back().material && polygon.try_add(m.faces[f].vertices);
        if (joins) {
            ++mesh.faces.back().triangle_count;
        } else {
            polygon.start(m.positions, m.faces[f].vertices);
            mesh.faces.push_back({static_cast<uint32_t>(mesh.triangle_count()), 1, material});
        }
        for (const uint16_t v : m.faces[f].vertices)
            mesh.indices.push_back(mesh_vertex_[v]);
    }
    Aabb box;
    for (const glm::vec3& p : m.positions)
        box.grow(p);
    meshes_[number] = {first_face, static_cast<uint32_t>(mesh.faces.size()) - first_face};
    mesh_box_[number] = box;
}

void EqZoneLoader::read_faces()
{
    zone_.region_face_offsets.assign(regions_.size() + 1, 0);
    uint64_t legacy = 0;
    for (size_t r = 0; r < regions_.size(); ++r) {
        const uint32_t number = resolve_fragment_ref(wld_, regions_[r].mesh_ref);
        Region& region = zone_.regions[r];
        if (number != 0 && wld_.fragments[number - 1].type == kWldMesh) {
            if (!meshes_.count(number))
                copy_mesh(number);
            const auto [first, count] = meshes_[number];
            for (uint32_t f = first; f < first + count; ++f)
                zone_.region_faces.push_back(f);
            region.bounds = mesh_box_[number];
        } else {
            legacy += number != 0;
        }
        const glm::vec4 s = regions_[r].sphere;
        if (region.bounds.empty() && (regions_[r].flags & kWldRegionSphere) && std::isfinite(s.x) &&
            std::isfinite(s.y) && std::isfinite(s.z) && std::isfinite(s.w) && s.w >= 0.0f) {
            region.bounds.grow(glm::vec3(s) - s.w);
            region.bounds.grow(glm::vec3(s) + s.w);
        }
        zone_.region_face_offsets[r + 1] = static_cast<uint32_t>(zone_.region_faces.size());
    }
    if (legacy)
        note(std::to_string(legacy) + " regions name a legacy 0x2C mesh, which is not read");
    zone_.source.counts.emplace_back("meshes", meshes_.size());
    zone_.source.counts.emplace_back("materials", zone_.materials.size());
}

void EqZoneLoader::read_textures()
{
    std::vector<std::string> missing, undecodable;
    uint64_t decoded = 0, dds_decoded = 0;
    for (Material& m : zone_.materials) {
        if (m.name.empty())
            continue;
        if (!archive_.contains(m.name)) {
            missing.push_back(m.name);
            continue;
        }
        std::string why;
        const std::vector<uint8_t> bytes = archive_.read(m.name);
        // By the magic, not the name: archives hold DDS data under .bmp names too.
        const bool dds = looks_like_dds(bytes);
        std::optional<RgbaImage> image = dds ? decode_dds(bytes, &why) : decode_bmp(bytes, &why);
        dds_decoded += dds && image;
        if (!image) {
            undecodable.push_back(m.name + " (" + why + ")");
            continue;
        }
        set_material_rgba(m, image->width, image->height, image->rgba);
        ++decoded;
    }
    zone_.source.counts.emplace_back("textures.decoded", decoded);
    zone_.source.counts.emplace_back("textures.dds", dds_decoded);
    if (!missing.empty())
        note(std::to_string(missing.size()) + " textures are not in the archive: " + name_list(missing));
    if (!undecodable.empty())
        note(std::to_string(undecodable.size()) + " textures are neither BMP nor DDS (DXT1/3/5) pvscope can decode: " +
             name_list(undecodable));
}

// ---- PVS ----

bool EqZoneLoader::pvs_row(uint32_t r, std::span<uint64_t> row) const
{
    const WldRegion& region = regions_[r];
    if (region.vis_lists.empty() || region.vis_lists[0].range_count() == 0)
        return false; // WQ: "no PVS data", show everything
    const EqVislistResult result = decode_vis_list(region.vis_lists[0], regions_.size(), row);
    if (!result.well_formed) {
        const uint32_t number = wld_.region_fragments[r];
        fail(wld_.fragments[number - 1].body_offset + first_vis_list_data(region) + result.consumed,
             "fragment " + std::to_string(number) + " (0x22 region): VISLIST of region " + std::to_string(r) +
                 " is malformed at list byte " + std::to_string(result.consumed) +
                 (region.vis_lists[0].byte_form ? " (a 0x3F/0xFF code without its two bytes)" : " (an odd byte)"));
    }
    return true;
}

void EqZoneLoader::read_pvs()
{
    const auto n = static_cast<uint32_t>(regions_.size());
    uint64_t rows = 0, extra_lists = 0, word_form = 0;
    for (const WldRegion& region : regions_) {
        rows += !region.vis_lists.empty() && region.vis_lists[0].range_count() > 0;
        extra_lists += region.vis_lists.size() > 1;
        word_form += !region.vis_lists.empty() && !region.vis_lists[0].byte_form;
    }
    zone_.source.counts.emplace_back("pvs.rows_in_file", rows);
    if (extra_lists)
        note(std::to_string(extra_lists) + " regions have several VISLISTs: only the first is used");
    if (word_form)
        note(std::to_string(word_form) + " VISLISTs are in the word form (read as region numbers, quail's reading)");
    if (rows == 0) {
        note("no PVS: no region has a VISLIST (every region sees everything)");
        return;
    }
    zone_.baked_pvs = Pvs::build(n, [&](uint32_t r, std::span<uint64_t> row) { return pvs_row(r, row); });
}

// ---- Flags and zone lines ----

std::string zone_line_target(const std::optional<WldZoneLineTarget>& target)
{
    if (!target)
        return "unreadable destination";
    if (target->zone_id == 255)
        return "zone 255 point " + std::to_string(target->zone_point);
    return "zone " + std::to_string(target->zone_id) + " (" + std::to_string(target->x) + ", " +
           std::to_string(target->y) + ", " + std::to_string(target->z) + ") heading " +
           std::to_string(target->heading);
}

// One zone line per destination: a DRNTP and a WTNTP (a zone line in water) with the same
// destination are one line whose regions are in either list.
void EqZoneLoader::add_zone_line(const WldRegionFlag& flag)
{
    const std::string target = zone_line_target(flag.type.zone_line);
    auto same = std::find_if(zone_.zone_lines.begin(), zone_.zone_lines.end(),
                             [&](const ZoneLine& l) { return flag.type.zone_line && l.target == target; });
    if (same == zone_.zone_lines.end()) {
        zone_.zone_lines.push_back({target, {}});
        same = zone_.zone_lines.end() - 1;
    }
    const auto index = static_cast<int32_t>(same - zone_.zone_lines.begin());
    for (const uint32_t r : flag.regions) {
        zone_.regions[r].zone_line = index;
        if (!zone_.regions[r].bounds.empty())
            same->bounds.grow(zone_.regions[r].bounds);
    }
}

void EqZoneLoader::read_flags()
{
    uint64_t untyped = 0;
    for (const uint32_t number : fragments_of_type(wld_, kWldRegionFlag)) {
        const WldRegionFlag flag = parse_region_flag(wld_, number);
        if (flag.type.flags == 0) {
            ++untyped;
            continue;
        }
        for (const uint32_t r : flag.regions)
            zone_.regions[r].flags |= flag.type.flags;
        if (flag.type.flags & kRegionZoneLine)
            add_zone_line(flag);
    }
    if (untyped)
        note(std::to_string(untyped) + " 0x29 region flags name no type pvscope knows; ignored");
}

} // namespace

bool looks_like_pfs(std::span<const uint8_t> bytes)
{
    return bytes.size() >= 12 && bytes[4] == 'P' && bytes[5] == 'F' && bytes[6] == 'S' && bytes[7] == ' ';
}

Zone load_eq_zone(std::span<const uint8_t> s3d, const std::string& file)
{
    const PfsArchive archive(s3d, file);
    const std::string member = find_zone_wld(archive, file);
    const std::vector<uint8_t> bytes = archive.read(member);
    const WldFile wld = parse_wld(bytes, member_label(file, member));
    Zone zone;
    zone.source.path = file;
    EqZoneLoader(archive, wld, zone).load();
    zone.source.notes.insert(zone.source.notes.begin(), "zone WLD: " + member);
    zone.shrink_to_fit(); // loaders grow their vectors; keep only what the zone needs
    return zone;
}

} // namespace pvs::eq
