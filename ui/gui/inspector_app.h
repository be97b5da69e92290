// The inspector's window: GLFW owns it and an OpenGL 3 context, Dear ImGui draws the panels
// (ui/gui/panels.h) through its GLFW and OpenGL3 backends, and the viewport's software-rendered
// picture is uploaded to an OpenGL texture each frame. Everything the panels show comes from an
// InspectorState; this file is only the platform shell and the frame loop:
//   poll events -> open dropped files -> ImGui new frame -> draw_inspector -> ImGui render
//   -> (screenshot) -> swap
#pragma once

#include "ui/gui/bake_job.h"
#include "render/method_compare.h"
#include "render/zone_overlays.h"
#include "visibility/culler.h"

#include <array>
#include <cstdint>
#include "wld/zone_file.h"

#include <optional>
#include <string>

namespace pvs::gui {

struct InspectorOptions {
    std::string zone_path; // empty: the built-in demo zone
    ZoneLoadOptions zone_load; // --map / --gwa of a Doom WAD
    uint32_t width = 1280, height = 800;
    std::optional<std::array<float, 5>> camera; // x, y, z, yaw, pitch; else the zone's start view
    CullMode cull_mode = CullMode::PvsFrustum;
    float far_clip = 0.0f; // InspectorState::far_clip
    // When set: draw `frames` frames, write the whole window (glReadPixels of the back buffer)
    // to this PNG and return, without waiting for the user. For tests and the README.
    std::string screenshot;
    int frames = 5;
    // When set: draw 10 warm-up frames and `frames` timed ones as fast as they go (no vsync),
    // print the frame times and where they go (fps_report.h) and return. For docs/performance.md.
    bool report_fps = false;
    // report_fps: draw each timed frame from the next of `cameras` seeded cameras
    // (random_cameras_in_regions with camera_seed) instead of `frames` frames from one, and name
    // the slowest (fps_report.h).
    uint32_t cameras = 0;
    uint64_t camera_seed = 1;
    ui::OverlaySettings overlays;
    bool pick_centre = false; // pick the face at the viewport's centre on the first frame
    int32_t bsp_node = -1;    // the BSP panel's selected node at start (-1: none)
    // Start a bake at launch; scripted runs count their frames only once it has finished.
    std::optional<BakeRequest> bake;
    // Run the Compare panel's compare at launch, its window open; scripted runs count their frames
    // only once it has finished (the README's and docs' Compare screenshots).
    bool compare = false;
    // "NAME" or "NAME:METHOD": open crafted stability case NAME (wld/gen/stability_cases.h) at its
    // camera, culling with METHOD's PVS (portal-full when not given), instead of zone_path, with
    // the Stability panel open and its table run (the docs' Stability screenshot).
    std::string stability_case;
    // Explain this pair (A, B) at start (InspectorState::request_explanation), region A selected;
    // scripted runs count their frames only once the explanation is done.
    std::optional<std::array<uint32_t, 2>> why;
    // The process's peak-memory probe for the Compare panel (app/process_memory.h), or none.
    std::optional<ui::PeakMemoryProbe> memory_probe;
};

// Opens the window and runs until it is closed or the screenshot is written. Returns the
// process exit code (0 success, 1 when the window, the context or the screenshot fails, or the
// zone cannot be opened); errors are printed to stderr.
int run_inspector(const InspectorOptions& options);

} // namespace pvs::gui
