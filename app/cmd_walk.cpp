#include "app/cmd_walk.h"

#include "app/argument_parsers.h"
#include "app/cli_validators.h"
#include "app/pvs_source.h"
#include "app/zone_load_args.h"
#include "app/error_path.h"
#include "render/accuracy_walk.h"
#include "visibility/eval/camera_set.h"
#include "visibility/eval/sight_check.h"
#include "visibility/eval/stale_region_cache.h"
#include "visibility/portal/portalize.h"
#include "visibility/file_error.h"
#include "wld/zone_file.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <unistd.h>

namespace pvs::app {

namespace {

struct WalkCommandOptions {
    std::string path;
    ZoneLoadOptions load; // --map, --gwa (Doom WADs)
    size_t cameras = 500;
    uint64_t seed = 1;
    std::string camera_path; // "regions", "portals" or a file of x,y,z,yaw,pitch lines
    float step = 4.0f;       // --path portals: units between cameras
    float region_cache = 0.0f; // > 0: cull from a stale region cache refreshed every this many units
    std::string cull = "pvs+frustum";
    std::string pvs = "baked";
    std::string size = "320x240";
    float fov = 70.0f;
    float far = 0.0f; // > 0: far clip and the culler's distance stage
    std::string csv;
    bool render_time = false;
};

// A camera path file: one camera per line, "x,y,z,yaw,pitch"; blank lines and lines starting
// with '#' are skipped.
std::vector<Camera> read_camera_path(const std::string& file, const Camera& lens)
{
    std::ifstream in(file);
    if (!in)
        throw FileError(file, 0, "cannot open the camera path");
    std::vector<Camera> cameras;
    std::string line;
    uint64_t offset = 0;
    for (size_t number = 1; std::getline(in, line); ++number) {
        const uint64_t line_offset = offset;
        offset += line.size() + 1;
        if (line.empty() || line[0] == '#')
            continue;
        const auto v = parse_camera_argument(line);
        if (!v)
            throw FileError(file, line_offset, "line " + std::to_string(number) + ": expected x,y,z,yaw,pitch");
        Camera c = lens;
        c.position = {(*v)[0], (*v)[1], (*v)[2]};
        c.yaw_degrees = (*v)[3];
        c.pitch_degrees = (*v)[4];
        cameras.push_back(c);
    }
    return cameras;
}

double percentile(std::vector<double> values, double p)
{
    if (values.empty())
        return 0.0;
    const size_t k = std::min(values.size() - 1, size_t(p * double(values.size() - 1) + 0.5));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
    return values[k];
}

void write_csv(const std::string& file, const std::vector<ui::WalkRow>& rows)
{
    std::ofstream out(file);
    if (!out)
        throw FileError(file, 0, "cannot create the CSV file");
    out << "camera,x,y,z,yaw,pitch,region,camera_place,lookup_us,pvs_us,distance_us,frustum_us,regions_total,"
           "regions_after_pvs,regions_after_distance,regions_drawn,triangles_total,triangles_after_pvs,triangles_drawn,render_ms,covered_pixels,"
           "raster_popping_pixels,popping_cracks,popping_unknown,popping_grazing,popping_unfaced,popping_unlisted,popping_confirmed,popping_regions,needed_triangles,"
           "triangle_overdraw,region_overdraw\n";
    const char* places[] = {"region", "solid", "outside"};
    for (size_t i = 0; i < rows.size(); ++i) {
        const ui::WalkRow& r = rows[i];
        std::string popping_regions;
        for (uint32_t region : r.confirmed_regions) {
            if (!popping_regions.empty())
                popping_regions.push_back(';');
            popping_regions.append(std::to_string(region));
        }
        out << i << ',' << r.camera.position.x << ',' << r.camera.position.y << ',' << r.camera.position.z << ','
            << r.camera.yaw_degrees << ',' << r.camera.pitch_degrees << ',' << r.cull.region << ','
            << places[int(r.cull.camera)] << ',' << r.cull.lookup_us << ',' << r.cull.pvs_us << ',' << r.cull.distance_us
            << ',' << r.cull.frustum_us << ',' << r.cull.regions_total << ',' << r.cull.regions_after_pvs << ','
            << r.cull.regions_after_distance << ',' << r.cull.regions_after_frustum
            << ',' << r.cull.triangles_total << ',' << r.cull.triangles_after_pvs << ','
            << r.cull.triangles_after_frustum << ',' << r.render_ms << ',' << r.accuracy.covered_pixels << ','
            << r.accuracy.popping_pixels << ',' << r.popping_cracks << ',' << r.popping_unknown << ',' << r.popping_grazing << ',' << r.popping_unfaced << ',' << r.popping_unlisted << ',' << r.popping_confirmed << ','
            << popping_regions << ',' << r.accuracy.needed_triangles << ',' << r.accuracy.triangle_overdraw() << ','
            << r.accuracy.region_overdraw() << '\n';
    }
}

void print_summary(const std::vector<ui::WalkRow>& rows, const WalkCommandOptions& o)
{
    std::vector<double> cull_us, distance_us, after_pvs, after_distance, regions, triangles, tri_over, region_over,
        render_ms;
    uint64_t raster_popping = 0, confirmed = 0, cracks = 0, unknown = 0, grazing = 0, unfaced = 0, unlisted = 0, popping_cameras = 0,
             outside = 0;
    for (const ui::WalkRow& r : rows) {
        cull_us.push_back(r.cull.cull_us());
        distance_us.push_back(r.cull.distance_us);
        after_pvs.push_back(r.cull.regions_after_pvs);
        after_distance.push_back(r.cull.regions_after_distance);
        regions.push_back(r.cull.regions_after_frustum);
        triangles.push_back(double(r.cull.triangles_after_frustum));
        tri_over.push_back(r.accuracy.triangle_overdraw());
        region_over.push_back(r.accuracy.region_overdraw());
        render_ms.push_back(r.render_ms);
        raster_popping += r.accuracy.popping_pixels;
        confirmed += r.popping_confirmed;
        cracks += r.popping_cracks;
        unknown += r.popping_unknown;
        grazing += r.popping_grazing;
        unfaced += r.popping_unfaced;
        unlisted += r.popping_unlisted;
        popping_cameras += r.popping_confirmed > 0;
        outside += r.cull.camera != CameraPlace::InRegion;
    }
    std::printf("%zu cameras, cull %s, PVS %s, %s; %llu not in a region\n", rows.size(), o.cull.c_str(), o.pvs.c_str(),
                o.size.c_str(), static_cast<unsigned long long>(outside));
    std::printf("  %-22s %12s %12s\n", "", "median", "p99");
    auto line = [](const char* name, const std::vector<double>& v) {
        std::printf("  %-22s %12.3f %12.3f\n", name, percentile(v, 0.5), percentile(v, 0.99));
    };
    line("cull time (us)", cull_us);
    if (o.far > 0.0f) {
        line("  of which distance", distance_us);
        line("regions after pvs", after_pvs);
        line("regions within far", after_distance);
    }
    line("regions drawn", regions);
    line("triangles drawn", triangles);
    line("triangle overdraw", tri_over);
    line("region overdraw", region_over);
    if (o.render_time)
        line("render time (ms)", render_ms);
    std::printf("  popping: %llu pixels confirmed (sight line open in the BSP tree, or to the face first in the mesh) on %llu cameras; %llu raster "
                "pixels, %llu of them cracks (sight line blocked by a wall: a gap between triangles), %llu unknown "
                "(the sight check cannot decide: a face seen edge-on, no tree), %llu grazing "
                "(open by less than %.2f units past a wall's edge), %llu unfaced (seen across a boundary the "
                "map's vis counts opaque, where no face is: the engine shows a hole), %llu unlisted (seen from a kept "
                "region that does not list the face)\n",
                static_cast<unsigned long long>(confirmed), static_cast<unsigned long long>(popping_cameras),
                static_cast<unsigned long long>(raster_popping), static_cast<unsigned long long>(cracks),
                static_cast<unsigned long long>(unknown),
                static_cast<unsigned long long>(grazing), kSightMargin, static_cast<unsigned long long>(unfaced),
                static_cast<unsigned long long>(unlisted));
    std::vector<size_t> order(rows.size());
    for (size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        if (rows[a].popping_confirmed != rows[b].popping_confirmed)
            return rows[a].popping_confirmed > rows[b].popping_confirmed;
        return rows[a].accuracy.triangle_overdraw() > rows[b].accuracy.triangle_overdraw();
    });
    std::printf("  worst cameras (confirmed popping, then triangle overdraw):\n");
    for (size_t k = 0; k < std::min<size_t>(5, order.size()); ++k) {
        const ui::WalkRow& r = rows[order[k]];
        std::printf("    #%zu  --camera %g,%g,%g,%g,%g  region %d  popping %llu  overdraw %.2f\n", order[k],
                    r.camera.position.x, r.camera.position.y, r.camera.position.z, r.camera.yaw_degrees,
                    r.camera.pitch_degrees, r.cull.region, static_cast<unsigned long long>(r.popping_confirmed),
                    r.accuracy.triangle_overdraw());
    }
}

int run_walk(const WalkCommandOptions& o)
{
    const auto size = parse_size_argument(o.size);
    const auto mode = parse_cull_mode(o.cull);
    if (!size || !mode)
        return bad_arguments(stderr, "bad --size or --cull (see pvscope walk --help)");
    return run_reporting_errors(o.path, stderr, [&] {
        const Zone zone = load_zone(o.path, o.load);
        const PvsSource source = make_pvs_source(zone, o.pvs);
        std::fprintf(stderr, "pvscope: PVS %s\n", source.note.c_str());
        const Pvs* pvs = source.pvs;
        Camera lens;
        lens.fov_y_degrees = o.fov;
        lens.aspect = float((*size)[0]) / float((*size)[1]);
        if (o.far > 0.0f)
            lens.far_distance = o.far;
        std::vector<Camera> cameras;
        if (o.camera_path == "regions")
            cameras = cameras_visiting_every_region(zone, o.seed, lens);
        else if (o.camera_path == "portals") {
            const PortalSet portals = zone.portals ? *zone.portals : build_zone_portals(zone);
            cameras = cameras_along_portals(zone, portals, o.step, o.cameras, o.seed, lens);
        } else if (!o.camera_path.empty())
            cameras = read_camera_path(o.camera_path, lens);
        else
            cameras = random_cameras_in_regions(zone, o.cameras, o.seed, lens);

        ui::WalkOptions options;
        options.mode = *mode;
        options.width = (*size)[0];
        options.height = (*size)[1];
        options.time_culled_render = o.render_time;
        options.distance_stage = o.far > 0.0f;
        std::vector<int32_t> cached_regions; // the stale cache's answer per camera, in walk order
        if (o.region_cache > 0.0f) {
            StaleRegionCache cache(zone, o.region_cache);
            RegionLocator exact(zone.tree, zone.bounds());
            size_t stale = 0;
            for (const Camera& c : cameras) {
                cached_regions.push_back(cache.region(c.position));
                stale += cached_regions.back() != exact.locate(c.position).region;
            }
            options.forced_regions = cached_regions;
            std::fprintf(stderr, "pvscope: region cache refreshed every %g units: %llu tree walks for %zu cameras, "
                                 "%zu cameras culled from a stale region\n",
                         double(o.region_cache), static_cast<unsigned long long>(cache.walks()), cameras.size(), stale);
        }
        const bool tty = isatty(STDERR_FILENO) != 0;
        options.progress = [tty](size_t done, size_t total) {
            if (tty && (done % 16 == 0 || done == total)) {
                const int filled = int(40 * done / std::max<size_t>(total, 1));
                std::fprintf(stderr, "\r[%-40s] %zu/%zu cameras", std::string(size_t(filled), '#').c_str(), done, total);
                if (done == total)
                    std::fprintf(stderr, "\n");
            }
            return true;
        };
        const auto rows = ui::run_accuracy_walk(zone, pvs, cameras, options);
        if (!o.csv.empty())
            write_csv(o.csv, rows);
        print_summary(rows, o);
        return kExitOk;
    });
}

} // namespace

