#include "wld/doom/doom_zone.h"

#include "visibility/codec/glvis_rows.h"
#include "visibility/bit_row.h"
#include "visibility/file_error.h"
#include "wld/doom/doom_specials.h"
#include "wld/doom/doom_textures.h"
#include "wld/doom/line_plane.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <map>

namespace pvs::doom {

namespace {

constexpr double kFlatSize = 64.0;

bool is_wall_seg(const GlSeg& seg) { return seg.linedef != kNoLinedef && seg.partner == kNoPartner; }

glm::vec2 point(const DoomMap& map, uint32_t v) { return {float(map.vertices[v].x), float(map.vertices[v].y)}; }

// The vertical plane through (ax, ay) along (dx, dy), the right side in front (line_plane.h: one
// line, one plane, bit for bit, whichever of its points and direction lengths names it).
BspNode line_node(double ax, double ay, double dx, double dy)
{
    const LinePlane plane = vertical_line_plane(ax, ay, dx, dy);
    BspNode node{};
    node.normal = glm::vec3(plane.nx, plane.ny, 0.0f);
    node.dist = plane.dist;
    return node;
}

uint32_t damage_flags(int16_t special)
{
    if (special >= 32) { // Boom generalized sector: damage in bits 5-6
        switch ((special >> 5) & 3) {
        case 1: return kRegionSlime;
        case 2:
        case 3: return kRegionLava;
        default: return 0;
        }
    }
    switch (special) {
    case 7: return kRegionSlime;
    case 4:
    case 5:
    case 11:
    case 16: return kRegionLava;
    default: return 0;
    }
}

bool is_exit(uint16_t special) { return special == 11 || special == 52 || special == 197; }
bool is_secret_exit(uint16_t special) { return special == 51 || special == 124 || special == 198; }

class ZoneBuilder {
public:
    ZoneBuilder(const DoomMap& map, const DoomTextures* textures) : map_(map), textures_(textures) {}

    Zone build()
    {
        zone_.regions.resize(map_.subsectors.size());
        build_tree();
        build_mesh();
        mark_flags();
        attach_gl_pvs();
        describe();
        zone_.shrink_to_fit();
        return std::move(zone_);
    }

private:
    const DoomMap& map_;
    const DoomTextures* textures_;
    Zone zone_;
    std::map<std::string, uint32_t> material_index_;

    const Sector& sector_of(uint32_t subsector) const { return map_.sectors[map_.subsectors[subsector].sector]; }

