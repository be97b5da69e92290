#include "ui/gui/inspector_tiling.h"

#include <algorithm>
#include <cmath>

namespace pvs::gui {

namespace {

// The share of the middle column the open Stability and Compare windows take together: their
// tables and charts need the room, and the picture keeps more than half.
constexpr float kOpenStripShare = 0.45f;

} // namespace

InspectorTiling inspector_tiling(float width, float height, float top, float title_height, bool stability_open,
                                 bool compare_open)
{
    const float h = std::max(height - top, 0.0f);
    const float left = std::floor(std::min(300.0f, width * 0.25f));
    const float right = std::floor(std::min(330.0f, width * 0.28f));
    const float middle = std::max(width - left - right, 0.0f);
    InspectorTiling t;
    const float zone_height = std::floor(h * 0.45f);
    t.zone = {0.0f, top, left, zone_height};
    t.region = {0.0f, top + zone_height, left, h - zone_height};
    const float culling_height = std::floor(h * 0.45f), bsp_height = std::floor(h * 0.27f);
    t.culling = {width - right, top, right, culling_height};
    t.bsp = {width - right, top + culling_height, right, bsp_height};
    t.bake = {width - right, top + culling_height + bsp_height, right, h - culling_height - bsp_height};

    // Under the viewport: a title bar per collapsed window, the open ones share the strip.
    const int open = int(stability_open) + int(compare_open);
    const float strip = open ? std::floor(h * kOpenStripShare) : 0.0f;
    const float open_height = open ? std::max(std::floor(strip / float(open)), title_height) : 0.0f;
    const float stability_height = stability_open ? open_height : title_height;
    const float compare_height = compare_open ? open_height : title_height;
    const float viewport_height = std::max(h - stability_height - compare_height, 0.0f);
    t.viewport = {left, top, middle, viewport_height};
    t.stability = {left, top + viewport_height, middle, stability_height};
    t.compare = {left, t.stability.bottom(), middle, compare_height};
    return t;
}

bool tiles_overlap(const TileRect& a, const TileRect& b)
{
    return a.x < b.right() && b.x < a.right() && a.y < b.bottom() && b.y < a.bottom();
}

} // namespace pvs::gui
