// `pvscope info FILE [--json]`: what a user wants to know first about a zone file.
#pragma once

#include <CLI/App.hpp>

namespace pvs {
struct Zone;
}

namespace pvs::app {

// The report `info` prints, as text or JSON; `load_ms` is how long the zone took to make.
void print_zone_report(const Zone& zone, double load_ms, bool json);

// Registers the subcommand; `exit_code` receives the command's result when it runs.
void register_info_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
