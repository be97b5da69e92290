#include "wld/doom/doom_map.h"

#include "wld/common/byte_reader.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>

namespace pvs::doom {

namespace {

// A lump of the WAD read through a ByteReader whose offsets are absolute in the file, so errors
// name the byte where the bad record sits.
struct LumpView {
    const WadFile& wad;
    size_t index;
    ByteReader reader;
    uint64_t base;
    uint32_t size;

    LumpView(const WadFile& w, size_t i) : wad(w), index(i), reader(w.bytes, w.path), base(w.lumps[i].offset), size(w.lumps[i].size) {}
    const std::string& name() const { return wad.lumps[index].name; }
    template <class T>
    T read(uint64_t at, const char* what) const { return reader.read<T>(base + at, what); }
    [[noreturn]] void fail(uint64_t at, const std::string& reason) const { reader.fail(base + at, name() + ": " + reason); }
    // Record count for fixed-size records after a `skip`-byte header; a ragged tail is an error.
    size_t records(size_t record_size, size_t skip = 0) const
    {
        if (size < skip || (size - skip) % record_size != 0)
            fail(0, std::to_string(size) + " bytes is not " + std::to_string(skip) + " + a multiple of " +
                        std::to_string(record_size) + "-byte records");
        return (size - skip) / record_size;
    }
};

bool is_map_marker(const WadFile& wad, size_t i)
{
    return i + 2 < wad.lumps.size() && wad.lumps[i + 1].name == "THINGS" && wad.lumps[i + 2].name == "LINEDEFS";
}

// The lump named `name` among the map's lumps (after the marker, before the next marker).
size_t map_lump(const WadFile& wad, size_t marker, const char* name, bool required)
{
    for (size_t i = marker + 1; i < wad.lumps.size() && i <= marker + 12; ++i) {
        if (i > marker + 1 && is_map_marker(wad, i))
            break;
        if (wad.lumps[i].name == name)
            return i;
    }
    if (required)
        throw FileError(wad.path, wad.lumps[marker].directory_offset,
                        "map " + wad.lumps[marker].name + " has no " + name + " lump");
    return SIZE_MAX;
}

std::string marker_text(const WadFile& wad, size_t marker)
{
    const auto data = wad.data(marker);
    return std::string(data.begin(), data.end());
}

std::string keyword(const std::string& text, const std::string& key)
{
    const size_t at = text.find(key + "=");
    if (at == std::string::npos)
        return {};
    const size_t begin = at + key.size() + 1;
    size_t end = text.find_first_of("\r\n", begin);
    return text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

// The GL marker of map `name` in `wad`: GL_<name>, or GL_LEVEL with LEVEL=<name>.
std::optional<size_t> find_gl_marker(const WadFile& wad, const std::string& name)
{
    if (name.size() <= 5)
        if (auto i = wad.find_last("GL_" + name))
            return i;
    for (size_t i = wad.lumps.size(); i-- > 0;)
        if (wad.lumps[i].name == "GL_LEVEL" && upper_case(keyword(marker_text(wad, i), "LEVEL")) == name)
            return i;
    return std::nullopt;
}

void read_vertexes(const WadFile& wad, size_t lump, DoomMap& map)
{
    const LumpView v(wad, lump);
    const size_t n = v.records(4);
    for (size_t i = 0; i < n; ++i)
        map.vertices.push_back({double(v.read<int16_t>(i * 4, "vertex x")), double(v.read<int16_t>(i * 4 + 2, "vertex y"))});
    map.map_vertex_count = uint32_t(n);
}

int32_t side_index(uint16_t raw) { return raw == 0xFFFF ? -1 : int32_t(raw); }

void read_linedefs(const WadFile& wad, size_t lump, DoomMap& map)
{
    const LumpView v(wad, lump);
    const size_t size = map.hexen ? 16 : 14;
    const size_t n = v.records(size);
    map.linedefs.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const uint64_t at = i * size;
        Linedef& l = map.linedefs[i];
        l.v1 = v.read<uint16_t>(at, "linedef v1");
        l.v2 = v.read<uint16_t>(at + 2, "linedef v2");
        l.flags = v.read<uint16_t>(at + 4, "linedef flags");
        if (map.hexen) {
            l.special = v.read<uint8_t>(at + 6, "linedef special");
            l.side[0] = side_index(v.read<uint16_t>(at + 12, "linedef front side"));
            l.side[1] = side_index(v.read<uint16_t>(at + 14, "linedef back side"));
        } else {
            l.special = v.read<uint16_t>(at + 6, "linedef special");
            l.tag = v.read<int16_t>(at + 8, "linedef tag");
            l.side[0] = side_index(v.read<uint16_t>(at + 10, "linedef front side"));
            l.side[1] = side_index(v.read<uint16_t>(at + 12, "linedef back side"));
        }
    }
}

void read_sidedefs(const WadFile& wad, size_t lump, DoomMap& map)
{
    const LumpView v(wad, lump);
    const size_t n = v.records(30);
    map.sidedefs.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const uint64_t at = i * 30;
        Sidedef& s = map.sidedefs[i];
        s.x_offset = v.read<int16_t>(at, "sidedef x offset");
        s.y_offset = v.read<int16_t>(at + 2, "sidedef y offset");
        s.upper = wad_name(v.reader.bytes(v.base + at + 4, 8, "sidedef upper texture"));
        s.lower = wad_name(v.reader.bytes(v.base + at + 12, 8, "sidedef lower texture"));
        s.middle = wad_name(v.reader.bytes(v.base + at + 20, 8, "sidedef middle texture"));
        s.sector = v.read<uint16_t>(at + 28, "sidedef sector");
    }
}

void read_sectors(const WadFile& wad, size_t lump, DoomMap& map)
{
    const LumpView v(wad, lump);
    const size_t n = v.records(26);
    map.sectors.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const uint64_t at = i * 26;
        Sector& s = map.sectors[i];
        s.floor_height = v.read<int16_t>(at, "sector floor");
        s.ceiling_height = v.read<int16_t>(at + 2, "sector ceiling");
        s.floor_flat = wad_name(v.reader.bytes(v.base + at + 4, 8, "sector floor flat"));
        s.ceiling_flat = wad_name(v.reader.bytes(v.base + at + 12, 8, "sector ceiling flat"));
        s.light = v.read<int16_t>(at + 20, "sector light");
        s.special = v.read<int16_t>(at + 22, "sector special");
        s.tag = v.read<int16_t>(at + 24, "sector tag");
    }
}

