#include "wld/player_start.h"

#include "wld/common/read_file.h"
#include "wld/quake/bsp_layout.h"
#include "wld/quake/entities.h"
#include "wld/quake2/ibsp38_file.h"

#include <cstdlib>
#include <cstring>
#include <exception>
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

// The entity lump's bytes: its (offset, length) pair is the first of the lump directory, after
// the 4-byte version (BSP 29) or magic (BSP2, 2PSB), or the magic and version (IBSP 38).
std::optional<std::span<const uint8_t>> entity_lump(std::span<const uint8_t> bytes)
{
    size_t directory = 0;
    if (quake2::looks_like_ibsp38(bytes))
        directory = 8;
    else if (quake::detect_bsp_variant(bytes))
        directory = 4;
    else
        return std::nullopt;
    if (bytes.size() < directory + 8)
        return std::nullopt;
    const uint64_t offset = read_u32(bytes, directory), length = read_u32(bytes, directory + 4);
    if (offset > bytes.size() || length > bytes.size() - offset)
        return std::nullopt;
    return bytes.subspan(size_t(offset), size_t(length));
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

} // namespace

std::optional<PlayerStart> find_player_start(std::span<const uint8_t> map_bytes)
{
    const std::optional<std::span<const uint8_t>> lump = entity_lump(map_bytes);
    if (!lump)
        return std::nullopt;
    try {
        const std::vector<quake::Entity> entities = quake::parse_entities(*lump, "map", 0);
        for (const char* classname : {"info_player_start", "info_player_deathmatch"})
            for (const quake::Entity& e : entities)
                if (e.get("classname") == std::string_view(classname))
                    if (const std::optional<PlayerStart> start = start_of(e))
                        return start;
    } catch (const std::exception&) { // entities that do not parse: no start, the map still opens
    }
    return std::nullopt;
}

std::optional<PlayerStart> find_player_start(const std::string& path)
{
    try {
        return find_player_start(read_whole_file(path));
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

} // namespace pvs
