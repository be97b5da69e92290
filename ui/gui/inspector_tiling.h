// Where each inspector window goes for a display size: a fixed tiling under the menu bar in which
// no window covers the viewport, at any size. Side columns of fixed width while the display allows
// (Zone and Region on the left; Culling, BSP and Bake on the right); the middle column holds the
// Viewport on top and, under it, the Stability and Compare windows: a title bar each while
// collapsed, sharing the lower part of the column while open (the viewport shrinks to make room).
// Pure arithmetic: no ImGui, so tests check it at any size; inspector_layout.cpp applies it.
#pragma once

namespace pvs::gui {

struct TileRect {
    float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;
    float right() const { return x + width; }
    float bottom() const { return y + height; }
};

struct InspectorTiling {
    TileRect viewport, zone, region, culling, bsp, bake, stability, compare;
};

// `width` x `height`: the display; `top`: the menu bar's height (the tiling starts below it);
// `title_height`: a collapsed window's height (its title bar); `stability_open`, `compare_open`:
// whether those windows are expanded.
InspectorTiling inspector_tiling(float width, float height, float top, float title_height, bool stability_open,
                                 bool compare_open);

// True when the two rectangles share interior area (touching edges do not overlap).
bool tiles_overlap(const TileRect& a, const TileRect& b);

} // namespace pvs::gui