bool starts_with_magic(const LumpView& v, const char* magic)
{
    return v.size >= 4 && std::memcmp(v.wad.bytes.data() + v.base, magic, 4) == 0;
}

void read_gl_vertices(const WadFile& wad, size_t lump, DoomMap& map)
{
    const LumpView v(wad, lump);
    if (starts_with_magic(v, "gNd5"))
        map.gl_version = 5;
    else if (starts_with_magic(v, "gNd2") || starts_with_magic(v, "gNd3"))
        map.gl_version = 2; // V3 is told by GL_SEGS' magic
    else if (starts_with_magic(v, "gNd4"))
        v.fail(0, "GL nodes V4 are not supported (V1, V2, V3 and V5 are: rebuild with glbsp or zdbsp)");
    else
        map.gl_version = 1;
    if (map.gl_version == 1) {
        const size_t n = v.records(4);
        for (size_t i = 0; i < n; ++i)
            map.vertices.push_back({double(v.read<int16_t>(i * 4, "GL vertex x")), double(v.read<int16_t>(i * 4 + 2, "GL vertex y"))});
        return;
    }
    const size_t n = v.records(8, 4);
    for (size_t i = 0; i < n; ++i)
        map.vertices.push_back({v.read<int32_t>(4 + i * 8, "GL vertex x") / 65536.0, v.read<int32_t>(8 + i * 8, "GL vertex y") / 65536.0});
}

