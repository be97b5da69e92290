#include "app/cmd_render.h"

#include "app/argument_parsers.h"
#include "app/cli_validators.h"
#include "app/pvs_source.h"
#include "app/zone_load_args.h"
#include "app/error_path.h"

#include "render/culled_frame.h"
#include "render/software_renderer.h"
#include "visibility/culler.h"
#include "visibility/file_error.h"
#include "wld/zone_file.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace pvs::app {

namespace {

struct RenderOptions {
    std::string path;
    ZoneLoadOptions load; // --map, --gwa (Doom WADs)
    std::string camera;
    std::string cull_camera; // empty: cull from --camera
    float fov = 70.0f;
    std::string size = "800x600";
    std::string mode = "textured";
    float far = 0.0f; // > 0: far clip and the culler's distance stage
    std::string cull = "pvs+frustum";
    std::string pvs = "baked";
    std::string output;
};

int run_render(const RenderOptions& options)
{
    // The validators already accepted these; parse again for the values.
    const auto camera_values = parse_camera_argument(options.camera);
    const auto size = parse_size_argument(options.size);
    const auto mode = ui::parse_render_mode(options.mode);
    const auto cull_mode = parse_cull_mode(options.cull);
    const bool locked = !options.cull_camera.empty();
    const auto cull_camera_values = locked ? parse_camera_argument(options.cull_camera) : std::nullopt;
    if (!camera_values || !size || !mode || !cull_mode || (locked && !cull_camera_values))
        return bad_arguments(stderr, "bad arguments (see pvscope render --help)");
    return run_reporting_errors(options.path, stderr, [&] {
        const Zone zone = load_zone(options.path, options.load);

        // Both cameras share the lens (fov, aspect, near); the far clip is the culling camera's:
        // with --cull-camera the picture looks at its work from outside, so it must not clip.
        auto make_camera = [&](const std::array<float, 5>& values, bool culls) {
            Camera c;
            c.position = {values[0], values[1], values[2]};
            c.yaw_degrees = values[3];
            c.pitch_degrees = values[4];
            c.fov_y_degrees = options.fov;
            c.aspect = float((*size)[0]) / float((*size)[1]);
            if (options.far > 0.0f && culls)
                c.far_distance = options.far;
            return c;
        };
        const Camera camera = make_camera(*camera_values, !locked);
        const std::optional<Camera> cull_camera =
            locked ? std::optional<Camera>(make_camera(*cull_camera_values, true)) : std::nullopt;

        const PvsSource source = make_pvs_source(zone, options.pvs);
        if ((options.pvs != "baked" && options.pvs != "file") || !source.pvs)
            std::fprintf(stderr, "pvscope: PVS %s\n", source.note.c_str());
        Culler culler(zone, source.pvs);
        ui::SoftwareRenderer renderer((*size)[0], (*size)[1]);
        CullOptions cull_options{*cull_mode, true};
        cull_options.distance_stage = options.far > 0.0f;
        const ui::CulledFrame frame =
            ui::render_culled(renderer, culler, camera, cull_camera, cull_options, *mode);
        const CullStats& s = frame.cull;
        const ui::Image& image = frame.image;
        ui::save_png(image, options.output);

        // The stats are the culling camera's: the locked one when --cull-camera is given.
        const double cull_ms = s.cull_us() / 1000.0;
        const ui::RenderStats& r = renderer.last_stats();
        const double render_ms = r.scene_ms + r.draw_ms;
        const char* place = s.camera == CameraPlace::InRegion ? "" : s.camera == CameraPlace::InSolid ? " (in solid)" : " (outside)";
        if (cull_camera)
            std::printf("locked cull camera %g,%g,%g,%g,%g | ", double(cull_camera->position.x),
                        double(cull_camera->position.y), double(cull_camera->position.z),
                        double(cull_camera->yaw_degrees), double(cull_camera->pitch_degrees));
        if (zone.view_grid)
            std::printf("cell %d | ", s.cell);
        if (options.far > 0.0f)
            std::printf("far %g: regions after pvs %u -> distance %u (%.3f us) | ", double(options.far),
                        s.regions_after_pvs, s.regions_after_distance, s.distance_us);
        std::printf("region %d%s | cull %s%s | regions %u -> pvs %u -> frustum %u | triangles %llu -> pvs %llu -> "
                    "frustum %llu | cull %.3f ms | render %.1f ms (scene %.1f, draw %.1f) | %ux%u %s -> %s\n",
                    s.region, place, cull_mode_name(*cull_mode), s.pvs_used ? "" : " (no pvs stage)", s.regions_total,
                    s.regions_after_pvs, s.regions_after_frustum, static_cast<unsigned long long>(s.triangles_total),
                    static_cast<unsigned long long>(s.triangles_after_pvs),
                    static_cast<unsigned long long>(s.triangles_after_frustum), cull_ms, render_ms, r.scene_ms,
                    r.draw_ms, image.width, image.height, ui::render_mode_name(*mode), options.output.c_str());
        return kExitOk;
    });
}

} // namespace

