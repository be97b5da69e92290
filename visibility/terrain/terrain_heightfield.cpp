#include "visibility/terrain/terrain_heightfield.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pvs {
namespace {

// Which children of `node` the box's interior reaches: bit 0 front, bit 1 back.
unsigned sides_reached(const BspNode& node, const Aabb& box)
{
    const double cx = (double(box.min.x) + double(box.max.x)) * 0.5;
    const double cy = (double(box.min.y) + double(box.max.y)) * 0.5;
    const double cz = (double(box.min.z) + double(box.max.z)) * 0.5;
    const double ex = (double(box.max.x) - double(box.min.x)) * 0.5;
    const double ey = (double(box.max.y) - double(box.min.y)) * 0.5;
    const double ez = (double(box.max.z) - double(box.min.z)) * 0.5;
    const double nx = node.normal.x, ny = node.normal.y, nz = node.normal.z;
    const double centre = ((nx * cx + ny * cy) + nz * cz) - double(node.dist);
    const double radius = std::abs(nx) * ex + std::abs(ny) * ey + std::abs(nz) * ez;
    // An axis-aligned plane gives the exact distances of the box faces (floats, halved and
    // subtracted in double); any other is rounded, so a box within a relative hair of the plane
    // is sent down both sides, which can only call a solid box open.
    const int axes = (nx != 0.0) + (ny != 0.0) + (nz != 0.0);
    const double tolerance =
        axes <= 1 ? 0.0 : 1e-9 * (std::abs(nx * cx) + std::abs(ny * cy) + std::abs(nz * cz) + std::abs(node.dist) + radius);
    unsigned sides = 0;
    if (centre + radius > tolerance)
        sides |= 1u; // some interior point in front
    if (centre - radius < -tolerance)
        sides |= 2u; // some interior point behind
    if (sides == 0)
        sides = 3u; // a box flat on the plane (no interior): both, the safe answer
    return sides;
}

bool leaf_blocks(const BspTree& tree, int32_t leaf, size_t region_count)
{
    if (leaf < 0 || size_t(leaf) >= tree.leaf_region.size())
        return true;
    const int32_t region = tree.leaf_region[size_t(leaf)];
    return region < 0 || size_t(region) >= region_count;
}

bool box_is_solid(const BspTree& tree, const Aabb& box, size_t region_count, std::vector<int32_t>& stack)
{
    stack.clear();
    stack.push_back(tree.root);
    size_t visits = 0;
    while (!stack.empty()) {
        const int32_t child = stack.back();
        stack.pop_back();
        if (BspTree::is_leaf(child)) {
            if (!leaf_blocks(tree, BspTree::leaf_index(child), region_count))
                return false;
            continue;
        }
        // A corrupt child blocks, as in the tracer; a cycle (which loaders reject) cannot hang.
        if (size_t(child) >= tree.nodes.size() || ++visits > 4 * tree.nodes.size() + 4)
            continue;
        const BspNode& node = tree.nodes[size_t(child)];
        const unsigned sides = sides_reached(node, box);
        if (sides & 1u)
            stack.push_back(node.children[0]);
        if (sides & 2u)
            stack.push_back(node.children[1]);
    }
    return true;
}

Aabb union_box(std::span<const Aabb> boxes)
{
    Aabb box;
    for (const Aabb& b : boxes)
        if (!b.empty())
            box.grow(b);
    return box;
}

// The smallest region extent along one axis (0 when no region has a positive one).
double smallest_extent(std::span<const Aabb> boxes, int axis)
{
    double smallest = 0.0;
    for (const Aabb& b : boxes) {
        if (b.empty())
            continue;
        const double extent = double(b.max[axis]) - double(b.min[axis]);
        if (extent > 0.0 && (smallest == 0.0 || extent < smallest))
            smallest = extent;
    }
    return smallest;
}

float float_at_most(double v)
{
    float f = float(v);
    return double(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

float float_at_least(double v)
{
    float f = float(v);
    return double(f) < v ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// Column size: a float, so that column edges (origin + i * cell, in double) are exact.
double column_cell(double requested, double smallest, double extent)
{
    double cell = requested > 0.0 ? requested : smallest;
    if (!(cell > 0.0))
        cell = extent > 0.0 ? extent : 1.0;
    return double(float_at_least(std::max(cell, extent / double(kMaxHeightfieldColumns))));
}

// Columns from `origin` whose last edge reaches `end` (at least one).
uint32_t columns_covering(double origin, double cell, double end)
{
    uint32_t columns = uint32_t(std::clamp(std::ceil((end - origin) / cell), 1.0, double(kMaxHeightfieldColumns + 1)));
    while (columns > 1 && origin + (columns - 1) * cell >= end)
        --columns;
    while (origin + columns * cell < end)
        ++columns;
    return columns;
}

} // namespace

bool box_interior_is_solid(const BspTree& tree, const Aabb& box)
{
    std::vector<int32_t> stack;
    return tree.exists() && box_is_solid(tree, box, SIZE_MAX, stack);
}

Heightfield zone_heightfield(const BspTree& tree, std::span<const Aabb> region_boxes, double cell)
{
    if (!tree.exists())
        throw std::invalid_argument("terrain: the zone has no BSP tree to find its ground in");
    const Aabb box = union_box(region_boxes);
    if (box.empty())
        throw std::invalid_argument("terrain: the zone has no region with a box");

    Heightfield field;
    field.origin_x = box.min.x;
    field.origin_y = box.min.y;
    field.floor = box.min.z;
    const double extent_x = double(box.max.x) - double(box.min.x);
    const double extent_y = double(box.max.y) - double(box.min.y);
    field.cell_x = column_cell(cell, smallest_extent(region_boxes, 0), extent_x);
    field.cell_y = column_cell(cell, smallest_extent(region_boxes, 1), extent_y);
    field.columns_x = columns_covering(field.origin_x, field.cell_x, box.max.x);
    field.columns_y = columns_covering(field.origin_y, field.cell_y, box.max.y);

    // Ground can only be where a region starts.
    std::vector<double> candidates;
    for (const Aabb& b : region_boxes)
        if (!b.empty() && double(b.min.z) > field.floor)
            candidates.push_back(b.min.z);
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());

    field.top.assign(size_t(field.columns_x) * field.columns_y, field.floor);
    std::vector<int32_t> stack;
    for (uint32_t y = 0; y < field.columns_y; ++y)
        for (uint32_t x = 0; x < field.columns_x; ++x) {
            // The float box holds the column (rounded outward), so "solid" covers all of it.
            Aabb column;
            column.min = glm::vec3(float_at_most(field.origin_x + x * field.cell_x),
                                   float_at_most(field.origin_y + y * field.cell_y), float(field.floor));
            column.max = glm::vec3(float_at_least(field.origin_x + (x + 1) * field.cell_x),
                                   float_at_least(field.origin_y + (y + 1) * field.cell_y), float(field.floor));
            // Largest candidate with a solid column: solidity only falls as the column grows.
            size_t lo = 0, hi = candidates.size(); // candidates[0, lo) solid, [hi, end) not
            while (lo < hi) {
                const size_t mid = lo + (hi - lo) / 2;
                column.max.z = float(candidates[mid]);
                if (box_is_solid(tree, column, region_boxes.size(), stack))
                    lo = mid + 1;
                else
                    hi = mid;
            }
            field.top[size_t(x) + size_t(y) * field.columns_x] = lo == 0 ? field.floor : candidates[lo - 1];
        }
    return field;
}

} // namespace pvs
