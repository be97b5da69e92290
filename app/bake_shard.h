// `bake --shard K/N` and `merge`: what a shard records so that the merge can write exactly the
// bytes a one-machine bake writes, and the checks that the parts belong together.
//
//  - The settings: the method and every bake option that changes a bit or a written byte, as JSON
//    text (the output, threads, progress and report are not among them). Every part of a merge
//    must carry the same text; the merge bakes nothing but writes with these options.
//  - The zone hash: FNV-1a 64 over the bytes of the files the bake reads: the input, a Doom map's
//    GL file when it is another file, the OBJ level's .hepvs and the portal file (--prt). A part
//    merged against another zone, or the same zone edited since, is refused.
//  - The split: a method's source_costs, dealt by shard_sources (source_shards.h).
#pragma once

#include "app/bake_input.h"
#include "app/bake_options.h"
#include "visibility/methods/source_shards.h"
#include "visibility/methods/vis_method.h"
#include "wld/pvs_part_file.h"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace pvs::app {

// "K/N" with 0 <= K < N, N >= 1; nullopt otherwise.
std::optional<ShardSpec> parse_shard_spec(const std::string& text);

// The settings text of these options (above).
std::string bake_settings_text(const BakeOptions& options);
// The options a settings text gives, with `input` and `output` set by the caller. Throws
// FileError naming `part` for text that is not such settings.
BakeOptions options_from_settings(const std::string& text, const std::string& part);

// The zone hash (above) of what `options` read into `in`.
uint64_t bake_zone_hash(const BakeOptions& options, const BakeInput& in);

// The rows of `pvs` listed in `sources`, as a part of shard `shard` (PartRows::Union: every row).
PvsPart make_pvs_part(const Pvs& pvs, std::span<const uint32_t> sources, ShardSpec shard, uint64_t zone_hash,
                      std::string settings, PartRows join);

// The process's CPU time so far (user and system), for the shards' reports.
double process_cpu_seconds();

} // namespace pvs::app
