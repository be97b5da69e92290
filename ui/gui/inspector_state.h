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
// frame() also polls the background bake (BakeJob: its finished PVS becomes the "baked" PVS
// source), records the culling camera's path down the tree, and paints the enabled overlays
// (ui/zone_overlays.h) over the picture. The culler's PVS is the zone file's, none, or the bake
// (set_pvs_source).
//
// Not thread-safe (the bake's worker thread touches only the zone, read-only, and its own job
// state); owns one SoftwareRenderer (see its header for what creating one does).
#pragma once

#include "render/overlay_layer.h"
#include "render/picture_occlusion.h"
#include "render/software_renderer.h"
#include "render/zone_overlays.h"
#include "ui/gui/background_job.h"
#include "ui/gui/bake_job.h"
#include "ui/gui/compare_job.h"
#include "ui/gui/frame_history.h"
#include "visibility/camera.h"
#include "visibility/culler.h"
#include "visibility/eval/pair_explanation.h"
#include "visibility/eval/zone_check.h"
#include "visibility/face_regions.h"
#include "visibility/geometry/winding.h"
#include "visibility/pvs_edits.h"
#include "visibility/region_lookup.h"
#include "visibility/zone.h"
#include "visibility/zone_stats.h"
#include "wld/zone_file.h"

#include <cstdint>
#include <future>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
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

// What the mouse is over in the picture: the face, the regions that list it and their flags.
struct HoverInfo {
    uint32_t face = ui::kNoFace;
    std::span<const uint32_t> regions; // ascending; valid until the zone changes
    uint32_t flags = 0;                // RegionFlag bits of those regions together
    float distance = 0.0f;             // from the eye
};

// A face picked in the viewport and the regions that list it.
struct Selection {
    uint32_t face = ui::kNoFace;
    std::vector<uint32_t> face_regions; // ascending
    int32_t region = -1;                // the selected region: a visible one of face_regions, or -1
    std::optional<glm::vec3> point;     // where the ray through the picked pixel hits the face
};

// Where the culler's PVS comes from: the zone file's, none (frustum only), a bake made in the
// inspector (BakeJob), or the hand-edited PVS (edit_pvs).
enum class PvsSource : uint8_t { File, None, Baked, Edited };
const char* pvs_source_name(PvsSource source);

inline constexpr float kMinFovDegrees = 20.0f, kMaxFovDegrees = 140.0f;
inline constexpr float kOrbitDegreesPerPixel = 0.3f;

class InspectorState {
public:
    InspectorState();
    ~InspectorState();
    InspectorState(const InspectorState&) = delete;
    InspectorState& operator=(const InspectorState&) = delete;

    // ---- Zone ----------------------------------------------------------------------------------
    // Loads a zone file (any supported format). On failure the current zone stays, error() says
    // why and false is returned; it never throws for a bad file.
    bool open_zone(const std::string& path, const ZoneLoadOptions& load = {});
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
    // Vertical field of view of both cameras (the culling camera's only while unlocked), clamped
    // to [kMinFovDegrees, kMaxFovDegrees].
    void set_fov(float degrees);
    // Orbit: the view camera turns about `target` at its current distance, always looking at it.
    // set_orbit_target aims the camera at the target (position kept); orbit() adds yaw and pitch
    // (pitch clamped to +-kMaxPitchDegrees) and puts the camera back at the same distance.
    // Without a target orbit() does nothing. Opening a zone clears the target.
    void set_orbit_target(std::optional<glm::vec3> target);
    const std::optional<glm::vec3>& orbit_target() const { return orbit_target_; }
    void orbit(float yaw_degrees, float pitch_degrees);

