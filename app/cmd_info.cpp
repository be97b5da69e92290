#include "app/cmd_info.h"

#include "app/zone_load_args.h"
#include "app/error_path.h"
#include "report/zone_report.h"
#include "visibility/file_error.h"
#include "visibility/zone_stats.h"
#include "wld/zone_file.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

namespace pvs::app {

namespace {

struct InfoOptions {
    std::string path;
    bool json = false;
    ZoneLoadOptions load;
};

void print_view_grid(const ViewGrid& g)
{
    std::printf("\nView grid (the camera's cell, one PVS row each)\n");
    std::printf("  %u x %u x %u = %llu cells of %g grid units (%g OBJ units), from (%g, %g, %g); grid size %g\n",
                g.counts.x, g.counts.y, g.counts.z, static_cast<unsigned long long>(g.cell_count()),
                double(g.cell_size), double(g.cell_size * g.grid_size), double(g.min.x), double(g.min.y),
                double(g.min.z), double(g.grid_size));
}

std::string human_bytes(size_t bytes)
{
    char text[32];
    if (bytes >= 1024 * 1024)
        std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / (1024.0 * 1024.0));
    else
        std::snprintf(text, sizeof text, "%.1f KiB", double(bytes) / 1024.0);
    return text;
}

void print_text(const Zone& zone, const ZoneStats& s, double load_ms)
{
    std::printf("%s\n  %s%s%s; loaded in %.1f ms; the model takes %s\n\n", zone.source.path.c_str(),
                zone.source.format.c_str(), zone.source.version.empty() ? "" : ", version ",
                zone.source.version.c_str(), load_ms, human_bytes(s.memory_bytes).c_str());
    std::printf("Counts\n");
    std::printf("  %-14s %10u   tree depth: max %u, mean %.1f\n", "nodes", s.tree.nodes, s.tree.max_depth,
                s.tree.mean_depth);
    std::printf("  %-14s %10u   (%s)\n", "regions", s.regions,
                zone.tree.exists() ? "leaves that can hold the camera" : "objects: the drawable groups");
    std::printf("  %-14s %10u\n", "solid leaves", s.tree.solid_leaves);
    if (s.tree.outside_leaves)
        std::printf("  %-14s %10u\n", "outside leaves", s.tree.outside_leaves);
    std::printf("  %-14s %10u   (%llu triangles, %u vertices)\n", "faces", s.faces,
                static_cast<unsigned long long>(s.triangles), s.vertices);
    std::printf("  %-14s %10u   (%u with pixels)\n", "materials", s.materials, s.materials_with_pixels);
    std::printf("  %-14s %10u\n", "portals", s.portals);
    std::printf("  %-14s %10u", "zone lines", s.zone_lines);
    for (const ZoneLine& line : zone.zone_lines)
        std::printf("   -> %s", line.target.empty() ? "(no target)" : line.target.c_str());
    std::printf("\n\nRegion flags\n ");
    for (uint32_t bit = 0; bit < kRegionFlagCount; ++bit)
        std::printf(" %s %u", region_flag_name(1u << bit), s.flag_counts[bit]);
    std::printf("\n\nPVS\n");
    if (!s.pvs.present)
        std::printf("  none in the file (culling falls back to the frustum)\n");
    else {
        std::printf("  %u rows (%u missing, read as all visible), %s storage, %s\n", s.pvs.rows, s.pvs.missing_rows,
                    s.pvs.dense ? "dense" : "compressed", human_bytes(s.pvs.memory_bytes).c_str());
        const double to_percent = s.regions ? 100.0 / s.regions : 0.0;
        std::printf("  visible %s: mean %.1f (%.1f %%), min %u (%.1f %%), max %u (%.1f %%)\n",
                    zone.view_grid ? "objects per cell" : "regions per region", s.pvs.mean_visible, s.pvs.mean_percent, s.pvs.min_visible, s.pvs.min_visible * to_percent,
                    s.pvs.max_visible, s.pvs.max_visible * to_percent);
    }
    if (!s.bounds.empty())
        std::printf("\nBounds\n  (%g, %g, %g) .. (%g, %g, %g)\n", s.bounds.min.x, s.bounds.min.y, s.bounds.min.z,
                    s.bounds.max.x, s.bounds.max.y, s.bounds.max.z);
    if (zone.view_grid)
        print_view_grid(*zone.view_grid);
    std::printf("\nIn the file\n ");
    for (const auto& [key, value] : zone.source.counts)
        std::printf(" %s %llu", key.c_str(), static_cast<unsigned long long>(value));
    std::printf("\n");
    for (const std::string& note : zone.source.notes)
        std::printf("  note: %s\n", note.c_str());
}

int run_info(const InfoOptions& options)
{
    return run_reporting_errors(options.path, stderr, [&] {
        const auto start = std::chrono::steady_clock::now();
        const Zone zone = load_zone(options.path, options.load);
        const double load_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        print_zone_report(zone, load_ms, options.json);
        return kExitOk;
    });
}

} // namespace

void print_zone_report(const Zone& zone, double load_ms, bool json)
{
    const ZoneStats stats = compute_zone_stats(zone);
    if (json)
        std::cout << zone_report_json(zone, stats, load_ms).dump(2) << "\n";
    else
        print_text(zone, stats, load_ms);
}

void register_info_command(CLI::App& app, int& exit_code)
{
    auto options = std::make_shared<InfoOptions>();
    CLI::App* cmd = app.add_subcommand("info", "Print what is in a zone file: counts, flags, PVS density, tree, bounds, memory");
    cmd->add_option("file", options->path, "Zone file (.bsp, .s3d, .obj, or a .hepvs with its OBJ)")->required();
    cmd->add_option("--obj", options->load.obj, "A .hepvs's OBJ level (default: the .obj of the same name beside it)");
    cmd->add_option("--hepvs", options->load.hepvs, "An OBJ's .hepvs PVS (default: the .hepvs of the same name, if any)");
    add_zone_load_options(cmd, options->load);
    cmd->add_option("--grid-size", options->load.grid_size, "OBJ units per .hepvs grid unit (the baker's -g)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_flag("--json", options->json, "Print the report as JSON (stable field names, for scripts)");
    cmd->callback([options, &exit_code] { exit_code = run_info(*options); });
}

} // namespace pvs::app
