#include "app/cmd_gen.h"

#include "app/cmd_info.h"
#include "wld/gen/generate_zone.h"
#include "wld/gen/voxel_level.h"

#include <chrono>
#include <memory>

namespace pvs::app {

namespace {
struct GenOptions {
    gen::GenParams params = gen::demo_zone_params();
    bool json = false;
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
    cmd->add_flag("--json", options->json, "Print the report as JSON");
    cmd->callback([options, &exit_code] {
        const auto start = std::chrono::steady_clock::now();
        const Zone zone = gen::generate_zone(options->params);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        print_zone_report(zone, ms, options->json);
        exit_code = 0;
    });
}

} // namespace pvs::app
