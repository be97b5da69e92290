// `pvscope compare FILE [--methods LIST] [--samples N] [--seed S] [--cameras N] [--size WxH]
//  [--sky MODE] [--threads N] [--csv OUT] [--json OUT] [--chart OUT.png|OUT.svg]`: every
// visibility method on one zone in one run, against the sampled reference (ui/method_compare.h):
// time, memory, PVS size, missing and excess bits, exact popping and overdraw over seeded cameras.
// A table on stdout; CSV (columns below), JSON and the speed-vs-accuracy chart on request;
// progress on stderr; Ctrl-C cancels (nothing written, exit 130).
//
// CSV columns: method,params,bound,wall_s,cpu_s,peak_mib,estimate_mib,pvs_bytes,mean_visible,
// missing_bits,excess_bits,rows_missing_bits,popping_pixels,crack_pixels,grazing_pixels,triangle_overdraw.
// Exit codes: 0 done, 1 the file could not be read or a result written, 2 bad arguments, 130 cancelled.
#pragma once

#include "wld/zone_file.h"

#include <CLI/App.hpp>

#include <cstdint>
#include <cstdio>
#include <string>

namespace pvs::app {

struct CompareCommandOptions {
    std::string input;
    ZoneLoadOptions load; // --map, --gwa (Doom WADs)
    std::string methods;   // comma-separated registry names; empty = all
    uint64_t samples = 0;  // the reference's lines per region (0: its default)
    uint64_t seed = 1;
    size_t cameras = 200;
    std::string size = "320x240";
    std::string sky = "sky-to-sky";
    unsigned threads = 0;
    std::string csv, json, chart;
};

int run_compare_command(const CompareCommandOptions& options, std::FILE* out = stdout, std::FILE* err = stderr);

void register_compare_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