    // ---- Frame ---------------------------------------------------------------------------------
    CullMode cull_mode = CullMode::PvsFrustum;
    // > 0: the view camera's far plane and the culler's distance stage (CullOptions::
    // distance_stage), as an EverQuest client's far clip; 0: neither.
    float far_clip = 0.0f;
    // Quake 2 maps: per Zone::area_portals entry, 1 = the door is shut. A frame then drops the
    // regions of every area no open areaportal joins to the culling camera's (area_flood.h), as
    // the engine does; last_area_dropped() says how many.
    std::vector<uint8_t> closed_area_portals;
    size_t last_area_dropped() const { return area_dropped_; }
    const std::vector<uint32_t>& last_area_culled() const { return area_culled_; } // ascending
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
    // The last frame()'s time after the picture was drawn: waiting for the line layer, painting
    // the other overlays and compositing (ms).
    double last_overlay_ms() const { return last_overlay_ms_; }
    const std::vector<uint32_t>& visible_regions() const { return visible_; }
    // Counts image_ generations so a texture is uploaded only when the picture changed.
    uint64_t frame_number() const { return frame_number_; }
    const FrameHistory& history() const { return history_; }
    const CullTotals& totals() const { return totals_; }
    // Regions the PVS stage kept this frame (every region when it did not run), ascending.
    const std::vector<uint32_t>& after_pvs_regions() const { return after_pvs_; }

    // ---- Overlays (ui/zone_overlays.h), painted by frame() except in IdBuffer mode ---------------
    ui::OverlaySettings overlays;
    const std::vector<ui::OverlayLabel>& overlay_labels() const { return labels_; }
    // The culling camera's walk down the tree this frame, root first (trace_point).
    const std::vector<PathStep>& camera_path() const { return path_; }
    // The BSP panel's node (-1: none): its plane is the highlighted one.
    int32_t selected_node = -1;
    // Every node's split plane clipped to its cell (computed on first use per zone).
    const std::vector<Winding>& node_polygons();
    // The zone's portals: its own, else built from its tree on a background thread, started by
    // request_portals() (the portal overlay and the region panel's neighbours request them), so
    // a large zone does not freeze the window; frame() takes the finished set. ready_portals() is
    // null until then (an empty set when the tree gives none). wait_for_portals() blocks (tests,
    // scripts). Opening another zone waits for a build in flight (it reads the zone).
    void request_portals();
    const PortalSet* ready_portals() const;
    bool portals_ready() const { return ready_portals() != nullptr; }
    bool portals_building() const { return portal_build_.valid(); }
    const PortalSet& wait_for_portals();
    // Regions whose leaves are under `node` (a node index), ascending.
    std::vector<uint32_t> regions_under(int32_t node) const;

    // ---- PVS source and bake -----------------------------------------------------------------------
    PvsSource pvs_source() const { return pvs_source_; }
    bool has_pvs_source(PvsSource source) const;
    // Switches the culler's PVS; false (nothing changes) when that source is not available.
    bool set_pvs_source(PvsSource source);
    const Pvs* active_pvs() const;
    // Changes whenever the active PVS or the baked one changes: panels key their lists on it.
    uint64_t pvs_generation() const { return pvs_generation_; }
    BakeJob& bake_job() { return bake_; }
    const BakeJob& bake_job() const { return bake_; }
    bool start_bake(const BakeRequest& request);
    // Takes a finished bake's PVS (called by frame(); tests call it directly). When it is the
    // culler's source already, the culler switches to the new one.
    void poll_bake();
    const std::optional<Pvs>& baked_pvs() const { return baked_pvs_; }

    // The Compare panel's job (compare_job.h) over the open zone, and its rows as PVS sources:
    // use_compared_pvs(i) makes row i's PVS the "baked" source and switches to it (a row with no
    // PVS, "none", switches to None). False when there is no such row.
    CompareJob& compare_job() { return compare_; }
    const CompareJob& compare_job() const { return compare_; }
    // The process's peak-memory probe for the compares started here (the application supplies it:
    // it touches process-wide state; without one the Compare rows show the bakers' estimates).
    void set_memory_probe(std::optional<ui::PeakMemoryProbe> probe) { memory_probe_ = std::move(probe); }
    bool start_compare(const ui::CompareOptions& options);
    bool use_compared_pvs(size_t row);

    // The Health section's job: `pvscope check` over the open zone (visibility/eval/zone_check.h)
    // on a background thread; its output is the report. go_to_check_place moves the camera to a
    // failure's place: its point when it has one, else into its region, and selects the region.
    using CheckJob = BackgroundJob<ZoneHealth>;
    CheckJob& check_job() { return check_; }
    const CheckJob& check_job() const { return check_; }
    bool start_check(const CheckOptions& options = {});
    void go_to_check_place(const CheckPlace& place);
    const std::string& baked_label() const { return baked_label_; }

