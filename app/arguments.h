// Parsers for the command-line values several subcommands share. Each returns nullopt when the
// text is not exactly what is expected, so the command can say which option is wrong.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace pvs::app {

std::optional<std::array<float, 5>> parse_camera_argument(const std::string& text); // "x,y,z,yaw,pitch"
std::optional<std::array<uint32_t, 2>> parse_size_argument(const std::string& text); // "800x600", 1..8192 each

} // namespace pvs::app
