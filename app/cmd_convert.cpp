#include "app/cmd_convert.h"

#include "app/zone_load_args.h"
#include "app/error_path.h"
#include "visibility/file_error.h"
#include "wld/convert.h"
#include "wld/zone_file.h"

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace pvs::app {

namespace {

struct ConvertOptions {
    std::string input;
    ZoneLoadOptions load; // --map, --gwa (Doom WADs)
    std::string output;
    std::string to;
};

int run_convert(const ConvertOptions& o)
{
    const auto output = zone_output_for(o.output, o.to);
    if (!output)
        return bad_arguments(stderr, "cannot tell the output format of '" + o.output + "': use .s3d or .obj, or --to");
    return run_reporting_errors(o.input, stderr, [&] {
        const Zone zone = load_zone(o.input, o.load);
        std::vector<std::string> notes;
        try {
            notes = write_zone(zone, o.output, *output);
        } catch (const std::invalid_argument& e) {
            return file_error(stderr, o.input + " cannot be written as " + o.output + ": " + e.what());
        }
        for (const std::string& note : notes)
            std::printf("note: %s\n", note.c_str());
        std::printf("%s -> %s (%zu regions, %zu faces)\n", o.input.c_str(), o.output.c_str(), zone.region_count(),
                    zone.mesh.faces.size());
        return kExitOk;
    });
}

} // namespace

void register_convert_command(CLI::App& app, int& exit_code)
{
    auto o = std::make_shared<ConvertOptions>();
    CLI::App* cmd = app.add_subcommand("convert", "Write a zone as an EverQuest .s3d or a Wavefront .obj");
    cmd->add_option("input", o->input, "Zone file (.bsp, .s3d, .wad)")->required();
    add_zone_load_options(cmd, o->load);
    cmd->add_option("output", o->output, "Output file (.s3d or .obj)")->required();
    cmd->add_option("--to", o->to, "Output format when the extension does not say")->check(CLI::IsMember({"s3d", "obj"}));
    cmd->callback([o, &exit_code] { exit_code = run_convert(*o); });
}

} // namespace pvs::app
