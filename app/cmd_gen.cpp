#include "app/cmd_gen.h"

#include "app/cmd_info.h"
#include "app/error_path.h"
#include "app/progress_bar.h"
#include "wld/convert.h"
#include "gen/generate_outdoor_zone.h"
#include "gen/terrain_level.h"
#include "gen/generate_zone.h"
#include "gen/stability_cases.h"
#include "gen/voxel_level.h"

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
    std::string case_name; // a crafted stability case instead of a procedural zone
    bool outdoor = false;  // a terrain zone instead of rooms
    float size = gen::OutdoorParams{}.size;
    int height = gen::OutdoorParams{}.height;
};

// The case's boxes (= regions) and its truth, row by row, for a user checking what a method got.
void print_case(const gen::StabilityCase& c)
{
    std::printf("stability case %s: %s\n", c.name.c_str(), c.failure.c_str());
    std::printf("truth (known by construction), region: the regions it sees\n");
    for (uint32_t r = 0; r < c.region_names.size(); ++r) {
        std::printf("  %u %-8s:", r, c.region_names[r].c_str());
        for (uint32_t s = 0; s < c.region_names.size(); ++s)
            if (s != r && c.truth.visible(r, s))
                std::printf(" %s", c.region_names[s].c_str());
        std::printf("\n");
    }
    std::printf("camera: (%.3f, %.3f, %.3f) yaw %.1f pitch %.1f\n\n", double(c.camera.position.x),
                double(c.camera.position.y), double(c.camera.position.z), double(c.camera.yaw_degrees),
                double(c.camera.pitch_degrees));
}

// The zone the options ask for: a crafted case, an outdoor zone or rooms. Throws
// std::invalid_argument for sizes the generators refuse.
Zone make_zone(const GenOptions& o, const gen::GenParams& params, bool bake_asked, bool cell_given,
               std::optional<gen::StabilityCase>& crafted)
{
    if (!o.case_name.empty()) {
        crafted.emplace(gen::make_stability_case(o.case_name));
        Zone zone = std::move(crafted->zone);
        // A case is made without a PVS (stability runs every method on it); --bake asks for one.
        if (bake_asked && params.bake) {
            std::erase_if(zone.source.notes, [](const std::string& note) { return note.starts_with("no PVS"); });
            gen::bake_generated_pvs(zone, params.bake_threads, params.bake_progress, VisParams::Method::Full, true);
        }
        return zone;
    }
    if (o.outdoor) {
        gen::OutdoorParams outdoor;
        outdoor.size = o.size;
        outdoor.cell_size = cell_given ? params.cell_size : outdoor.cell_size;
        outdoor.height = o.height;
        outdoor.seed = params.seed;
        outdoor.bake = params.bake;
        outdoor.bake_progress = params.bake_progress;
        return gen::generate_outdoor_zone(outdoor);
    }
    return gen::generate_zone(params);
}

int run_gen(const GenOptions& o, bool bake_asked, bool cell_given, std::FILE* err)
{
    // The output's kind is known before the zone is made (an outdoor bake takes minutes).
    const auto output = o.output.empty() ? std::nullopt : zone_output_for(o.output, "");
    if (!o.output.empty() && !output)
        return bad_arguments(err, "'" + o.output + "': the output must end in .s3d or .obj");
    const auto start = std::chrono::steady_clock::now();
    gen::GenParams params = o.params;
    std::optional<ProgressBar> bar; // made on the first call: only a bake that runs shows it
    params.bake_progress = [&bar, err](double fraction) {
        if (!bar)
            bar.emplace(err, "bake");
        bar->update(fraction);
        return true;
    };
    std::optional<gen::StabilityCase> crafted;
    std::optional<Zone> zone;
    try {
        zone.emplace(make_zone(o, params, bake_asked, cell_given, crafted));
    } catch (const std::invalid_argument& e) {
        return bad_arguments(err, e.what());
    }
    if (bar)
        bar->finish();
    if (crafted && !o.json)
        print_case(*crafted);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    print_zone_report(*zone, ms, o.json);
    if (!output)
        return kExitOk;
    return run_reporting_errors(o.output, err, [&] {
        for (const std::string& note : write_zone(*zone, o.output, *output))
            std::fprintf(err, "note: %s\n", note.c_str());
        return kExitOk;
    });
}
} // namespace

void register_gen_command(CLI::App& app, int& exit_code)
{
    auto options = std::make_shared<GenOptions>();
    CLI::App* cmd = app.add_subcommand("gen", "Make a procedural zone - indoor (rooms, corridors, floors, liquids, "
                                              "PvP arena, zone line) or, with --outdoor, a terrain zone (hills, a "
                                              "walled town, a lake and bridge, lava, zone lines; one region per "
                                              "open cell) - and print its report");
    cmd->add_option("--rooms", options->params.rooms, "Number of rooms")
        ->check(CLI::Range(gen::kMinRooms, gen::kMaxRooms))
        ->capture_default_str();
    cmd->add_option("--seed", options->params.seed, "Random seed: the same seed gives the same zone")
        ->capture_default_str();
    CLI::Option* cell = cmd->add_option("--cell", options->params.cell_size,
                                        "World units per grid cell (rooms are 3 cells high; --outdoor: default 64)")
                            ->check(CLI::PositiveNumber)
                            ->capture_default_str();
    CLI::Option* outdoor = cmd->add_flag("--outdoor", options->outdoor,
                                         "A terrain zone as EverQuest's open zones (see --size, --height)");
    cmd->add_option("--size", options->size, "--outdoor: world units a side")
        ->check(CLI::PositiveNumber)
        ->needs(outdoor)
        ->capture_default_str();
    cmd->add_option("--height", options->height, "--outdoor: cells from the bottom of the world to the sky")
        ->check(CLI::Range(gen::kMinTerrainHeight, gen::kMaxTerrainHeight))
        ->needs(outdoor)
        ->capture_default_str();
    CLI::Option* bake = cmd->add_flag("--no-bake{false},--bake", options->params.bake,
                                      "Do not bake the PVS (by default the zone is baked with portal-full when "
                                      "made; a --case zone only with --bake)");
    cmd->add_flag("--json", options->json, "Print the report as JSON");
    std::vector<std::string> case_names(gen::stability_case_names().begin(), gen::stability_case_names().end());
    cmd->add_option("--case", options->case_name, "Instead of rooms: a crafted zone on one failure mode, with its "
                                                  "known truth (pvscope stability --cases runs every method on them)")
        ->check(CLI::IsMember(case_names))
        ->excludes(outdoor);
    cmd->add_option("-o,--output", options->output, "Also write the zone (.s3d or .obj)");
    cmd->callback([options, cell, bake, &exit_code] {
        exit_code = run_gen(*options, bake->count() > 0, cell->count() > 0, stderr);
    });
}

} // namespace pvs::app
