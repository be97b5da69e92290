// Where a player starts in a map, as the game places one: the first info_player_start of a Quake
// (BSP 29, BSP2, 2PSB) or Quake 2 (IBSP 38) map, else its first info_player_deathmatch, read from
// the map's entities. The eye is the entity's origin raised by the game's view height (22 units
// in both games); the yaw is its "angle" (Quake 2 also "angles": pitch yaw roll), degrees
// counter-clockwise from +x, as the zone's cameras take it. What the inspector opens on.
//
// nullopt when the file is not such a map, has no such entity, or its entities cannot be read:
// a start is a convenience, never an error. Reads the file's header and entity lump only.
#pragma once

#include <glm/vec3.hpp>

#include <optional>
#include <span>
#include <string>

namespace pvs {

struct PlayerStart {
    glm::vec3 eye{0.0f};
    float yaw_degrees = 0.0f;
};

inline constexpr float kQuakeViewHeight = 22.0f;

// From the map's bytes (the whole file, or at least up to the end of its entity lump).
std::optional<PlayerStart> find_player_start(std::span<const uint8_t> map_bytes);
// From the file at `path`.
std::optional<PlayerStart> find_player_start(const std::string& path);

} // namespace pvs
