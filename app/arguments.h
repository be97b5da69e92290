// Parsers for the command-line values several subcommands share. Each returns nullopt when the
// text is not exactly what is expected, so the command can say which option is wrong.
#pragma once

#include "visibility/portal/media.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pvs::app {

// The exit codes of the commands that bake (bake, compare, stability).
inline constexpr int kExitFileError = 1;     // a file could not be read or written
inline constexpr int kExitBadArguments = 2;
inline constexpr int kExitCancelled = 130;   // 128 + SIGINT, what a shell reports for Ctrl-C

std::optional<std::array<float, 5>> parse_camera_argument(const std::string& text); // "x,y,z,yaw,pitch"
std::optional<std::array<uint32_t, 2>> parse_size_argument(const std::string& text); // "800x600", 1..8192 each
// "a,b,,c" -> {"a", "b", "c"}: a comma-separated list, empty items dropped (--methods).
std::vector<std::string> split_comma_list(const std::string& text);
// "sky-to-sky" | "all" | "none" (--sky; CLI11 checks the name) as the portal builder's mode.
SkyPortals sky_mode_from_name(const std::string& name);
// Runs a command's body; a FileError or other exception it throws is printed to `err` as
// "pvscope: error: ..." (naming `input` when the message does not) and gives kExitFileError.
int run_reporting_errors(const std::string& input, std::FILE* err, const std::function<int()>& body);
// Writes `text` to `path` (read_file.h's write_whole_file: throws FileError naming the path).
void write_text_file(const std::string& path, const std::string& text);

} // namespace pvs::app
