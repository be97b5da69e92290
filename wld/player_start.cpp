#include "wld/player_start.h"

#include "visibility/bsp_tree_edit.h"
#include "visibility/region_lookup.h"
#include "wld/doom/wad_file.h"
#include "wld/quake/bsp_layout.h"
#include "wld/quake/entities.h"
#include "wld/quake2/ibsp38_file.h"

#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <sstream>
#include <string_view>

namespace pvs {

namespace {

uint32_t read_u32(std::span<const uint8_t> bytes, size_t at)
{
    uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}

int16_t read_i16(std::span<const uint8_t> bytes, size_t at)
{
    int16_t v = 0;
    std::memcpy(&v, bytes.data() + at, 2);
    return v;
}

struct LumpRange {
    uint64_t offset = 0, length = 0;
};

// The entity lump's place: its (offset, length) pair is the first of the lump directory, after
// the 4-byte version (BSP 29) or magic (BSP2, 2PSB), or the magic and version (IBSP 38). `header`
// holds at least the file's first 16 bytes.
std::optional<LumpRange> entity_lump_range(std::span<const uint8_t> header)
{
    size_t directory = 0;
    if (quake2::looks_like_ibsp38(header))
        directory = 8;
    else if (quake::detect_bsp_variant(header))
        directory = 4;
    else
        return std::nullopt;
    if (header.size() < directory + 8)
        return std::nullopt;
    return LumpRange{read_u32(header, directory), read_u32(header, directory + 4)};
}

std::optional<std::span<const uint8_t>> entity_lump(std::span<const uint8_t> bytes)
{
    const std::optional<LumpRange> range = entity_lump_range(bytes);
    if (!range || range->offset > bytes.size() || range->length > bytes.size() - range->offset)
        return std::nullopt;
    return bytes.subspan(size_t(range->offset), size_t(range->length));
}

// `length` bytes of the file from `offset`, or nullopt when the file is shorter (checked before
// anything is allocated: a header may claim any length).
std::optional<std::vector<uint8_t>> read_range(std::ifstream& in, uint64_t offset, uint64_t length)
{
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (!in || size < 0 || offset > uint64_t(size) || length > uint64_t(size) - offset)
        return std::nullopt;
    std::vector<uint8_t> bytes(static_cast<size_t>(length));
    in.seekg(std::streamoff(offset));
    in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(length));
    if (!in || uint64_t(in.gcount()) != length)
        return std::nullopt;
    return bytes;
}

std::optional<glm::vec3> parse_vec3(std::string_view text)
{
    std::istringstream in{std::string(text)};
    glm::vec3 v;
    if (!(in >> v.x >> v.y >> v.z))
        return std::nullopt;
    return v;
}

std::optional<PlayerStart> start_of(const quake::Entity& e)
{
    const std::optional<std::string_view> origin_text = e.get("origin");
    const std::optional<glm::vec3> origin = origin_text ? parse_vec3(*origin_text) : std::nullopt;
    if (!origin)
        return std::nullopt;
    PlayerStart start;
    start.eye = *origin + glm::vec3(0.0f, 0.0f, kQuakeViewHeight);
    if (const auto angles = e.get("angles"); angles && parse_vec3(*angles))
        start.yaw_degrees = parse_vec3(*angles)->y;
    else if (const auto angle = e.get("angle"))
        start.yaw_degrees = std::strtof(std::string(*angle).c_str(), nullptr);
    return start;
}

// The first info_player_start's (else info_player_deathmatch's) start in an entity lump.
std::optional<PlayerStart> start_in_entities(std::span<const uint8_t> lump)
{
    try {
        const std::vector<quake::Entity> entities = quake::parse_entities(lump, "map", 0);
        for (const char* classname : {"info_player_start", "info_player_deathmatch"})
            for (const quake::Entity& e : entities)
                if (e.get("classname") == std::string_view(classname))
                    if (const std::optional<PlayerStart> start = start_of(e))
                        return start;
    } catch (const std::exception&) { // entities that do not parse: no start, the map still opens
    }
    return std::nullopt;
}

// The index of map `name`'s marker: the last lump of that name followed by THINGS.
std::optional<size_t> doom_map_marker(const doom::WadFile& wad, const std::string& name)
{
    for (size_t i = wad.lumps.size(); i-- > 0;)
        if (wad.lumps[i].name == name && i + 1 < wad.lumps.size() && wad.lumps[i + 1].name == "THINGS")
            return i;
    return std::nullopt;
}

// Hexen's map lumps include BEHAVIOR (its THINGS records are 20 bytes, Doom's 10).
bool hexen_map(const doom::WadFile& wad, size_t marker)
{
    for (size_t i = marker + 2; i < wad.lumps.size() && i <= marker + 12; ++i)
        if (wad.lumps[i].name == "BEHAVIOR")
            return true;
    return false;
}

// The first thing of type 1 (player 1's start) in THINGS: x, y and angle.
std::optional<PlayerStart> player_one_thing(std::span<const uint8_t> things, bool hexen)
{
    // Doom: x y angle type flags; Hexen: tid x y z angle type flags special args[5].
    const size_t size = hexen ? 20 : 10, x_at = hexen ? 2 : 0, angle_at = hexen ? 8 : 4, type_at = hexen ? 10 : 6;
    for (size_t at = 0; at + size <= things.size(); at += size) // a partial record at the end: ignored
        if (read_i16(things, at + type_at) == 1)
            return PlayerStart{{float(read_i16(things, at + x_at)), float(read_i16(things, at + x_at + 2)), 0.0f},
                               float(read_i16(things, at + angle_at))};
    return std::nullopt;
}

// The map a Doom zone was loaded from: its count "map.NAME" (doom_zone.h), else "".
std::string doom_map_of(const Zone& zone)
{
    for (const auto& [name, count] : zone.source.counts)
        if (name.starts_with("map."))
            return name.substr(4);
    return {};
}

} // namespace

