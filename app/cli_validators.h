// CLI11 validators for the option values several subcommands share (app/arguments.h parses them),
// so every command refuses a bad --camera or --size with the same message before it runs.
#pragma once

#include "app/arguments.h"

#include <CLI/CLI.hpp>
#include <string>

namespace pvs::app {

inline CLI::Validator camera_validator()
{
    return CLI::Validator(
        [](std::string& text) {
            return parse_camera_argument(text)
                       ? std::string()
                       : "expects x,y,z,yaw,pitch (five numbers, no spaces), got '" + text + "'";
        },
        "X,Y,Z,YAW,PITCH");
}

inline CLI::Validator size_validator()
{
    return CLI::Validator(
        [](std::string& text) {
            return parse_size_argument(text) ? std::string()
                                             : "expects WIDTHxHEIGHT with each 1..8192, e.g. 800x600, got '" + text + "'";
        },
        "WxH");
}

// --threads of every command: 0 (all cores) to kMaxThreads. The workers are capped again at the
// work items and four per hardware thread (visibility/worker_pool.h); a count beyond this range
// is a typo, refused before anything runs.
inline constexpr unsigned kMaxThreads = 1024;
inline CLI::Validator threads_validator() { return CLI::Range(0u, kMaxThreads); }

} // namespace pvs::app
