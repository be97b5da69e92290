// The vertical split plane of a Doom line, the same bits for every name of the same line.
//
// A Doom map names one line many ways: a GL node by a point and a direction of any length (the
// linedef's, for glBSP and ZDBSP), a wall seg by its linedef's end points, a split seg by a GL
// vertex rounded to 16.16. Planes computed from different names by floating-point arithmetic
// differ in their last bits, and where a wall's plane and a node's plane on the same line differ
// by 1e-5, the tree gets a sliver of solid that wide along an open boundary (the sampled
// reference then misses real sight lines). So the plane is computed from the line's canonical
// form, exactly:
//   - every input is a multiple of 1/65536 (map units or 16.16 fixed point) and is taken as the
//     integer 65536 * v;
//   - the direction is divided by the gcd of its components (the primitive direction of the
//     line: the same for every point pair on it with the same orientation);
//   - the distance's numerator, cross(direction, point), is an exact 128-bit integer: the same
//     for every point on the line.
// Then normal = (uy, -ux) / |u| and dist = numerator / (|u| * 65536), rounded once to float: the
// same inputs to the same operations, so the same bits. The opposite orientation gives the exact
// negation (the same plane facing the other way). The right side of the direction is in front.
#pragma once

namespace pvs::doom {

struct LinePlane {
    float nx = 0, ny = 0; // unit normal in the plane z = 0
    float dist = 0;       // nx * x + ny * y on the line
};

// The plane of the line through (x, y) along (dx, dy); a zero direction gives a zero normal.
// Coordinates beyond +-2^24 map units (far outside any Doom map) are clamped there.
LinePlane vertical_line_plane(double x, double y, double dx, double dy);

} // namespace pvs::doom
