// Parsers for the command-line values several subcommands share. Each returns nullopt when the
// text is not exactly what is expected, so the command can say which option is wrong.
#pragma once

#include "visibility/portal/media.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pvs::app {

std::optional<std::array<float, 5>> parse_camera_argument(const std::string& text); // "x,y,z,yaw,pitch"
std::optional<std::array<uint32_t, 2>> parse_size_argument(const std::string& text); // "800x600", 1..8192 each
// "a,b,,c" -> {"a", "b", "c"}: a comma-separated list, empty items dropped (--methods).
std::vector<std::string> split_comma_list(const std::string& text);
// "sky-to-sky" | "all" | "none" (--sky; CLI11 checks the name) as the portal builder's mode.
SkyPortals sky_mode_from_name(const std::string& name);

} // namespace pvs::app
