// `pvscope check FILE [--json] [--strict]`: a zone's health report (visibility/eval/zone_check.h):
// tree and portal invariants, blocked portal crossings with their positions, leaks, regions
// without faces, PVS rows, self bits, neighbours and asymmetries.
// Exit code, for scripts: 0 healthy (no failed error check; with --strict no failed warning
// either), 1 unhealthy, 2 the file could not be read.
#pragma once

#include <CLI/App.hpp>


namespace pvs {
struct ZoneHealth;
}

namespace pvs::app {

// The exit code for a report: 0 healthy, 1 when an error check failed (or, with `strict`, any
// warning check).
int check_exit_code(const ZoneHealth& health, bool strict);

void register_check_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
