// The inspector's state and logic, with no ImGui, GLFW or OpenGL in it: the loaded zone, the
// view camera and the culling camera (locked or following), the cull and render modes, the
// last frame (stats and picture), the per-frame time history, and the selection. Tests drive it
// headless; the panels (ui/gui/panels.h) only show it and call its functions.
//
// Call flow of one inspector frame (the viewport panel makes these calls):
//   step_camera(input, dt)      fly the view camera
//   set_viewport_size(w, h)     the picture's size follows the viewport window
//   frame()                     cull from the culling camera, render from the view camera
//   pick(x, y) on a click       ID render of the same frame -> face -> its regions
//
// Lock (Source's r_lockpvs): while locked, the culling camera stays where it was and the view
// camera moves alone, so the set the culler kept can be looked at from outside; the stats are
// then exactly those of culling from the locked camera alone. Unlocking snaps the culling camera
// back onto the view camera.
//
// Not thread-safe; owns one SoftwareRenderer (see its header for what creating one does).
#pragma once

#include "ui/gui/frame_history.h"
#include "ui/software_renderer.h"
#include "visibility/camera.h"
#include "visibility/culler.h"
#include "visibility/zone.h"
#include "visibility/zone_stats.h"

#include <cstdint>
#include <glm/vec2.hpp>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace pvs::gui {

// One frame of fly-camera input (WASD + QE, mouse look, wheel for speed, shift to go fast).
struct CameraInput {
    bool forward = false, back = false;  // W, S: along the view direction (pitch included)
    bool left = false, right = false;    // A, D: sideways, horizontal
    bool up = false, down = false;       // E, Q: along +z / -z
    bool fast = false;                   // shift: kFastFactor times the speed
    glm::vec2 look{0.0f};                // mouse movement in pixels while looking: x right, y down
    float wheel = 0.0f;                  // wheel steps: each multiplies the speed by kSpeedStep
};

inline constexpr float kFastFactor = 4.0f;
inline constexpr float kSpeedStep = 1.25f;
inline constexpr float kLookDegreesPerPixel = 0.15f;
inline constexpr float kMaxPitchDegrees = 89.0f;

// A face picked in the viewport and the regions that list it.
struct Selection {
    uint32_t face = ui::kNoFace;
    std::vector<uint32_t> face_regions; // ascending
    int32_t region = -1;                // the selected region: a visible one of face_regions, or -1
};

class InspectorState {
public:
    InspectorState();
    ~InspectorState();
    InspectorState(const InspectorState&) = delete;
    InspectorState& operator=(const InspectorState&) = delete;

    // ---- Zone ----------------------------------------------------------------------------------
    // Loads a zone file (any supported format). On failure the current zone stays, error() says
    // why and false is returned; it never throws for a bad file.
    bool open_zone(const std::string& path);
    // The built-in procedural demo zone (gen::demo_zone_params()).
    void open_demo();
    bool has_zone() const { return zone_ != nullptr; }
    const Zone& zone() const { return *zone_; } // precondition: has_zone()
    const ZoneStats& zone_stats() const { return zone_stats_; }
    double load_ms() const { return load_ms_; }
    const std::string& error() const { return error_; }
    // Counts the zones opened (1 for the first): caches keyed by it see a new zone.
    uint64_t zone_generation() const { return zone_generation_; }
    // Regions listing a face, ascending (the inverse of Zone::faces_of_region).
    std::span<const uint32_t> regions_of_face(uint32_t face) const;
    // Triangles of a region's faces.
    uint64_t region_triangles(uint32_t region) const;

    // ---- Cameras -------------------------------------------------------------------------------
    Camera& view_camera() { return view_; }
    const Camera& view_camera() const { return view_; }
    const Camera& cull_camera() const { return cull_; }
    bool locked() const { return locked_; }
    void set_lock(bool locked);
    // Units per second; starts at a tenth of the zone's diagonal.
    float move_speed() const { return move_speed_; }
    void set_move_speed(float speed);
    void step_camera(const CameraInput& input, float dt_seconds);
    // The camera a zone opens with: at the centre of one of its largest regions, looking
    // horizontally (pitch -10) the way the line of sight through open space is longest.
    void reset_camera();
    // Moves the view camera to the centre of a region's bounds (direction kept).
    void go_to_region(uint32_t region);

    // ---- Frame ---------------------------------------------------------------------------------
    CullMode cull_mode = CullMode::PvsFrustum;
    ui::RenderMode render_mode = ui::RenderMode::Textured;

    // The picture's size in pixels (1 .. 8192 each, clamped); the view camera's aspect follows.
    void set_viewport_size(uint32_t width, uint32_t height);
    uint32_t viewport_width() const { return width_; }
    uint32_t viewport_height() const { return height_; }
    // Culls from the culling camera, renders the kept regions from the view camera into image(),
    // records the stats and the times. Returns the cull stats (all zero without a zone).
    const CullStats& frame();
    const ui::Image& image() const { return image_; }
    const CullStats& last_cull() const { return last_cull_; }
    const ui::RenderStats& last_render() const { return last_render_; }
    const std::vector<uint32_t>& visible_regions() const { return visible_; }
    // Counts image_ generations so a texture is uploaded only when the picture changed.
    uint64_t frame_number() const { return frame_number_; }
    const FrameHistory& history() const { return history_; }
    const CullTotals& totals() const { return totals_; }

    // ---- Selection -----------------------------------------------------------------------------
    // Picks the face under pixel (x, y) of the last frame's picture (an ID render of the same
    // camera and visible set) and selects it. Returns the selection, or nullopt (and clears it)
    // for the background or a pixel outside the picture.
    std::optional<Selection> pick(uint32_t x, uint32_t y);
    void select_region(int32_t region); // -1 clears
    const Selection& selection() const { return selection_; }
    // The region the region panel shows: the selected one, else the culling camera's, else -1.
    int32_t shown_region() const;

    // ---- Export --------------------------------------------------------------------------------
    // The zone report (`pvscope info --json`'s fields) plus a "culling" object: the stats
    // gathered since the zone was opened and the last frame's. Pretty-printed JSON.
    std::string export_stats_json() const;
    // The same content as one CSV table: a header line of dotted field names ("counts.regions",
    // "culling.frames", ...) and one line of values. Lists (notes, zone lines) are left out.
    std::string export_stats_csv() const;

private:
    void adopt_zone(std::unique_ptr<Zone> zone, double load_ms);
    void ensure_renderer();

    std::unique_ptr<Zone> zone_;
    std::unique_ptr<Culler> culler_;
    ZoneStats zone_stats_;
    double load_ms_ = 0;
    std::string error_;
    uint64_t zone_generation_ = 0;
    std::vector<uint32_t> face_region_offsets_, face_regions_;

    Camera view_, cull_;
    bool locked_ = false;
    float move_speed_ = 320.0f;

    uint32_t width_ = 640, height_ = 480;
    std::unique_ptr<ui::SoftwareRenderer> renderer_;
    ui::Image image_;
    CullStats last_cull_;
    ui::RenderStats last_render_;
    std::vector<uint32_t> visible_;
    uint64_t frame_number_ = 0;
    FrameHistory history_;
    CullTotals totals_;

    Selection selection_;
};

} // namespace pvs::gui