void register_walk_command(CLI::App& app, int& exit_code)
{
    auto o = std::make_shared<WalkCommandOptions>();
    CLI::App* cmd = app.add_subcommand("walk", "Cull and render a reproducible set of cameras: speed, popping and "
                                               "overdraw per camera (CSV) and a summary");
    cmd->add_option("file", o->path, "Zone file")->required();
    add_zone_load_options(cmd, o->load);
    cmd->add_option("--cameras", o->cameras, "Number of seeded random cameras inside regions")->capture_default_str();
    cmd->add_option("--seed", o->seed, "Seed of the random cameras")->capture_default_str();
    cmd->add_option("--path", o->camera_path,
                    "'regions' for one camera in every region a player can stand in, 'portals' for a player's "
                    "continuous walk through the portal graph (--step units apart, at most --cameras), or a file "
                    "of x,y,z,yaw,pitch lines (replaces the random cameras)");
    cmd->add_option("--step", o->step, "--path portals: units between cameras")
        ->check(distance_validator(true))
        ->capture_default_str();
    cmd->add_option("--region-cache", o->region_cache,
                    "Baseline: cull from a stale camera->region cache walked again only after the camera moved "
                    "this many units (an EverQuest client uses 5); 0 = pvscope's culler (a tree walk every frame)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    cmd->add_option("--cull", o->cull, "Which culling stages run: none | frustum | pvs | pvs+frustum")
        ->capture_default_str()
        ->check(CLI::IsMember({"none", "frustum", "pvs", "pvs+frustum"}));
    cmd->add_option("--pvs", o->pvs,
                    "PVS source: baked (the file's), none, or portal-fast / portal-full (baked now from "
                    "portals built from the zone's tree)")
        ->check(CLI::IsMember(pvs_source_names()))
        ->capture_default_str();
    cmd->add_option("--size", o->size, "ID-buffer size WIDTHxHEIGHT")->capture_default_str()->check(size_validator());
    cmd->add_option("--fov", o->fov, "Vertical field of view in degrees")->capture_default_str()->check(fov_validator());
    cmd->add_option("--far", o->far, "Far clip distance in zone units (EverQuest clips at the zone's far plane / fog distance): the camera's far plane and a distance stage in the culler that drops regions beyond its reach. 0: none")
        ->capture_default_str()
        ->check(distance_validator(false));
    cmd->add_option("--csv", o->csv, "Write one row per camera to this CSV file");
    cmd->add_flag("--render-time", o->render_time, "Also time a textured render of each culled frame");
    cmd->callback([o, &exit_code] { exit_code = run_walk(*o); });
}

} // namespace pvs::app