    void build_tree()
    {
        BspTree& tree = zone_.tree;
        const size_t ss_count = map_.subsectors.size();
        tree.leaf_region.resize(ss_count + 1);
        tree.leaf_region[0] = kLeafSolid;
        for (size_t s = 0; s < ss_count; ++s)
            tree.leaf_region[s + 1] = int32_t(s);
        constexpr int32_t solid = ~0;
        for (const GlNode& gl : map_.nodes) {
            BspNode node = line_node(gl.x, gl.y, gl.dx, gl.dy);
            node.children[0] = gl.children[0];
            node.children[1] = gl.children[1];
            tree.nodes.push_back(node);
        }
        // Wall chains: the entry of subsector s is its first wall node, or its floor node.
        std::vector<int32_t> entry(ss_count);
        std::vector<size_t> last_wall(ss_count, SIZE_MAX);
        for (size_t s = 0; s < ss_count; ++s) {
            const GlSubsector& ss = map_.subsectors[s];
            for (uint32_t k = 0; k < ss.seg_count; ++k) {
                const GlSeg& seg = map_.segs[ss.first_seg + k];
                if (!is_wall_seg(seg))
                    continue;
                // The wall's plane is its linedef's line, not the seg's: a seg end can be a GL
                // vertex rounded to 16.16, and a plane through it differs by ~1e-5 from the node
                // built on the same linedef, leaving a sliver of solid along an open boundary.
                const Linedef& line = map_.linedefs[seg.linedef];
                const MapVertex a = map_.vertices[seg.side == 0 ? line.v1 : line.v2];
                const MapVertex b = map_.vertices[seg.side == 0 ? line.v2 : line.v1];
                if (a.x == b.x && a.y == b.y)
                    continue;
                BspNode node = line_node(a.x, a.y, b.x - a.x, b.y - a.y);
                node.children[1] = solid;
                if (last_wall[s] == SIZE_MAX)
                    entry[s] = int32_t(tree.nodes.size());
                else
                    tree.nodes[last_wall[s]].children[0] = int32_t(tree.nodes.size());
                last_wall[s] = tree.nodes.size();
                tree.nodes.push_back(node);
            }
        }
        tree.first_height_node = uint32_t(tree.nodes.size());
        for (size_t s = 0; s < ss_count; ++s) {
            const int32_t floor_index = int32_t(tree.nodes.size());
            if (last_wall[s] == SIZE_MAX)
                entry[s] = floor_index;
            else
                tree.nodes[last_wall[s]].children[0] = floor_index;
            const Sector& sector = sector_of(uint32_t(s));
            BspNode floor{glm::vec3(0, 0, 1), float(sector.floor_height), {floor_index + 1, solid}};
            BspNode ceiling{glm::vec3(0, 0, -1), -float(sector.ceiling_height), {~int32_t(s + 1), solid}};
            tree.nodes.push_back(floor);
            tree.nodes.push_back(ceiling);
        }
        for (size_t n = 0; n < map_.nodes.size(); ++n)
            for (int32_t& child : tree.nodes[n].children)
                if (child < 0)
                    child = entry[size_t(~child)];
        tree.root = map_.nodes.empty() ? entry[0] : int32_t(map_.nodes.size() - 1);
        tree.tie_rule = TieRule::OnPlaneGoesBack;
    }

    uint32_t material(const std::string& name, bool flat)
    {
        const std::string key = (flat ? "F:" : "W:") + name;
        if (auto it = material_index_.find(key); it != material_index_.end())
            return it->second;
        Material m;
        m.name = name;
        m.width = 64;
        m.height = flat ? 64 : 128;
        if (textures_) {
            if (auto image = flat ? textures_->flat(name) : textures_->wall(name))
                set_material_rgba(m, image->width, image->height, image->rgba);
        }
        if (flat && name.rfind("F_SKY", 0) == 0)
            m.flags |= kMaterialSky;
        const uint32_t index = uint32_t(zone_.materials.size());
        zone_.materials.push_back(std::move(m));
        material_index_.emplace(key, index);
        return index;
    }

    // The sky drawn where two sky ceilings meet at different heights.
    uint32_t sky_wall_material()
    {
        const uint32_t m = material("F_SKY1", true);
        zone_.materials[m].flags |= kMaterialSky;
        return m;
    }

    // Starts a face; returns its index.
    uint32_t begin_face(uint32_t material_index)
    {
        Face face;
        face.first_triangle = uint32_t(zone_.mesh.triangle_count());
        face.material = material_index;
        zone_.mesh.faces.push_back(face);
        return uint32_t(zone_.mesh.faces.size() - 1);
    }

    void end_face(uint32_t face, std::vector<uint32_t>& region_faces)
    {
        Face& f = zone_.mesh.faces[face];
        f.triangle_count = uint32_t(zone_.mesh.triangle_count()) - f.first_triangle;
        region_faces.push_back(face);
    }

    void fan(const std::vector<glm::vec3>& points, const std::vector<glm::vec2>& uvs)
    {
        Mesh& mesh = zone_.mesh;
        const uint32_t base = uint32_t(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(), points.begin(), points.end());
        mesh.uvs.insert(mesh.uvs.end(), uvs.begin(), uvs.end());
        for (uint32_t i = 1; i + 1 < points.size(); ++i)
            mesh.indices.insert(mesh.indices.end(), {base, base + i, base + i + 1});
    }

