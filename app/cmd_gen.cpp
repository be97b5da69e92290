#include "app/cmd_gen.h"

#include "app/cmd_info.h"
#include "app/progress_bar.h"
#include "visibility/file_error.h"
#include "wld/convert.h"
#include "wld/gen/generate_zone.h"
#include "wld/gen/voxel_level.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>

namespace pvs::app {

namespace {
struct GenOptions {
    gen::GenParams params = gen::demo_zone_params();
    bool json = false;
    std::string output;
};
} // namespace

void register_gen_command(CLI::App& app, int& exit_code)
{
    auto options = std::make_shared<GenOptions>();
    CLI::App* cmd = app.add_subcommand("gen", "Make a procedural indoor zone (rooms, corridors, floors, liquids, "
                                              "PvP arena, zone line) and print its report");
    cmd->add_option("--rooms", options->params.rooms, "Number of rooms")
        ->check(CLI::Range(gen::kMinRooms, gen::kMaxRooms))
        ->capture_default_str();
    cmd->add_option("--seed", options->params.seed, "Random seed: the same seed gives the same zone")
        ->capture_default_str();
    cmd->add_option("--cell", options->params.cell_size, "World units per grid cell (rooms are 3 cells high)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_flag("--no-bake{false},--bake", options->params.bake,
                  "Do not bake the PVS (by default the zone is baked with portal-full when made)");
    cmd->add_flag("--json", options->json, "Print the report as JSON");
    cmd->add_option("-o,--output", options->output, "Also write the zone (.s3d or .obj)");
    cmd->callback([options, &exit_code] {
        const auto start = std::chrono::steady_clock::now();
        gen::GenParams params = options->params;
        std::optional<ProgressBar> bar; // made on the first call: only a bake that runs shows it
        params.bake_progress = [&bar](double fraction) {
            if (!bar)
                bar.emplace(stderr, "bake");
            bar->update(fraction);
            return true;
        };
        const Zone zone = gen::generate_zone(params);
        if (bar)
            bar->finish();
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        print_zone_report(zone, ms, options->json);
        exit_code = 0;
        if (options->output.empty())
            return;
        const auto output = zone_output_for(options->output, "");
        if (!output) {
            std::fprintf(stderr, "pvscope: error: '%s': the output must end in .s3d or .obj\n", options->output.c_str());
            exit_code = 2;
            return;
        }
        try {
            for (const std::string& note : write_zone(zone, options->output, *output))
                std::fprintf(stderr, "note: %s\n", note.c_str());
        } catch (const FileError& e) {
            std::fprintf(stderr, "pvscope: error: %s\n", e.what());
            exit_code = 1;
        }
    });
}

} // namespace pvs::app
