// Many overlay lines drawn as few: the inspector's membership boxes, region bounds and portal
// outlines on a zone of tens of thousands of grid cells, where neighbouring cells share edges.
//
// add_box() / add_segment() / add_outline() collect segments with a colour; segments() joins
// those of one colour that lie on the same axis-parallel line and overlap or touch into one
// segment, so an edge shared by four cells is drawn once and a grid line across the zone is one
// line (one projection, one clip, a depth test per piece of it) instead of one per cell.
// Coordinates are compared exactly: cells cut by the same split planes share their corners bit
// for bit, and lines that only nearly meet stay apart (drawn as they were given). Segments that
// are not axis-parallel are kept as given.
//
// Paint order: colours in the order they were first added (the first under the later ones where
// lines cross or coincide), so a caller adds what it wants on top last. Empty boxes, zero-length
// segments and anything with a non-finite coordinate are skipped. Reuse one object across
// frames: clear() keeps its memory.
#pragma once

#include "render/overlay_lines.h"
#include "visibility/math/aabb.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <unordered_map>
#include <vector>

namespace pvs::ui {

struct ColoredSegment {
    glm::vec3 a, b;
    uint32_t rgb;
};

class LineBatch {
public:
    void clear();
    void add_box(const Aabb& box, uint32_t rgb);                            // its 12 edges
    void add_segment(const glm::vec3& a, const glm::vec3& b, uint32_t rgb);
    void add_outline(std::span<const glm::vec3> polygon, uint32_t rgb);     // closed

    // The joined segments, colour by colour in first-added order.
    std::span<const ColoredSegment> segments();

    // Draws segments() with draw_line_3d. Returns the pixels set.
    uint32_t draw(Image& image, const LineProjection& view);

private:
    uint32_t group_of(uint32_t rgb);
    void add_axis_edge(uint32_t group, uint32_t axis, float u, float v, float lo, float hi);
    void sort_lines(uint32_t line_class);

    // An axis-parallel segment, kept in the list of its colour and axis (its line class: group * 3
    // + axis). Coordinates as integers that order as the floats do, so sorting compares integers.
    struct Edge {
        uint64_t line;   // the other two coordinates, in axis order (u high, v low)
        uint32_t lo, hi; // the edge's extent along its axis
    };
    struct Loose {
        uint32_t group;
        glm::vec3 a, b;
    };
    std::vector<std::vector<Edge>> edges_; // by line class; inner lists keep their memory
    std::vector<Edge> spare_;
    std::vector<Loose> loose_; // not axis-parallel
    std::vector<uint32_t> group_rgb_;
    std::unordered_map<uint32_t, uint32_t> group_of_rgb_;
    std::vector<ColoredSegment> segments_;
    bool joined_ = false;
};

} // namespace pvs::ui