    // The subsector's polygon, clockwise seen from above (the segs' order), without repeats.
    std::vector<glm::vec2> polygon(uint32_t s) const
    {
        std::vector<glm::vec2> points;
        const GlSubsector& ss = map_.subsectors[s];
        for (uint32_t k = 0; k < ss.seg_count; ++k) {
            const glm::vec2 p = point(map_, map_.segs[ss.first_seg + k].v1);
            if (points.empty() || points.back() != p)
                points.push_back(p);
        }
        while (points.size() > 1 && points.front() == points.back())
            points.pop_back();
        return points;
    }

    void add_flats(uint32_t s, std::vector<uint32_t>& faces)
    {
        const std::vector<glm::vec2> outline = polygon(s);
        if (outline.size() < 3)
            return;
        const Sector& sector = sector_of(s);
        std::vector<glm::vec3> points;
        std::vector<glm::vec2> uvs;
        // Floor: counter-clockwise from above (reverse of the segs' clockwise order).
        for (size_t i = outline.size(); i-- > 0;) {
            points.emplace_back(outline[i], float(sector.floor_height));
            uvs.emplace_back(outline[i].x / kFlatSize, -outline[i].y / kFlatSize);
        }
        uint32_t face = begin_face(material(sector.floor_flat, true));
        fan(points, uvs);
        end_face(face, faces);
        points.clear();
        uvs.clear();
        for (const glm::vec2& p : outline) {
            points.emplace_back(p, float(sector.ceiling_height));
            uvs.emplace_back(p.x / kFlatSize, -p.y / kFlatSize);
        }
        face = begin_face(material(sector.ceiling_flat, true));
        fan(points, uvs);
        end_face(face, faces);
    }

    // A wall quad along seg a->b from z0 up to z1, facing the seg's right side.
    // A wall blocks sight whatever its texture says: a missing one ("-", the engines' hall of
    // mirrors) gets the untextured material "-"; `sky` makes it a sky wall (the upper part
    // between two sky ceilings, which the engines fill with sky).
    void add_wall(const GlSeg& seg, float z0, float z1, const std::string& texture, std::vector<uint32_t>& faces,
                  bool sky = false)
    {
        if (!(z1 > z0))
            return;
        const glm::vec2 a = point(map_, seg.v1), b = point(map_, seg.v2);
        const Linedef& line = map_.linedefs[seg.linedef];
        const Sidedef& side = map_.sidedefs[size_t(line.side[seg.side])];
        const glm::vec2 line_start = point(map_, seg.side == 0 ? line.v1 : line.v2);
        const uint32_t m = sky ? sky_wall_material() : material(texture.empty() ? "-" : texture, false);
        const float w = float(zone_.materials[m].width), h = float(zone_.materials[m].height);
        const float u0 = (glm::distance(line_start, a) + side.x_offset) / w;
        const float u1 = u0 + glm::distance(a, b) / w;
        const float v1 = float(side.y_offset) / h, v0 = v1 + (z1 - z0) / h;
        const uint32_t face = begin_face(m);
        fan({glm::vec3(a, z0), glm::vec3(b, z0), glm::vec3(b, z1), glm::vec3(a, z1)},
            {glm::vec2(u0, v0), glm::vec2(u1, v0), glm::vec2(u1, v1), glm::vec2(u0, v1)});
        end_face(face, faces);
    }

