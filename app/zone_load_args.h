// Command-line options every command that opens a zone file shares: which map of a Doom WAD
// (`--map MAP10`), and its GL nodes when they are not beside it (`--gwa FILE`).
#pragma once

#include "wld/zone_file.h"

#include <CLI/CLI.hpp>

namespace pvs::app {

inline void add_zone_load_options(CLI::App* cmd, ZoneLoadOptions& load)
{
    cmd->add_option("--map", load.map, "Doom WAD: the map to open (E1M1, MAP10; default: the first; `info` lists them)");
    cmd->add_option("--gwa", load.gwa, "Doom WAD: its GL nodes (default: the .gwa beside it, else the WAD's own)")
        ->check(CLI::ExistingFile);
}

} // namespace pvs::app