void register_render_command(CLI::App& app, int& exit_code)
{
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Draw the regions the culler keeps, headless (Irrlicht's software renderer), into a PNG");
    cmd->add_option("file", options->path, "Zone file (.bsp, .s3d, .wad, .obj)")->required();
    add_zone_load_options(cmd, options->load);
    cmd->add_option("--camera", options->camera, "Camera position and direction, zone units and degrees (z up; "
                                                  "yaw 0 = +x, 90 = +y; pitch up from the horizontal)")
        ->required()
        ->check(camera_validator());
    cmd->add_option("--cull-camera", options->cull_camera,
                    "Cull from this camera instead (x,y,z,yaw,pitch, same lens as --camera) while drawing from "
                    "--camera: the locked culling camera, as Source's r_lockpvs. The printed stats are its own, and "
                    "its view volume is drawn in yellow (except with --mode ids)")
        ->check(camera_validator());
    cmd->add_option("--fov", options->fov, "Vertical field of view in degrees")
        ->capture_default_str()
        ->check(fov_validator());
    cmd->add_option("--far", options->far, "Far clip distance in zone units (EverQuest clips at the zone's far plane / fog distance): the culling camera's far plane (with --cull-camera the picture's camera does not clip) and a distance stage in the culler that drops regions beyond its reach. 0: none")
        ->capture_default_str()
        ->check(distance_validator(false));
    cmd->add_option("--size", options->size, "Image size WIDTHxHEIGHT (1..8192 each)")
        ->capture_default_str()
        ->check(size_validator());
    std::vector<std::string> mode_names;
    for (ui::RenderMode m : ui::kRenderModes)
        mode_names.emplace_back(ui::render_mode_name(m));
    cmd->add_option("--mode", options->mode,
                    "What the pixels show: textured (the textures), regions (a colour per region), ids (face id + 1), "
                    "flags (textured, tinted by region flags: water blue, lava orange, slime green, ice pale cyan, "
                    "vwater teal, pvp red, zone line magenta, sky light blue)")
        ->capture_default_str()
        ->check(CLI::IsMember(mode_names));
    cmd->add_option("--cull", options->cull, "Which culling stages run before drawing")
        ->capture_default_str()
        ->check(CLI::IsMember({"none", "frustum", "pvs", "pvs+frustum"}));
    cmd->add_option("--pvs", options->pvs,
                    "PVS source: baked (the file's), none, or portal-fast / portal-full (baked now from portals "
                    "built from the zone's tree)")
        ->check(CLI::IsMember(pvs_source_names()))
        ->capture_default_str();
    cmd->add_option("-o,--output", options->output, "PNG file to write")->required();
    cmd->callback([options, &exit_code] { exit_code = run_render(*options); });
}

} // namespace pvs::app