std::optional<PlayerStart> find_player_start(std::span<const uint8_t> map_bytes)
{
    const std::optional<std::span<const uint8_t>> lump = entity_lump(map_bytes);
    return lump ? start_in_entities(*lump) : std::nullopt;
}

std::optional<PlayerStart> find_player_start(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::optional<std::vector<uint8_t>> header = read_range(in, 0, 16);
    const std::optional<LumpRange> range = header ? entity_lump_range(*header) : std::nullopt;
    if (!range)
        return std::nullopt;
    const std::optional<std::vector<uint8_t>> lump = read_range(in, range->offset, range->length);
    return lump ? start_in_entities(*lump) : std::nullopt;
}

std::optional<PlayerStart> find_doom_thing_start(const std::string& path, const std::string& map_name)
{
    try {
        const doom::WadFile wad = doom::read_wad(path); // mapped: only the directory and THINGS are read
        const std::optional<size_t> marker = doom_map_marker(wad, map_name);
        return marker ? player_one_thing(wad.data(*marker + 1), hexen_map(wad, *marker)) : std::nullopt;
    } catch (const std::exception&) { // a WAD that does not parse: no start
        return std::nullopt;
    }
}

std::optional<PlayerStart> find_zone_player_start(const Zone& zone)
{
    const std::string map = doom_map_of(zone);
    if (map.empty())
        return find_player_start(zone.source.path);
    std::optional<PlayerStart> start = find_doom_thing_start(zone.source.path, map);
    if (!start || !zone.tree.exists())
        return std::nullopt;
    // The floor of the subsector under the thing: its column in the tree without floors and
    // ceilings, whose region spans the floor to the ceiling.
    const PointLocation column = locate_point(without_height_nodes(zone.tree), start->eye);
    if (!column.in_region() || size_t(column.region) >= zone.region_count())
        return std::nullopt;
    start->eye.z = zone.regions[size_t(column.region)].bounds.min.z + kDoomViewHeight;
    return start;
}

} // namespace pvs
