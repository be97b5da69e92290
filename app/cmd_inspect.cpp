#include "app/cmd_inspect.h"

#include "app/arguments.h"
#include "ui/gui/inspector_app.h"

#include <memory>

namespace pvs::app {

namespace {

struct InspectOptions {
    std::string path;
    std::string screenshot;
    int frames = 5;
    std::string size = "1280x800";
    std::string camera;
    std::string cull = "pvs+frustum";
};

} // namespace

int run_inspect(const std::string& path)
{
    gui::InspectorOptions options;
    options.zone_path = path;
    return gui::run_inspector(options);
}

void register_inspect_command(CLI::App& app, int& exit_code)
{
    auto o = std::make_shared<InspectOptions>();
    CLI::App* cmd = app.add_subcommand("inspect", "Open the inspector window (the default when no subcommand is given)");
    cmd->add_option("file", o->path, "Zone file; the built-in demo zone when absent");
    cmd->add_option("--screenshot", o->screenshot,
                    "Draw --frames frames, write the whole window to this PNG and exit (needs a display; "
                    "xvfb-run works)");
    cmd->add_option("--frames", o->frames, "Frames drawn before the screenshot")
        ->capture_default_str()
        ->check(CLI::Range(1, 100000));
    cmd->add_option("--size", o->size, "Window size WIDTHxHEIGHT")
        ->capture_default_str()
        ->check(CLI::Validator(
            [](std::string& text) {
                return parse_size_argument(text)
                           ? std::string()
                           : "expects WIDTHxHEIGHT with each 1..8192, e.g. 1280x800, got '" + text + "'";
            },
            "WxH"));
    cmd->add_option("--camera", o->camera, "Start camera x,y,z,yaw,pitch (zone units, degrees; z up, yaw 0 = +x); "
                                           "default: a view down the longest open line from a large region")
        ->check(CLI::Validator(
            [](std::string& text) {
                return parse_camera_argument(text) ? std::string()
                                                   : "expects x,y,z,yaw,pitch (five numbers, no spaces), got '" +
                                                         text + "'";
            },
            "X,Y,Z,YAW,PITCH"));
    cmd->add_option("--cull", o->cull, "Culling stages at start")
        ->capture_default_str()
        ->check(CLI::IsMember({"none", "frustum", "pvs", "pvs+frustum"}));
    cmd->callback([o, &exit_code] {
        const auto size = parse_size_argument(o->size); // the validator accepted it
        gui::InspectorOptions options;
        options.zone_path = o->path;
        options.screenshot = o->screenshot;
        options.frames = o->frames;
        options.width = (*size)[0];
        options.height = (*size)[1];
        if (!o->camera.empty())
            options.camera = parse_camera_argument(o->camera);
        options.cull_mode = parse_cull_mode(o->cull).value_or(CullMode::PvsFrustum);
        exit_code = gui::run_inspector(options);
    });
}

} // namespace pvs::app
