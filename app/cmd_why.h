// `pvscope why FILE A B [--pvs SOURCE] [--json]`: why region A's PVS row holds region B, or why
// not (visibility/eval/pair_explanation.h): the PVS bit, a sight line found for this pair (the
// witness, with a camera that looks along it), portal-full's chain of portals from A to B with
// how far each window narrowed, and a verdict in plain words (sees, overdraw, would pop, hidden,
// unexplained). Exit 0 when explained, 2 when the file or the arguments are bad.
#pragma once

#include <CLI/App.hpp>

namespace pvs::app {

void register_why_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