// A seg vertex index: the flag bit selects GL_VERT, else VERTEXES.
uint32_t seg_vertex(const LumpView& v, const DoomMap& map, uint64_t at, uint32_t raw, uint32_t flag)
{
    const uint32_t gl_count = uint32_t(map.vertices.size()) - map.map_vertex_count;
    if (raw & flag) {
        const uint32_t index = raw & ~flag;
        if (index >= gl_count)
            v.fail(at, "seg GL vertex " + std::to_string(index) + " out of range (" + std::to_string(gl_count) + " in GL_VERT)");
        return map.map_vertex_count + index;
    }
    if (raw >= map.map_vertex_count)
        v.fail(at, "seg vertex " + std::to_string(raw) + " out of range (" + std::to_string(map.map_vertex_count) + " in VERTEXES)");
    return raw;
}

void read_gl_segs(const WadFile& wad, size_t lump, size_t seg_total, DoomMap& map)
{
    const LumpView v(wad, lump);
    if (starts_with_magic(v, "gNd3")) {
        if (map.gl_version != 2)
            v.fail(0, "GL_SEGS says V3 but GL_VERT says V" + std::to_string(map.gl_version));
        map.gl_version = 3;
    }
    const bool wide = map.gl_version >= 3;
    const size_t skip = map.gl_version == 3 ? 4 : 0;
    // V5 segs are 16 bytes as glBSP writes them (§4.3); zdbsp 1.19 writes 20 (a u32 linedef,
    // the side, then the partner at +16: seen on Freedoom). The segs the subsectors use tell which.
    const bool zdbsp_v5 = map.gl_version == 5 && seg_total > 0 && v.size == 20 * seg_total;
    const size_t size = zdbsp_v5 ? 20 : wide ? 16 : 10;
    const size_t partner_at = zdbsp_v5 ? 16 : 12;
    const uint32_t flag = map.gl_version == 5 ? 0x80000000u : map.gl_version == 3 ? 0x40000000u : 0x8000u;
    const size_t n = v.records(size, skip);
    map.segs.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const uint64_t at = skip + i * size;
        GlSeg& s = map.segs[i];
        const uint32_t raw1 = wide ? v.read<uint32_t>(at, "seg start") : v.read<uint16_t>(at, "seg start");
        const uint32_t raw2 = wide ? v.read<uint32_t>(at + 4, "seg end") : v.read<uint16_t>(at + 2, "seg end");
        s.v1 = seg_vertex(v, map, at, raw1, flag);
        s.v2 = seg_vertex(v, map, at, raw2, flag);
        const uint32_t raw_line = zdbsp_v5 ? v.read<uint32_t>(at + 8, "seg linedef") : v.read<uint16_t>(at + (wide ? 8 : 4), "seg linedef");
        const uint32_t line = zdbsp_v5 || raw_line != 0xFFFF ? raw_line : kNoLinedef;
        const uint16_t side = v.read<uint16_t>(at + (zdbsp_v5 ? 12 : wide ? 10 : 6), "seg side");
        const uint32_t partner = wide ? v.read<uint32_t>(at + partner_at, "seg partner") : v.read<uint16_t>(at + 8, "seg partner");
        s.side = uint8_t(side & 1);
        if (line != kNoLinedef) {
            if (line >= map.linedefs.size())
                v.fail(at, "seg " + std::to_string(i) + " linedef " + std::to_string(line) + " out of range (" +
                               std::to_string(map.linedefs.size()) + " linedefs)");
            if (map.linedefs[line].side[s.side] < 0)
                v.fail(at, "seg " + std::to_string(i) + " lies on side " + std::to_string(s.side) + " of linedef " +
                               std::to_string(line) + ", which has no sidedef there");
            s.linedef = line;
        }
        const bool none = wide ? partner == 0xFFFFFFFFu : partner == 0xFFFFu;
        if (!none) {
            if (partner >= n)
                v.fail(at, "seg " + std::to_string(i) + " partner " + std::to_string(partner) + " out of range (" +
                               std::to_string(n) + " segs)");
            s.partner = partner;
        }
    }
}