    void add_walls(uint32_t s, std::vector<uint32_t>& faces)
    {
        const GlSubsector& ss = map_.subsectors[s];
        const Sector& front = sector_of(s);
        for (uint32_t k = 0; k < ss.seg_count; ++k) {
            const GlSeg& seg = map_.segs[ss.first_seg + k];
            if (seg.linedef == kNoLinedef)
                continue;
            const Linedef& line = map_.linedefs[seg.linedef];
            const Sidedef& side = map_.sidedefs[size_t(line.side[seg.side])];
            const int32_t back_side = line.side[seg.side ^ 1];
            if (back_side < 0 || seg.partner == kNoPartner) {
                add_wall(seg, front.floor_height, front.ceiling_height, side.middle, faces);
                continue;
            }
            const Sector& back = map_.sectors[map_.sidedefs[size_t(back_side)].sector];
            add_wall(seg, front.floor_height, back.floor_height, side.lower, faces);
            const bool both_sky = front.ceiling_flat.rfind("F_SKY", 0) == 0 && back.ceiling_flat.rfind("F_SKY", 0) == 0;
            add_wall(seg, back.ceiling_height, front.ceiling_height, side.upper, faces, both_sky);
        }
    }

    void build_mesh()
    {
        zone_.region_face_offsets.push_back(0);
        std::vector<uint32_t> faces;
        for (uint32_t s = 0; s < map_.subsectors.size(); ++s) {
            faces.clear();
            add_flats(s, faces);
            add_walls(s, faces);
            zone_.region_faces.insert(zone_.region_faces.end(), faces.begin(), faces.end());
            zone_.region_face_offsets.push_back(uint32_t(zone_.region_faces.size()));
            Aabb& bounds = zone_.regions[s].bounds;
            const Sector& sector = sector_of(s);
            for (const glm::vec2& p : polygon(s)) {
                bounds.grow(glm::vec3(p, float(sector.floor_height)));
                bounds.grow(glm::vec3(p, float(std::max(sector.ceiling_height, sector.floor_height))));
            }
        }
    }

    void mark_flags()
    {
        for (uint32_t s = 0; s < map_.subsectors.size(); ++s)
            zone_.regions[s].flags |= damage_flags(sector_of(s).special);
        std::map<uint32_t, int32_t> line_of_exit; // linedef -> zone line
        for (uint32_t s = 0; s < map_.subsectors.size(); ++s) {
            const GlSubsector& ss = map_.subsectors[s];
            for (uint32_t k = 0; k < ss.seg_count; ++k) {
                const GlSeg& seg = map_.segs[ss.first_seg + k];
                if (seg.linedef == kNoLinedef || seg.side != 0)
                    continue;
                const Linedef& line = map_.linedefs[seg.linedef];
                if (!is_exit(line.special) && !is_secret_exit(line.special))
                    continue;
                auto [it, fresh] = line_of_exit.try_emplace(seg.linedef, int32_t(zone_.zone_lines.size()));
                if (fresh) {
                    ZoneLine zl;
                    zl.target = next_map_name(map_.name, is_secret_exit(line.special));
                    const Sector& sector = sector_of(s);
                    zl.bounds.grow(glm::vec3(point(map_, line.v1), float(sector.floor_height)));
                    zl.bounds.grow(glm::vec3(point(map_, line.v2), float(sector.ceiling_height)));
                    zone_.zone_lines.push_back(zl);
                }
                zone_.regions[s].flags |= kRegionZoneLine;
                zone_.regions[s].zone_line = it->second;
            }
        }
    }

    void attach_gl_pvs()
    {
        const uint32_t n = uint32_t(map_.subsectors.size());
        if (!map_.source.gl_pvs_present) {
            zone_.source.notes.push_back("no GL_PVS lump: not vised (everything visible)");
            return;
        }
        if (map_.gl_pvs.empty()) {
            zone_.source.notes.push_back("GL_PVS is empty (glBSP's placeholder): everything visible, no PVS");
            return;
        }
        if (map_.gl_pvs.size() < glvis_lump_size(n))
            throw FileError(map_.source.gl_path, 0,
                            "GL_PVS of " + map_.name + " has " + std::to_string(map_.gl_pvs.size()) + " bytes, " +
                                std::to_string(glvis_lump_size(n)) + " needed for " + std::to_string(n) + " subsectors");
        zone_.baked_pvs = Pvs::build(n, [&](uint32_t row, std::span<uint64_t> out) {
            decode_glvis_row(map_.gl_pvs, n, row, out);
            return true;
        });
    }

