#include "app/cmd_stats.h"
#include "app/error_path.h"

#include "report/json_csv.h"
#include "report/region_report.h"
#include "report/zone_batch.h"
#include "report/zone_report.h"
#include "visibility/file_error.h"
#include "visibility/zone_stats.h"
#include "wld/common/read_file.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <memory>

namespace pvs::app {

namespace {

// The zone's report with where it came from; an error row names the file, the map and why.
nlohmann::json zone_row(const BatchItem& item, const LoadedZone& loaded, const ZoneStats* stats)
{
    nlohmann::json row;
    if (loaded.zone)
        row = zone_report_json(*loaded.zone, *stats, loaded.load_ms);
    row["file"] = item.path;
    row["map"] = item.map;
    row["status"] = loaded.zone ? "ok" : "error";
    row["error"] = loaded.error;
    return row;
}

// Where the row came from and whether it loaded first, then the report's columns.
CsvFields zone_csv_fields(const nlohmann::json& row)
{
    CsvFields fields = {{"file", csv_cell(row["file"].get<std::string>())},
                        {"map", csv_cell(row["map"].get<std::string>())},
                        {"status", csv_cell(row["status"].get<std::string>())},
                        {"error", csv_cell(row["error"].get<std::string>())}};
    nlohmann::json rest = row;
    for (const char* key : {"file", "map", "status", "error"})
        rest.erase(key);
    flatten_json(rest, "", fields);
    return fields;
}

CsvFields region_row_fields(const BatchItem& item, const Zone& zone, const RegionRow& row)
{
    CsvFields fields = {{"file", csv_cell(item.path)}, {"map", csv_cell(item.map)}};
    for (auto& field : region_fields(zone, row))
        fields.push_back(std::move(field));
    return fields;
}

void write_text(const std::string& path, const std::string& text, std::FILE* out)
{
    if (path == "-")
        std::fputs(text.c_str(), out);
    else
        write_whole_file(path, std::vector<uint8_t>(text.begin(), text.end()));
}

void print_summary(const std::vector<nlohmann::json>& rows, std::FILE* out)
{
    std::fprintf(out, "%-40s %-6s %8s %8s %7s %6s %9s %8s  %s\n", "file", "map", "regions", "faces", "pvs %",
                 "depth", "memory", "load ms", "status");
    for (const nlohmann::json& r : rows) {
        std::string file = r["file"].get<std::string>();
        if (file.size() > 40)
            file = "..." + file.substr(file.size() - 37);
        if (r["status"] != "ok") {
            std::fprintf(out, "%-40s %-6s %8s %8s %7s %6s %9s %8s  error: %s\n", file.c_str(),
                         r["map"].get<std::string>().c_str(), "", "", "", "", "", "", r["error"].get<std::string>().c_str());
            continue;
        }
        const nlohmann::json& pvs = r["pvs"];
        const std::string percent = pvs["present"].get<bool>() ? std::to_string(pvs["mean_visible_percent"].get<double>()).substr(0, 5) : "-";
        std::fprintf(out, "%-40s %-6s %8u %8u %7s %6u %8.1fM %8.1f  ok\n", file.c_str(), r["map"].get<std::string>().c_str(),
                     r["counts"]["regions"].get<uint32_t>(), r["counts"]["faces"].get<uint32_t>(), percent.c_str(),
                     r["tree"]["max_depth"].get<uint32_t>(), double(r["memory_bytes"].get<size_t>()) / 1048576.0,
                     r["load_ms"].get<double>());
    }
}

} // namespace

int run_stats(const StatsOptions& o, std::FILE* out, std::FILE* err)
{
    if (o.inputs.empty()) {
        return bad_arguments(err, "stats needs at least one file or folder");
    }
    const std::vector<BatchItem> items = batch_items(o.inputs);
    std::vector<nlohmann::json> rows;
    std::vector<CsvFields> zone_fields, region_fields_all;
    size_t failed = 0;
    for (size_t i = 0; i < items.size(); ++i) {
        const BatchItem& item = items[i];
        std::fprintf(err, "stats: [%zu/%zu] %s%s%s\n", i + 1, items.size(), item.path.c_str(),
                     item.map.empty() ? "" : " ", item.map.c_str());
        const LoadedZone loaded = load_batch_item(item);
        std::optional<ZoneStats> stats;
        if (loaded.zone)
            stats = compute_zone_stats(*loaded.zone);
        else
            ++failed;
        rows.push_back(zone_row(item, loaded, stats ? &*stats : nullptr));
        zone_fields.push_back(zone_csv_fields(rows.back()));
        if (!o.regions_csv.empty() && loaded.zone)
            for (const RegionRow& row : region_rows(*loaded.zone))
                region_fields_all.push_back(region_row_fields(item, *loaded.zone, row));
    }
    const int written = run_reporting_errors("stats", err, [&] {
        if (!o.csv.empty())
            write_text(o.csv, csv_table(zone_fields), out);
        if (!o.json.empty())
            write_text(o.json, nlohmann::json(rows).dump(2) + "\n", out);
        if (!o.regions_csv.empty())
            write_text(o.regions_csv, csv_table(region_fields_all), out);
        return kExitOk;
    });
    if (written != kExitOk)
        return written;
    if (o.csv != "-" && o.json != "-" && o.regions_csv != "-")
        print_summary(rows, out);
    std::fprintf(err, "stats: %zu zones, %zu loaded, %zu failed\n", items.size(), items.size() - failed, failed);
    return failed ? 1 : 0;
}

void register_stats_command(CLI::App& app, int& exit_code)
{
    auto o = std::make_shared<StatsOptions>();
    CLI::App* cmd = app.add_subcommand("stats", "The info report for many zones: files, folders (recursed: .bsp, .s3d, .wad, "
                                                ".obj) and every map of a WAD; one row per zone, a bad file is an error row");
    cmd->add_option("inputs", o->inputs, "Zone files and folders")->required();
    cmd->add_option("--csv", o->csv, "One row per zone: every scalar of `info --json` as a column ('-': stdout)");
    cmd->add_option("--json", o->json, "An array of `info --json` reports, with file, map, status and error ('-': stdout)");
    cmd->add_option("--regions-csv", o->regions_csv, "One row per region: flags, bounds, faces, triangles, visible, "
                                                      "visible_from, portal_neighbours ('-': stdout)");
    cmd->callback([o, &exit_code] { exit_code = run_stats(*o); });
}

} // namespace pvs::app