void read_gl_subsectors(const WadFile& wad, size_t lump, DoomMap& map)
{
    const LumpView v(wad, lump);
    const bool wide = map.gl_version >= 3;
    const size_t skip = map.gl_version == 3 && starts_with_magic(v, "gNd3") ? 4 : 0;
    const size_t size = wide ? 8 : 4;
    const size_t n = v.records(size, skip);
    if (n == 0)
        v.fail(0, "no subsectors");
    map.subsectors.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const uint64_t at = skip + i * size;
        GlSubsector& s = map.subsectors[i];
        s.seg_count = wide ? v.read<uint32_t>(at, "subsector seg count") : v.read<uint16_t>(at, "subsector seg count");
        s.first_seg = wide ? v.read<uint32_t>(at + 4, "subsector first seg") : v.read<uint16_t>(at + 2, "subsector first seg");
        // Fewer than three segs is a degenerate sliver (zdbsp writes some on Freedoom): kept, with no area.
        if (s.seg_count == 0 || uint64_t(s.first_seg) + s.seg_count > map.segs.size())
            v.fail(at, "subsector " + std::to_string(i) + " segs " + std::to_string(s.first_seg) + " + " +
                           std::to_string(s.seg_count) + " are not a range inside the " +
                           std::to_string(map.segs.size()) + " segs");
        bool found = false;
        for (uint32_t k = 0; k < s.seg_count && !found; ++k) {
            const GlSeg& seg = map.segs[s.first_seg + k];
            if (seg.linedef != kNoLinedef) {
                s.sector = map.sidedefs[size_t(map.linedefs[seg.linedef].side[seg.side])].sector;
                found = true;
            }
        }
        if (!found)
            v.fail(at, "subsector " + std::to_string(i) + " has only minisegs: it has no sector (glVIS and Vavoom refuse it too)");
    }
}

// The number of segs the subsectors use (the largest first + count; 8-byte V5 records), which
// tells the V5 seg record size; 0 for other versions or a ragged lump (read_gl_subsectors reports it).
size_t segs_used(const WadFile& wad, size_t lump, const DoomMap& map)
{
    const LumpView v(wad, lump);
    if (map.gl_version != 5 || v.size % 8 != 0)
        return 0;
    size_t used = 0;
    for (size_t at = 0; at < v.size; at += 8)
        used = std::max<size_t>(used, size_t(v.read<uint32_t>(at, "subsector seg count")) + v.read<uint32_t>(at + 4, "subsector first seg"));
    return used;
}

void read_gl_nodes(const WadFile& wad, size_t lump, DoomMap& map)
{
    const LumpView v(wad, lump);
    const bool v5 = map.gl_version == 5;
    const size_t size = v5 ? 32 : 28;
    // zdbsp 1.19's V5 GL_NODES is 40 bytes per node long but holds 32-byte nodes followed by
    // zeros (seen on Freedoom). A binary tree has one node fewer than leaves: when the lump is
    // 40 bytes per expected node, that is the layout.
    const size_t expected = map.subsectors.size() - 1;
    const bool zdbsp_v5 = v5 && v.size == 40 * expected && expected > 0;
    const size_t n = zdbsp_v5 ? expected : v.records(size);
    const uint32_t leaf_flag = v5 ? 0x80000000u : 0x8000u;
    map.nodes.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const uint64_t at = i * size;
        GlNode& node = map.nodes[i];
        node.x = v.read<int16_t>(at, "node x");
        node.y = v.read<int16_t>(at + 2, "node y");
        node.dx = v.read<int16_t>(at + 4, "node dx");
        node.dy = v.read<int16_t>(at + 6, "node dy");
        if (node.dx == 0 && node.dy == 0)
            v.fail(at, "node " + std::to_string(i) + " has a zero-length partition line");
        for (int c = 0; c < 2; ++c) {
            const uint32_t raw = v5 ? v.read<uint32_t>(at + 24 + 4 * c, "node child") : v.read<uint16_t>(at + 24 + 2 * c, "node child");
            if (raw & leaf_flag) {
                const uint32_t ss = raw & ~leaf_flag;
                if (ss >= map.subsectors.size())
                    v.fail(at, "node " + std::to_string(i) + " child subsector " + std::to_string(ss) + " out of range (" +
                                   std::to_string(map.subsectors.size()) + " subsectors)");
                node.children[c] = ~int32_t(ss);
            } else {
                // Children come before their parent (the root is the last node): that also rules out cycles.
                if (raw >= i)
                    v.fail(at, "node " + std::to_string(i) + " child node " + std::to_string(raw) +
                                   " is not an earlier node (the tree would not be a tree)");
                node.children[c] = int32_t(raw);
            }
        }
    }
}

