// `pvscope stats FILE|DIR... [--csv OUT] [--json OUT] [--regions-csv OUT]`: the `info` report
// for many zones at once — every zone of a folder (recursing), every map of a WAD — one row per
// zone, and with --regions-csv one row per region. A bad file is one error row, not the end of
// the batch. Progress goes to stderr, a summary table to stdout.
#pragma once

#include <CLI/App.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace pvs::app {

struct StatsOptions {
    std::vector<std::string> inputs;
    std::string csv;         // one row per zone ("-": stdout)
    std::string json;        // an array of zone reports ("-": stdout)
    std::string regions_csv; // one row per region of every zone
};

// Runs the batch; `out` gets the summary table (when no report goes to stdout), `err` the
// progress. Returns 0 when every zone loaded, 1 when some did not (their rows say why), 2 for
// bad arguments.
int run_stats(const StatsOptions& options, std::FILE* out = stdout, std::FILE* err = stderr);

void register_stats_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
