// `pvscope stability FILE [--methods LIST] [--samples N] [--sky MODE] [--threads N] [--json OUT]
//  [--csv OUT]`: each method baked on the zone as given and under transforms that change nothing
// a player could see (translations by 2^k, quarter turns, mirror, a 1e-3 jitter), compared row for
// row with itself and against the reference of the untransformed zone (visibility/eval/stability.h).
// A table on stdout, JSON entries {method, params, transform, exact, changed_bits, gained_bits,
// lost_bits, changed_rows, missing_bits, seconds}, the same as CSV; progress on stderr; Ctrl-C
// cancels (exit 130). Exit codes: 0 done, 1 the file could not be read or a result written,
// 2 bad arguments, 130 cancelled.
//
// `pvscope stability --cases all|NAME,... [--methods] [--samples] [--json] [--csv]`: instead of a
// file, each method on each crafted case (wld/gen/stability_cases.h, wld/gen/case_table.h):
// missing and excess bits against the case's known truth, entries {case, method, params, bound,
// regions, truth_bits, bits, missing_bits, excess_bits, broken, seconds}. `broken` marks an
// upper bound that misses a bit or a lower bound with an excess one; the exit code stays 0.
#pragma once

#include "wld/zone_file.h"

#include <CLI/App.hpp>

#include <cstdint>
#include <cstdio>
#include <string>

namespace pvs::app {

struct StabilityCommandOptions {
    std::string input;
    ZoneLoadOptions load; // --map, --gwa (Doom WADs)
    std::string cases; // "all" or comma-separated case names; instead of input
    // Empty: the mode's own list (a file: portal-fast, portal-full, clustered, reference; --cases:
    // those and raster, which is quick on the small crafted zones).
    std::string methods;
    uint64_t samples = 256; // the reference's lines per region
    std::string sky = "sky-to-sky";
    unsigned threads = 0;
    std::string json, csv;
};

int run_stability_command(const StabilityCommandOptions& options, std::FILE* out = stdout, std::FILE* err = stderr);

void register_stability_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