    // ---- PVS editing (pvs_editing.cpp) --------------------------------------------------------
    // Hand edits of the PVS with undo/redo (visibility/pvs_edits.h). The first edit copies the
    // active PVS (file or baked); the culler then uses the edited one (PvsSource::Edited) and
    // every edit, undo and redo updates it. Opening another zone drops the edits. False (nothing
    // changes) without a PVS to edit or for an index out of range.
    bool edit_pvs(const PvsEdit& edit);
    // Row `row` := that row of `method` (portal-fast, portal-full, reference, ...: baked now
    // through the registry, milliseconds to seconds), or cleared to the region itself.
    bool fill_pvs_row(uint32_t row, const std::string& method);
    bool undo_pvs_edit();
    bool redo_pvs_edit();
    const EditablePvs* pvs_editor() const { return editor_ ? &*editor_ : nullptr; }
    // The edit list (wld/pvs_edit_list.h) as JSON, and loading one (its edits applied in order
    // on top of the current ones); load returns false with error() set for a bad list.
    std::string pvs_edit_list_json() const;
    bool load_pvs_edit_list(const std::string& path);
    // Pairs the edits hid that `reference` sees (what culling with the edits could pop).
    size_t pvs_edit_popping_risk(const Pvs& reference) const;
    // Writes the active PVS (edited or not) into a copy of the zone's file at `out_path`, in its
    // own format, through the writers `bake` uses (wld/pvs_writeback.h). False with error() set
    // when it cannot (a generated zone, no PVS, a write error); `message` says what was written.
    bool save_pvs(const std::string& out_path, std::string& message);
    const std::string& baked_summary() const { return baked_summary_; } // the bake's one line

    // ---- Stability cases (the Stability panel) -----------------------------------------------
    // Opens crafted case `name` (wld/gen/stability_cases.h) with its camera, bakes `method` of the
    // registry on it (milliseconds: the cases are a few regions) and culls with that PVS as the
    // "baked" source, labelled "METHOD on case NAME". False, with error() saying why, for an
    // unknown case or a method that bakes nothing; the open zone then stays.
    bool open_stability_case(const std::string& name, const std::string& method);
    // The case open now (empty when the zone is not one) and the regions its truth has that the
    // baked PVS of that case lacks, as "A -> B" lines (what the method would pop there).
    const std::string& stability_case_name() const { return case_name_; }
    const std::vector<std::string>& stability_case_missing() const { return case_missing_; }

    // ---- Why does A see B? (pair_view.cpp) ----------------------------------------------------
    // Explains the pair (visibility/eval/pair_explanation.h) for the active PVS on a background
    // thread (its portal-full flow takes about a second on e1m1); frame() takes the result and
    // the overlay then draws the sight line and the numbered chain (ui::PairOverlay). False, with
    // error() saying why, without a zone with a BSP tree or for a region out of range. A new
    // request waits for the one in flight and replaces it; opening a zone drops it.
    bool request_explanation(uint32_t a, uint32_t b);
    bool explanation_running() const { return explain_job_.valid(); }
    const std::optional<PairExplanation>& explanation() const { return explanation_; }
    // Blocks until the request in flight is done (tests, scripts); null when there is none.
    const PairExplanation* wait_for_explanation();
    void clear_explanation();
    // The view camera at the witness's A end, looking at its B end (the culling camera follows
    // unless locked): B from A, or the pop of a missing bit. False without a witness.
    bool look_along_witness();