    void describe()
    {
        ZoneSource& src = zone_.source;
        src.path = map_.source.wad_path;
        src.format = "Doom WAD + GL nodes";
        src.version = "GL nodes V" + std::to_string(map_.gl_version);
        src.counts.emplace_back("map." + map_.name, 1);
        src.counts.emplace_back("vertices", map_.map_vertex_count);
        src.counts.emplace_back("vertices.gl", map_.vertices.size() - map_.map_vertex_count);
        src.counts.emplace_back("linedefs", map_.linedefs.size());
        src.counts.emplace_back("sidedefs", map_.sidedefs.size());
        src.counts.emplace_back("sectors", map_.sectors.size());
        src.counts.emplace_back("segs", map_.segs.size());
        src.counts.emplace_back("subsectors", map_.subsectors.size());
        src.counts.emplace_back("nodes", map_.nodes.size());
        const std::vector<bool> moving = moving_sectors(map_);
        src.counts.emplace_back("sectors.moving", size_t(std::count(moving.begin(), moving.end(), true)));
        src.notes.insert(src.notes.begin(), "map " + map_.name + (map_.hexen ? " (Hexen format)" : "") + ", GL nodes from " +
                                                map_.source.gl_path + (map_.gl_builder.empty() ? "" : " (" + map_.gl_builder + ")"));
        src.notes.push_back("tree: GL BSP + one-sided wall segs + floors and ceilings as built (heights are static here)");
    }
};

// The WAD's maps, for `info` (a user picks one with --map).
void note_maps(Zone& zone, const WadFile& wad)
{
    const std::vector<std::string> names = map_names(wad);
    std::string list;
    for (const std::string& n : names)
        list += (list.empty() ? "" : " ") + n;
    zone.source.notes.push_back(std::to_string(names.size()) + " maps in the WAD (--map NAME): " + list);
}

} // namespace

Zone build_doom_zone(const DoomMap& map, const DoomTextures* textures) { return ZoneBuilder(map, textures).build(); }

Zone load_doom_zone(const std::string& path, const std::string& map_name, const std::string& gwa_path)
{
    const OpenedMap opened = open_doom_map(path, map_name, gwa_path);
    const DoomTextures textures(opened.wad);
    Zone zone = build_doom_zone(opened.map, &textures);
    note_maps(zone, opened.wad);
    return zone;
}

std::string next_map_name(const std::string& name, bool secret)
{
    // snprintf, not string +: GCC 12 warns (-Wrestrict) on `"E" + std::to_string(e)` inlined.
    char out[16];
    const auto episode = [&](int e, int m) { return std::snprintf(out, sizeof out, "E%dM%d", e, m), std::string(out); };
    const auto map = [&](int n) { return std::snprintf(out, sizeof out, "MAP%02d", n), std::string(out); };
    int e = 0, m = 0;
    if (std::sscanf(name.c_str(), "E%dM%d", &e, &m) == 2 && name.size() == 4) {
        static const int secret_from[5] = {0, 3, 5, 6, 2}; // E1M3, E2M5, E3M6, E4M2 lead to ExM9
        if (secret)
            return episode(e, 9);
        if (m == 9 && e >= 1 && e <= 4)
            return episode(e, secret_from[e] + 1);
        return m < 8 ? episode(e, m + 1) : std::string();
    }
    if (std::sscanf(name.c_str(), "MAP%d", &m) == 1) {
        if (secret)
            return m == 15 ? map(31) : m == 31 ? map(32) : std::string();
        if (m == 31 || m == 32)
            return map(16);
        return m < 30 ? map(m + 1) : std::string();
    }
    return {};
}

} // namespace pvs::doom
