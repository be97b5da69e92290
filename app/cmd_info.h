// `pvscope info FILE [--json]`: what a user wants to know first about a zone file.
#pragma once

#include <CLI/App.hpp>

namespace pvs::app {

// Registers the subcommand; `exit_code` receives the command's result when it runs.
void register_info_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
