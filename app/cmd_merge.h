// `pvscope merge PART... --zone ZONE -o OUT`: joins the part files of a sharded bake (`bake
// --shard K/N`, bake_shard.h) into the file a one-machine bake writes, byte for byte, in the
// zone's own format (every writer of `bake`: .bsp with Quake's ambient levels and Quake 2's PHS,
// .s3d, a Doom map's GL file, .hepvs). It bakes nothing: it checks that the parts belong together
// (the same settings and shard count, every shard once, the zone hash of ZONE), that every row is
// in exactly one part, and writes with the settings the parts carry. --apply-edits applies a PVS
// edit list first, as bake's does. The write is atomic like every write.
// Exit codes: 0 done, 1 a file could not be read or written or the parts do not fit (the message
// names the part and what is wrong), 2 bad arguments.
#pragma once

#include <CLI/App.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace pvs::app {

struct MergeOptions {
    std::vector<std::string> parts;
    std::string zone;
    std::string output;
    std::string report;      // JSON: parts, rows, time, CPU, peak RSS ("-": stdout)
    std::string apply_edits; // a PVS edit list applied before the write
};

int run_merge(const MergeOptions& options, std::FILE* err = stderr);

void register_merge_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
