#include "app/cmd_convert.h"

#include "app/zone_load_args.h"
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
    if (!output) {
        std::fprintf(stderr, "pvscope: error: cannot tell the output format of '%s': use .s3d or .obj, or --to\n",
                     o.output.c_str());
        return 2;
    }
    try {
        const Zone zone = load_zone(o.input, o.load);
        for (const std::string& note : write_zone(zone, o.output, *output))
            std::printf("note: %s\n", note.c_str());
        std::printf("%s -> %s (%zu regions, %zu faces)\n", o.input.c_str(), o.output.c_str(), zone.region_count(),
                    zone.mesh.faces.size());
        return 0;
    } catch (const FileError& e) {
        std::fprintf(stderr, "pvscope: error: %s\n", e.what());
        return 1;
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "pvscope: error: %s cannot be written as %s: %s\n", o.input.c_str(), o.output.c_str(),
                     e.what());
        return 1;
    }
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
