#include "app/cmd_merge.h"

#include "app/bake_input.h"
#include "app/bake_output.h"
#include "app/bake_shard.h"
#include "app/error_path.h"
#include "app/output_files.h"
#include "app/process_memory.h"
#include "visibility/file_error.h"
#include "visibility/worker_pool.h"
#include "wld/common/read_file.h"
#include "wld/pvs_part_file.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>

namespace pvs::app {

namespace {

struct NamedPart {
    std::string file;
    PvsPart part;
};

std::string hex(uint64_t value)
{
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

// Every part against the first: one bake (settings, zone, shard count, sizes), each shard once.
void check_parts_fit(const std::vector<NamedPart>& parts)
{
    const NamedPart& first = parts.front();
    std::vector<const NamedPart*> by_shard(first.part.shards, nullptr);
    for (const NamedPart& p : parts) {
        const auto mismatch = [&](uint64_t offset, const std::string& what) {
            throw FileError(p.file, offset, "does not belong with " + first.file + ": " + what);
        };
        if (p.part.shards != first.part.shards)
            mismatch(24, "it is a shard of " + std::to_string(p.part.shards) + ", not of " +
                             std::to_string(first.part.shards));
        if (p.part.zone_hash != first.part.zone_hash)
            mismatch(12, "baked from another zone (hash " + hex(p.part.zone_hash) + ", not " +
                             hex(first.part.zone_hash) + ")");
        if (p.part.settings != first.part.settings)
            mismatch(36, "baked with other settings: " + p.part.settings + " against " + first.part.settings);
        if (p.part.row_count != first.part.row_count || p.part.region_count != first.part.region_count)
            mismatch(28, "other row or region counts");
        if (p.part.join != first.part.join)
            mismatch(36, "its rows join by another rule");
        if (const NamedPart* other = by_shard[p.part.shard])
            throw FileError(p.file, 20, "shard " + std::to_string(p.part.shard) + " twice: it is also " + other->file);
        by_shard[p.part.shard] = &p;
    }
    std::string missing;
    for (uint32_t k = 0; k < by_shard.size(); ++k)
        if (!by_shard[k])
            missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    if (!missing.empty())
        throw FileError(first.file, 20,
                        "the merge needs all " + std::to_string(first.part.shards) + " shards; missing: " + missing);
}

// The whole PVS from parts whose rows are ORed (PartRows::Union): every part holds every row.
Pvs union_rows(const std::vector<NamedPart>& parts)
{
    const PvsPart& first = parts.front().part;
    for (const NamedPart& p : parts)
        if (p.part.sources.size() != first.row_count)
            throw FileError(p.file, 0,
                            "holds " + std::to_string(p.part.sources.size()) + " of " +
                                std::to_string(first.row_count) +
                                " rows, but its rows are to be ORed with the other parts' (it must hold every row)");
    const size_t words = first.words_per_row();
    return Pvs::build_rows(first.row_count, first.region_count, [&](uint32_t r, std::span<uint64_t> out) {
        for (const NamedPart& p : parts)
            for (size_t w = 0; w < words; ++w)
                out[w] |= p.part.rows[size_t(r) * words + w];
        return true;
    });
}

// The whole PVS from the parts: every row in exactly one part.
Pvs join_rows(const std::vector<NamedPart>& parts)
{
    const PvsPart& first = parts.front().part;
    if (first.join == PartRows::Union)
        return union_rows(parts);
    struct Where {
        int32_t part = -1;
        uint32_t index = 0;
    };
    std::vector<Where> where(first.row_count);
    for (size_t p = 0; p < parts.size(); ++p)
        for (uint32_t i = 0; i < parts[p].part.sources.size(); ++i) {
            Where& w = where[parts[p].part.sources[i]];
            if (w.part >= 0)
                throw FileError(parts[p].file, 0,
                                "row " + std::to_string(parts[p].part.sources[i]) + " is also in " +
                                    parts[size_t(w.part)].file);
            w = {int32_t(p), i};
        }
    for (uint32_t r = 0; r < where.size(); ++r)
        if (where[r].part < 0)
            throw FileError(parts.front().file, 0, "row " + std::to_string(r) + " is in none of the parts");
    const size_t words = first.words_per_row();
    return Pvs::build_rows(first.row_count, first.region_count, [&](uint32_t r, std::span<uint64_t> out) {
        const PvsPart& part = parts[size_t(where[r].part)].part;
        std::copy_n(part.rows.begin() + std::ptrdiff_t(size_t(where[r].index) * words), words, out.begin());
        return true;
    });
}

int run_checked(const MergeOptions& m, std::FILE* err)
{
    const auto start = std::chrono::steady_clock::now();
    const auto seconds_since = [](std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    };
    // The parts read and unpacked on every core (zlib is most of the merge's own time).
    std::vector<NamedPart> parts(m.parts.size());
    std::atomic<bool> stop{false};
    parallel_items(
        parts.size(), 0, {}, [] { return 0.0; }, stop, [] { return 0; },
        [&](size_t i, int) {
            parts[i] = {m.parts[i], decode_pvs_part(read_whole_file(m.parts[i]), m.parts[i])};
        });
    check_parts_fit(parts);
    BakeOptions o = options_from_settings(parts.front().part.settings, parts.front().file);
    o.input = m.zone;
    o.output = m.output;
    o.apply_edits = m.apply_edits;
    if (const std::string problem = check_bake_options(o); !problem.empty())
        return bad_arguments(err, problem);
    const double parts_seconds = seconds_since(start);
    const auto load_start = std::chrono::steady_clock::now();
    const BakeInput in = load_bake_input(o, err);
    if (const std::string problem = check_output_against_input(o, in); !problem.empty())
        return bad_arguments(err, problem);
    if (const uint64_t hash = bake_zone_hash(o, in); hash != parts.front().part.zone_hash)
        throw FileError(m.zone, 0,
                        "is not the zone the parts were baked from (its hash is " + hex(hash) + ", the parts' " +
                            hex(parts.front().part.zone_hash) + ")");
    const uint32_t rows =
        in.zone.view_grid ? uint32_t(in.zone.view_grid->cell_count()) : uint32_t(in.zone.region_count());
    if (parts.front().part.row_count != rows || parts.front().part.region_count != in.zone.region_count())
        throw FileError(parts.front().file, 28,
                        "rows for a zone of " + std::to_string(parts.front().part.row_count) + " rows, but " + m.zone +
                            " has " + std::to_string(rows));
    const double load_seconds = seconds_since(load_start);
    const auto join_start = std::chrono::steady_clock::now();
    Pvs pvs = join_rows(parts);
    parts.clear(); // the rows are in `pvs` now
    parts.shrink_to_fit();
    apply_edit_list(o, pvs, err);
    const double join_seconds = seconds_since(join_start);
    const auto write_start = std::chrono::steady_clock::now();
    write_bake_output(o, in, pvs, err);
    const double write_seconds = seconds_since(write_start);
    std::fprintf(err, "merged %zu parts (%u rows, %s)\n", m.parts.size(), rows, o.method.c_str());
    if (!m.report.empty())
        write_report(m.report, {{"parts", m.parts.size()},
                                {"rows", rows},
                                {"method", o.method},
                                {"seconds", seconds_since(start)},
                                {"read_parts_seconds", parts_seconds},
                                {"load_zone_seconds", load_seconds},
                                {"join_seconds", join_seconds},
                                {"write_seconds", write_seconds},
                                {"cpu_seconds", process_cpu_seconds()},
                                {"peak_rss_bytes", peak_rss_bytes()}});
    return 0;
}

} // namespace

int run_merge(const MergeOptions& m, std::FILE* err)
{
    if (m.parts.empty())
        return bad_arguments(err, "no part files to merge");
    if (m.zone.empty())
        return bad_arguments(err, "--zone: the zone the parts were baked from is needed to write its file");
    if (m.output.empty())
        return bad_arguments(err, "no output file: give -o OUT in the zone's format");
    return run_reporting_errors(m.zone, err, [&] { return run_checked(m, err); });
}

void register_merge_command(CLI::App& app, int& exit_code)
{
    auto o = std::make_shared<MergeOptions>();
    CLI::App* cmd = app.add_subcommand(
        "merge", "Join the part files of a sharded bake (bake --shard K/N) into the zone's file, byte for byte what "
                 "the whole bake on one machine writes");
    cmd->add_option("parts", o->parts, "The part files (.pvsp), one per shard, in any order")->required();
    cmd->add_option("--zone", o->zone, "The zone file the shards baked")->required();
    cmd->add_option("-o,--output", o->output, "Output file, in the zone's format (as bake's -o)")->required();
    cmd->add_option("--report", o->report, "Write a JSON report (parts, time, CPU, peak memory); '-' for stdout");
    cmd->add_option("--apply-edits", o->apply_edits, "Apply this PVS edit list before writing, as bake's")
        ->check(CLI::ExistingFile);
    cmd->callback([o, &exit_code] { exit_code = run_merge(*o); });
}

} // namespace pvs::app