void check_map_indices(const WadFile& wad, size_t linedef_lump, size_t sidedef_lump, const DoomMap& map)
{
    const LumpView lines(wad, linedef_lump);
    const size_t line_size = map.hexen ? 16 : 14;
    for (size_t i = 0; i < map.linedefs.size(); ++i) {
        const Linedef& l = map.linedefs[i];
        if (l.v1 >= map.map_vertex_count || l.v2 >= map.map_vertex_count)
            lines.fail(i * line_size, "linedef " + std::to_string(i) + " vertex out of range (" +
                                          std::to_string(map.map_vertex_count) + " vertices)");
        for (int s = 0; s < 2; ++s)
            if (l.side[s] >= int32_t(map.sidedefs.size()))
                lines.fail(i * line_size, "linedef " + std::to_string(i) + " sidedef " + std::to_string(l.side[s]) +
                                              " out of range (" + std::to_string(map.sidedefs.size()) + " sidedefs)");
    }
    const LumpView sides(wad, sidedef_lump);
    for (size_t i = 0; i < map.sidedefs.size(); ++i)
        if (map.sidedefs[i].sector >= map.sectors.size())
            sides.fail(i * 30 + 28, "sidedef " + std::to_string(i) + " sector " + std::to_string(map.sidedefs[i].sector) +
                                        " out of range (" + std::to_string(map.sectors.size()) + " sectors)");
}

// The GL lumps in the order glBSP writes them after the marker.
size_t gl_lump(const WadFile& file, size_t marker, size_t offset, const char* name)
{
    const size_t i = marker + offset;
    if (i >= file.lumps.size() || file.lumps[i].name != name)
        throw FileError(file.path, file.lumps[marker].directory_offset,
                        "GL group " + file.lumps[marker].name + ": no " + name + " at marker + " + std::to_string(offset) +
                            " (found " + (i < file.lumps.size() ? "'" + file.lumps[i].name + "'" : "the end of the directory") +
                            "; glBSP writes GL_VERT, GL_SEGS, GL_SSECT, GL_NODES in this order)");
    return i;
}

void read_gl_group(const WadFile& file, size_t marker, DoomMap& map)
{
    map.source.gl_path = file.path;
    map.source.gl_marker = marker;
    map.gl_builder = keyword(marker_text(file, marker), "BUILDER");
    const size_t vert = gl_lump(file, marker, 1, "GL_VERT"), segs = gl_lump(file, marker, 2, "GL_SEGS"),
                 ssect = gl_lump(file, marker, 3, "GL_SSECT"), nodes = gl_lump(file, marker, 4, "GL_NODES");
    read_gl_vertices(file, vert, map);
    read_gl_segs(file, segs, segs_used(file, ssect, map), map);
    read_gl_subsectors(file, ssect, map);
    read_gl_nodes(file, nodes, map);
    const size_t pvs = marker + 5;
    if (pvs < file.lumps.size() && file.lumps[pvs].name == "GL_PVS") {
        map.source.gl_pvs_present = true;
        const auto data = file.data(pvs);
        map.gl_pvs.assign(data.begin(), data.end());
    }
}

} // namespace

std::vector<std::string> map_names(const WadFile& wad)
{
    std::vector<std::string> names;
    for (size_t i = 0; i < wad.lumps.size(); ++i)
        if (is_map_marker(wad, i))
            names.push_back(wad.lumps[i].name);
    return names;
}