    // ---- Hover -----------------------------------------------------------------------------------
    // The face of the last frame's picture under pixel (x, y) by a ray from the view camera
    // against the faces the picture drew, front sides (ui/picture_occlusion.h): one ray, cheap
    // enough for every frame the mouse is over the picture, where pick() renders an ID picture.
    // nullopt for the background, a pixel outside the picture or no zone.
    std::optional<HoverInfo> hover(uint32_t x, uint32_t y);
    // Regions whose pair with the culling camera's row a hand edit changed, last frame (boxed
    // on the picture in ui::kEditedPairColor while the edited PVS culls).
    const std::vector<uint32_t>& edited_pairs() const { return edited_pairs_; }
    // Rays the depth test of the overlay lines cast in the last frame (0 when it was off).
    uint64_t overlay_depth_rays() const { return overlay_depth_rays_; }

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
    void rebuild_culler();
    // The overlays' scene, all but the picture's occlusion (set where it is drawn with); the
    // many-line overlays into line_layer_ (run while the picture renders); the overlays over
    // the picture, with that layer or drawing those lines themselves (null).
    ui::OverlayScene overlay_scene();
    void paint_line_layer(ui::OverlayScene& scene);
    void paint_overlays(ui::OverlayScene& scene, const ui::Image* line_layer);
    void update_after_pvs();
    void take_finished_portals();
    std::span<const uint32_t> drawn_regions() const; // what the picture drew this frame
    // The picture's occlusion for the last frame (built once per zone, set per frame); null when
    // Embree cannot give one (error() says why).
    const ui::PictureOcclusion* picture_occlusion();
    void update_edited_pairs();
    void take_finished_explanation();

    std::unique_ptr<Zone> zone_;
    std::unique_ptr<Culler> culler_;
    ZoneStats zone_stats_;
    double load_ms_ = 0;
    std::string error_;
    uint64_t zone_generation_ = 0;
    FaceRegions face_regions_;

    Camera view_, cull_;
    bool locked_ = false;
    float move_speed_ = 320.0f;

    uint32_t width_ = 640, height_ = 480;
    std::unique_ptr<ui::SoftwareRenderer> renderer_;
    ui::Image image_;
    CullStats last_cull_;
    ui::RenderStats last_render_;
    double last_overlay_ms_ = 0;
    std::vector<uint32_t> visible_;
    uint64_t frame_number_ = 0;
    FrameHistory history_;
    CullTotals totals_;

    Selection selection_;
    std::optional<glm::vec3> orbit_target_;

    std::vector<uint32_t> after_pvs_;
    size_t area_dropped_ = 0;
    std::vector<uint32_t> area_culled_; // this frame's regions the frustum kept and shut areaportals dropped
    std::vector<uint32_t> picture_regions_, region_tints_; // the membership tint's frame lists
    std::vector<ui::OverlayLabel> labels_;
    ui::OverlayLines overlay_lines_; // paint_line_layer's working memory
    ui::Image line_layer_;
    std::vector<PathStep> path_;
    std::vector<uint32_t> path_nodes_;
    std::optional<std::vector<Winding>> node_polygons_;
    std::optional<PortalSet> built_portals_;
    std::future<PortalSet> portal_build_; // after zone_: destroyed (waited for) before it
    std::unique_ptr<ui::PictureOcclusion> occlusion_;
    uint64_t occlusion_frame_ = 0; // frame_number_ the occlusion was set for (0: none)
    uint64_t overlay_depth_rays_ = 0;
    std::vector<uint32_t> edited_pairs_; // the overlay's hand-edited pairs this frame

    PvsSource pvs_source_ = PvsSource::None;
    std::optional<Pvs> baked_pvs_;
    std::optional<EditablePvs> editor_;
    ZoneLoadOptions zone_load_; // how the open zone was read (a Doom map and its GL nodes)
    std::optional<Pvs> edited_pvs_;
    void publish_edits(); // edited_pvs_ from editor_, culling with it
    std::string case_name_;                 // the stability case open, if the zone is one
    std::vector<std::string> case_missing_; // its truth's pairs the baked PVS lacks
    std::string baked_label_; // what the "baked" source holds: "portal-full level=4 ...", a compare row
    CompareJob compare_;
    CheckJob check_;
    std::optional<ui::PeakMemoryProbe> memory_probe_;
    std::string baked_summary_;
    uint64_t pvs_generation_ = 0;
    std::optional<PairExplanation> explanation_;
    ui::PairOverlay pair_overlay_; // explanation_ as the overlay draws it
    std::optional<Pvs> explain_pvs_; // the PVS the job in flight explains (a copy: the active one may change)
    std::future<PairExplanation> explain_job_; // after zone_: destroyed (waited for) before it
    BakeJob bake_; // last: destroyed (stopped) first, before the zone it reads
};

} // namespace pvs::gui
