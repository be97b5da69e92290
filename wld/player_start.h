// Where a player starts in a map, as the game places one. What the inspector opens on.
// - Quake (BSP 29, BSP2, 2PSB) and Quake 2 (IBSP 38): the first info_player_start, else the first
//   info_player_deathmatch, read from the map's entities. The eye is the entity's origin raised by
//   the game's view height (22 units in both games); the yaw is its "angle" (Quake 2 also
//   "angles": pitch yaw roll).
// - Doom: player 1's start, the first thing of type 1 in the map's THINGS (Doom or Hexen records),
//   its eye 41 units (Doom's view height) above the floor of the subsector it stands in.
// Yaw in degrees counter-clockwise from +x, as the zone's cameras take it.
//
// nullopt when the file is not such a map, has no such entity or thing, or what holds it cannot be
// read: a start is a convenience, never an error. Reads the file's header and the one lump only.
#pragma once

#include "visibility/zone.h"

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
inline constexpr float kDoomViewHeight = 41.0f;

// From the map's bytes (the whole file, or at least up to the end of its entity lump).
std::optional<PlayerStart> find_player_start(std::span<const uint8_t> map_bytes);
// From the file at `path`.
std::optional<PlayerStart> find_player_start(const std::string& path);

// Doom: player 1's start in map `map_name` (upper case) of the WAD at `path`, as x, y and yaw; its
// eye's z is 0 (the floor is the zone's: find_zone_player_start).
std::optional<PlayerStart> find_doom_thing_start(const std::string& path, const std::string& map_name);

// A loaded zone's start: a Doom zone's (the map it names in its counts as "map.NAME"), the eye
// over the floor of the zone's region under it; else the zone's file's, as find_player_start.
std::optional<PlayerStart> find_zone_player_start(const Zone& zone);

} // namespace pvs