std::string gwa_path_for(const std::string& wad_path)
{
    return std::filesystem::path(wad_path).replace_extension(".gwa").string();
}

DoomMap read_doom_map(const WadFile& wad, const WadFile* gwa, const std::string& name)
{
    const std::vector<std::string> names = map_names(wad);
    if (names.empty())
        throw FileError(wad.path, 0, "no map in this WAD (no marker lump followed by THINGS and LINEDEFS)");
    DoomMap map;
    map.name = name.empty() ? names.front() : upper_case(name);
    std::optional<size_t> marker;
    for (size_t i = wad.lumps.size(); i-- > 0;)
        if (wad.lumps[i].name == map.name && is_map_marker(wad, i)) {
            marker = i;
            break;
        }
    if (!marker) {
        std::string list;
        for (const std::string& n : names)
            list += (list.empty() ? "" : " ") + n;
        throw FileError(wad.path, 0, "no map " + map.name + " in this WAD (it has: " + list + ")");
    }
    map.source.wad_path = wad.path;
    map.source.map_marker = *marker;
    map.hexen = map_lump(wad, *marker, "BEHAVIOR", false) != SIZE_MAX;
    const size_t linedefs = map_lump(wad, *marker, "LINEDEFS", true);
    const size_t sidedefs = map_lump(wad, *marker, "SIDEDEFS", true);
    read_vertexes(wad, map_lump(wad, *marker, "VERTEXES", true), map);
    read_linedefs(wad, linedefs, map);
    read_sidedefs(wad, sidedefs, map);
    read_sectors(wad, map_lump(wad, *marker, "SECTORS", true), map);
    check_map_indices(wad, linedefs, sidedefs, map);
    if (const size_t reject = map_lump(wad, *marker, "REJECT", false); reject != SIZE_MAX) {
        const auto data = wad.data(reject);
        map.reject.assign(data.begin(), data.end());
    }

    std::optional<size_t> gl_marker = gwa ? find_gl_marker(*gwa, map.name) : std::nullopt;
    const WadFile* gl_file = gl_marker ? gwa : &wad;
    if (!gl_marker)
        gl_marker = find_gl_marker(wad, map.name);
    if (!gl_marker)
        throw FileError(wad.path, wad.lumps[*marker].directory_offset,
                        "map " + map.name + " has no GL nodes (no GL_" + map.name + " lump" +
                            (gwa ? " here or in " + gwa->path : std::string(" and no .gwa beside it")) +
                            "): build them with `glbsp " + wad.path + "` or `zdbsp -g`");
    read_gl_group(*gl_file, *gl_marker, map);
    return map;
}

OpenedMap open_doom_map(const std::string& path, const std::string& name, const std::string& gwa_path)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    OpenedMap out;
    if (upper_case(fs::path(path).extension().string()) == ".GWA") {
        const std::string wad_path = fs::path(path).replace_extension(".wad").string();
        if (!fs::exists(wad_path, ec))
            throw FileError(path, 0, "a .gwa holds only GL nodes: its map lumps are in " + wad_path + ", which is missing");
        out.wad = read_wad(wad_path);
        out.gwa = read_wad(path);
    } else {
        out.wad = read_wad(path);
        const std::string beside = gwa_path.empty() ? gwa_path_for(path) : gwa_path;
        if (!gwa_path.empty() || (beside != path && fs::exists(beside, ec)))
            out.gwa = read_wad(beside);
    }
    out.map = read_doom_map(out.wad, out.gwa ? &*out.gwa : nullptr, name);
    return out;
}

uint32_t locate_subsector(const DoomMap& map, double x, double y)
{
    if (map.nodes.empty())
        return 0;
    int32_t child = int32_t(map.nodes.size() - 1);
    while (child >= 0) {
        const GlNode& node = map.nodes[size_t(child)];
        const double c = (x - node.x) * node.dy - (y - node.y) * node.dx;
        child = node.children[c > 0 ? 0 : 1];
    }
    return uint32_t(~child);
}

} // namespace pvs::doom
