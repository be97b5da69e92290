// CLI11 validators for the option values several subcommands share (app/arguments.h parses them),
// so every command refuses a bad --camera or --size with the same message before it runs.
#pragma once

#include "app/argument_parsers.h"
#include "visibility/methods/vis_method.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace pvs::app {

// The registry's methods that bake: the choices of every --method or --bake that bakes.
inline std::vector<std::string> baking_method_choices()
{
    std::vector<std::string> names;
    for (const VisMethod& m : vis_methods())
        if (m.bakes)
            names.emplace_back(m.name);
    return names;
}

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

// The whole text as a finite number, else nothing (CLI11's Range and NonNegativeNumber let NaN
// through, as every comparison with it is false, and take "inf").
inline std::optional<double> finite_number(const std::string& text)
{
    try {
        size_t used = 0;
        const double value = std::stod(text, &used);
        if (used == text.size() && std::isfinite(value))
            return value;
    } catch (const std::exception&) {
    }
    return std::nullopt;
}

// --fov of render, walk and the inspector: degrees in [1, 179].
inline CLI::Validator fov_validator()
{
    return CLI::Validator(
        [](std::string& text) {
            const std::optional<double> v = finite_number(text);
            return v && *v >= 1.0 && *v <= 179.0 ? std::string()
                                                 : "expects degrees from 1 to 179, got '" + text + "'";
        },
        "FLOAT in [1 - 179]");
}

// Distances (--far, --step): a finite number, 0 or more (or more than 0 when `positive`).
inline CLI::Validator distance_validator(bool positive)
{
    return CLI::Validator(
        [positive](std::string& text) {
            const std::optional<double> v = finite_number(text);
            const bool ok = v && (positive ? *v > 0.0 : *v >= 0.0);
            return ok ? std::string()
                      : std::string("expects a finite number ") + (positive ? "above 0" : "of 0 or more") + ", got '" +
                            text + "'";
        },
        positive ? "FLOAT > 0" : "FLOAT >= 0");
}

// --threads of every command: 0 (all cores) to kMaxThreads. The workers are capped again at the
// work items and four per hardware thread (visibility/worker_pool.h); a count beyond this range
// is a typo, refused before anything runs.
inline constexpr unsigned kMaxThreads = 1024;
inline CLI::Validator threads_validator() { return CLI::Range(0u, kMaxThreads); }

} // namespace pvs::app
