#include "app/cmd_render.h"

#include "app/arguments.h"

#include "ui/software_renderer.h"
#include "visibility/culler.h"
#include "visibility/file_error.h"
#include "wld/zone_file.h"

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace pvs::app {

namespace {

struct RenderOptions {
    std::string path;
    std::string camera;
    float fov = 70.0f;
    std::string size = "800x600";
    std::string mode = "textured";
    std::string cull = "pvs+frustum";
    std::string output;
};

int run_render(const RenderOptions& options)
{
    // The validators already accepted these; parse again for the values.
    const auto camera_values = parse_camera_argument(options.camera);
    const auto size = parse_size_argument(options.size);
    const auto mode = ui::parse_render_mode(options.mode);
    const auto cull_mode = parse_cull_mode(options.cull);
    if (!camera_values || !size || !mode || !cull_mode) {
        std::fprintf(stderr, "pvscope: error: bad arguments (see pvscope render --help)\n");
        return 2;
    }
    try {
        const Zone zone = load_zone(options.path);

        Camera camera;
        camera.position = {(*camera_values)[0], (*camera_values)[1], (*camera_values)[2]};
        camera.yaw_degrees = (*camera_values)[3];
        camera.pitch_degrees = (*camera_values)[4];
        camera.fov_y_degrees = options.fov;
        camera.aspect = float((*size)[0]) / float((*size)[1]);

        Culler culler(zone, zone.baked_pvs ? &*zone.baked_pvs : nullptr);
        std::vector<uint32_t> visible;
        const CullStats s = culler.cull(camera, {*cull_mode, true}, visible);

        ui::SoftwareRenderer renderer((*size)[0], (*size)[1]);
        const auto start = std::chrono::steady_clock::now();
        const ui::Image image = renderer.render(zone, camera, visible, *mode);
        const double render_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        ui::save_png(image, options.output);

        const char* place = s.camera == CameraPlace::InRegion ? "" : s.camera == CameraPlace::InSolid ? " (in solid)" : " (outside)";
        std::printf("region %d%s | cull %s%s | regions %u -> pvs %u -> frustum %u | triangles %llu -> pvs %llu -> "
                    "frustum %llu | cull %.3f ms | render %.1f ms (scene %.1f, draw %.1f) | %ux%u %s -> %s\n",
                    s.region, place, cull_mode_name(*cull_mode), s.pvs_used ? "" : " (no pvs stage)", s.regions_total,
                    s.regions_after_pvs, s.regions_after_frustum, static_cast<unsigned long long>(s.triangles_total),
                    static_cast<unsigned long long>(s.triangles_after_pvs),
                    static_cast<unsigned long long>(s.triangles_after_frustum), (s.lookup_us + s.pvs_us + s.frustum_us) / 1000.0,
                    render_ms, renderer.last_stats().scene_ms, renderer.last_stats().draw_ms, image.width, image.height,
                    ui::render_mode_name(*mode), options.output.c_str());
        return 0;
    } catch (const FileError& e) {
        std::fprintf(stderr, "pvscope: error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pvscope: error: %s\n", e.what());
        return 1;
    }
}

} // namespace

void register_render_command(CLI::App& app, int& exit_code)
{
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Draw the regions the culler keeps, headless (Irrlicht's software renderer), into a PNG");
    cmd->add_option("file", options->path, "Zone file (Quake .bsp)")->required();
    cmd->add_option("--camera", options->camera, "Camera position and direction, zone units and degrees (z up; "
                                                  "yaw 0 = +x, 90 = +y; pitch up from the horizontal)")
        ->required()
        ->check(CLI::Validator(
            [](std::string& text) {
                return parse_camera_argument(text) ? std::string()
                                                   : "expects x,y,z,yaw,pitch (five numbers, no spaces), got '" +
                                                         text + "'";
            },
            "X,Y,Z,YAW,PITCH"));
    cmd->add_option("--fov", options->fov, "Vertical field of view in degrees")
        ->capture_default_str()
        ->check(CLI::Range(1.0f, 179.0f));
    cmd->add_option("--size", options->size, "Image size WIDTHxHEIGHT (1..8192 each)")
        ->capture_default_str()
        ->check(CLI::Validator(
            [](std::string& text) {
                return parse_size_argument(text)
                           ? std::string()
                           : "expects WIDTHxHEIGHT with each 1..8192, e.g. 800x600, got '" + text + "'";
            },
            "WxH"));
    cmd->add_option("--mode", options->mode, "What the pixels show: the textures, a colour per region, or face id + 1")
        ->capture_default_str()
        ->check(CLI::IsMember({"textured", "regions", "ids"}));
    cmd->add_option("--cull", options->cull, "Which culling stages run before drawing")
        ->capture_default_str()
        ->check(CLI::IsMember({"none", "frustum", "pvs", "pvs+frustum"}));
    cmd->add_option("-o,--output", options->output, "PNG file to write")->required();
    cmd->callback([options, &exit_code] { exit_code = run_render(*options); });
}

} // namespace pvs::app
