#include "gen/stability_cases.h"

#include "visibility/bit_row.h"
#include "visibility/reference/tree_trace.h"
#include "gen/grid_zone.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <set>
#include <stdexcept>

namespace pvs::gen {

namespace {

constexpr float kRock = 16.0f;   // solid rock around a case's boxes (unless the case opens a side)
constexpr float kHeight = 96.0f; // rooms of the plan cases are open from z = 0 to here

struct BoxSpec {
    std::string name;
    glm::vec3 lo, hi;
};

struct CaseSpec {
    std::string failure;
    std::vector<BoxSpec> boxes;
    std::vector<std::pair<glm::vec3, glm::vec3>> lines;
    glm::vec3 eye{0.0f}, target{1.0f, 0.0f, 0.0f};
    Aabb world; // empty: the boxes' bounds with kRock all round
};

// A box of the plan cases: open from the floor (z = 0) to kHeight.
BoxSpec plan_box(std::string name, float x0, float x1, float y0, float y1)
{
    return {std::move(name), {x0, y0, 0.0f}, {x1, y1, kHeight}};
}

// Two 128-unit rooms A and B separated by a wall `thickness` thick, both open along their whole
// north side onto a corridor C. A and B do not see each other: a segment between them stays at
// y < 128 (both rooms do), so it crosses the wall's x range inside the wall (y = 128 exactly only
// touches the wall's top edge). Each sees C.
CaseSpec wall_case(float thickness)
{
    const float b0 = 128.0f + thickness;
    CaseSpec c;
    c.failure = "a wall " + std::string(thickness < 1.0f ? "0.1 units" : "1 unit") +
                " thick between two rooms that share a corridor: sampling can see through it";
    c.boxes = {plan_box("A", 0, 128, 0, 128), plan_box("B", b0, b0 + 128, 0, 128),
               plan_box("C", 0, b0 + 128, 128, 192)};
    c.lines = {{{64, 64, 48}, {64, 160, 48}}, {{b0 + 64, 64, 48}, {b0 + 64, 160, 48}}};
    c.eye = {64, 64, 48};
    c.target = {b0 + 64, 64, 48};
    return c;
}

// Rooms A and B either side of the 8-unit wall x in [128, 136], joined by one opening box; the
// case's sight lines run from A through the opening into B (the first is also the camera's).
CaseSpec opening_case(std::string failure, BoxSpec opening, std::vector<std::pair<glm::vec3, glm::vec3>> lines)
{
    CaseSpec c;
    c.failure = std::move(failure);
    c.boxes = {plan_box("A", 0, 128, 0, 128), std::move(opening), plan_box("B", 136, 264, 0, 128)};
    c.lines = std::move(lines);
    c.eye = c.lines.front().first;
    c.target = c.lines.front().second;
    return c;
}

// An opening D `width` wide and full height, centred at y = 64 (offset moves the whole case). All
// three boxes see each other along y = 64.
CaseSpec crack_case(float width, const glm::vec3& offset, const std::string& failure)
{
    const float half = width * 0.5f;
    CaseSpec c = opening_case(failure, plan_box("D", 128, 136, 64 - half, 64 + half), {{{32, 64, 48}, {232, 64, 48}}});
    for (BoxSpec& b : c.boxes) {
        b.lo += offset;
        b.hi += offset;
    }
    for (auto& [from, to] : c.lines) {
        from += offset;
        to += offset;
    }
    c.eye += offset;
    c.target += offset;
    return c;
}

// A letterbox S, 0.5 units tall and the rooms' full 128-unit width: a long thin portal.
CaseSpec slot_case()
{
    return opening_case("a letterbox 0.5 units tall and 128 wide through a wall: a long thin portal",
                        {"S", {128, 0, 40}, {136, 128, 40.5f}},
                        {{{32, 64, 40.25f}, {232, 64, 40.25f}}, {{32, 8, 40.25f}, {232, 120, 40.25f}}});
}

// A hole H 0.05 x 0.05 units: smaller than vis's ON_EPSILON (0.1).
CaseSpec pinhole_case()
{
    return opening_case("a hole 0.05 x 0.05 units through a wall, smaller than the vis epsilon (0.1)",
                        {"H", {128, 63.975f, 47.975f}, {136, 64.025f, 48.025f}}, {{{32, 64, 48}, {232, 64, 48}}});
}

// A, B and C in a row with no walls between them (the portals' edges lie in the planes of the
// walls, floors and ceilings, and the floors are coplanar), and D north of C, round a corner.
// All four see each other: A and B see D past the corner through C (the line from A's centre to
// (376, 136) stays south of y = 128 until x = 341, inside C, then enters D). A first draft of
// this case claimed A and B meet D only along the corner's edge; the reference found the line.
CaseSpec corner_case()
{
    CaseSpec c;
    c.failure = "coplanar portals, walls and floors; rooms seen past a corner through a third";
    c.boxes = {plan_box("A", 0, 128, 0, 128), plan_box("B", 128, 256, 0, 128), plan_box("C", 256, 384, 0, 128),
               plan_box("D", 256, 384, 128, 256)};
    c.lines = {{{64, 64, 48}, {320, 64, 48}}, {{320, 64, 48}, {320, 192, 48}}, {{64, 64, 48}, {376, 136, 48}}};
    c.eye = {64, 64, 48};
    c.target = {376, 136, 48};
    return c;
}

// Room A (floor 0) climbs 32 steps of 0.5 units, each 4 deep, to room B (floor 16), under one
// ceiling at 112: every box is open from its floor to z = 112, so the line at z = 100 passes
// through all of them and every pair sees each other.
CaseSpec stairs_case()
{
    CaseSpec c;
    c.failure = "32 steps 0.5 units high: many tiny portals stacked on each other";
    c.boxes.push_back({"A", {0, 0, 0}, {128, 64, 112}});
    for (int i = 0; i < 32; ++i)
        c.boxes.push_back({"step" + std::to_string(i + 1),
                           {128.0f + 4.0f * float(i), 0, 0.5f * float(i + 1)},
                           {132.0f + 4.0f * float(i), 64, 112}});
    c.boxes.push_back({"B", {256, 0, 16}, {384, 64, 112}});
    c.lines = {{{64, 32, 100}, {320, 32, 100}}};
    c.eye = {64, 32, 48};
    c.target = {320, 32, 64};
    return c;
}

// Rooms A and B, each with a 16-unit window (WA, WB) in its north wall onto V, open space that
// reaches the world's edge (as a leaky map's outside does). The rooms are sealed from each other
// by the wall x in [128, 136]. A sees WA and V, B sees WB and V. A segment between the two rooms,
// or between one window and the other room or window, stays at y < 136, where everything between
// x = 72 and x = 192 is rock except the windows themselves: no pair across the wall sees.
CaseSpec leak_case()
{
    CaseSpec c;
    c.failure = "rooms whose windows open onto the outside (open space reaching the world's edge)";
    c.boxes = {plan_box("A", 0, 128, 0, 128),   plan_box("WA", 56, 72, 128, 136), plan_box("B", 136, 264, 0, 128),
               plan_box("WB", 192, 208, 128, 136), plan_box("V", 0, 264, 136, 200)};
    c.lines = {{{64, 64, 48}, {64, 180, 48}}, {{200, 64, 48}, {200, 180, 48}}};
    c.eye = {64, 64, 48};
    c.target = {64, 180, 48};
    c.world.grow(glm::vec3(-kRock, -kRock, -kRock));
    c.world.grow(glm::vec3(264 + kRock, 200, kHeight + kRock));
    return c;
}

// Rooms A and B joined by a corridor of 20 pieces, 16 units long, alternately 32 and 16 wide,
// all centred on y = 64: the line along y = 64 passes through every box, so all see each other.
CaseSpec chain_case()
{
    CaseSpec c;
    c.failure = "two rooms seen only through a chain of 20 corridor pieces (21 portals)";
    c.boxes.push_back(plan_box("A", 0, 128, 0, 128));
    for (int i = 0; i < 20; ++i) {
        const float half = i % 2 == 0 ? 16.0f : 8.0f;
        c.boxes.push_back(plan_box("piece" + std::to_string(i + 1), 128.0f + 16.0f * float(i),
                                   144.0f + 16.0f * float(i), 64 - half, 64 + half));
    }
    c.boxes.push_back(plan_box("B", 448, 576, 0, 128));
    c.lines = {{{32, 64, 48}, {544, 64, 48}}};
    c.eye = {32, 64, 48};
    c.target = {512, 64, 48};
    return c;
}

constexpr std::array<std::string_view, 13> kCaseNames{"wall-1",  "wall-0.1", "door-8", "crack-1",  "crack-0.1",
                                                      "crack-0.01", "slot",   "pinhole", "corner",  "stairs",
                                                      "far-crack-0.1", "leak", "chain-20"};

CaseSpec case_spec(std::string_view name)
{
    const glm::vec3 here(0.0f);
    if (name == "wall-1")
        return wall_case(1.0f);
    if (name == "wall-0.1")
        return wall_case(0.1f);
    if (name == "door-8")
        return crack_case(8.0f, here, "a doorway 8 units wide in an 8-unit wall");
    if (name == "crack-1")
        return crack_case(1.0f, here, "a crack 1 unit wide: thinner than a raster's sample step at range");
    if (name == "crack-0.1")
        return crack_case(0.1f, here, "a crack 0.1 units wide: as wide as the vis epsilon");
    if (name == "crack-0.01")
        return crack_case(0.01f, here, "a crack 0.01 units wide: far below every epsilon, still a real sight line");
    if (name == "slot")
        return slot_case();
    if (name == "pinhole")
        return pinhole_case();
    if (name == "corner")
        return corner_case();
    if (name == "stairs")
        return stairs_case();
    if (name == "far-crack-0.1")
        return crack_case(0.1f, glm::vec3(20000.0f, 20000.0f, 0.0f),
                          "the 0.1-unit crack 20 000 units from the origin, where floats step by 0.002");
    if (name == "leak")
        return leak_case();
    if (name == "chain-20")
        return chain_case();
    throw std::invalid_argument("unknown stability case '" + std::string(name) + "' (cases: " +
                                [] {
                                    std::string all;
                                    for (std::string_view n : kCaseNames)
                                        all += (all.empty() ? "" : ", ") + std::string(n);
                                    return all;
                                }() +
                                ")");
}

// The grid lines of one axis: the world's sides and every box side, sorted, each once.
std::vector<float> axis_lines(const CaseSpec& spec, int axis)
{
    std::set<float> lines{spec.world.min[axis], spec.world.max[axis]};
    for (const BoxSpec& b : spec.boxes) {
        lines.insert(b.lo[axis]);
        lines.insert(b.hi[axis]);
    }
    return {lines.begin(), lines.end()};
}

int line_index(const std::vector<float>& lines, float value)
{
    return int(std::lower_bound(lines.begin(), lines.end(), value) - lines.begin());
}

Camera camera_looking(const glm::vec3& eye, const glm::vec3& target)
{
    const glm::vec3 d = target - eye;
    Camera camera;
    camera.position = eye;
    camera.yaw_degrees = float(std::atan2(d.y, d.x) * 180.0 / M_PI);
    camera.pitch_degrees = float(std::atan2(d.z, std::hypot(d.x, d.y)) * 180.0 / M_PI);
    camera.far_distance = 4096.0f;
    return camera;
}

// Region -> box, checking that every box became exactly one region.
std::vector<std::string> name_regions(const std::string& name, const CaseSpec& spec, const Zone& zone)
{
    std::vector<std::string> names(zone.regions.size());
    std::vector<int> seen(spec.boxes.size(), 0);
    for (size_t r = 0; r < zone.regions.size(); ++r) {
        const Aabb& bounds = zone.regions[r].bounds;
        for (size_t b = 0; b < spec.boxes.size(); ++b)
            if (bounds.min == spec.boxes[b].lo && bounds.max == spec.boxes[b].hi) {
                names[r] = spec.boxes[b].name;
                ++seen[b];
            }
        if (names[r].empty())
            throw std::logic_error("stability case " + name + ": region " + std::to_string(r) + " is not one box");
    }
    for (size_t b = 0; b < spec.boxes.size(); ++b)
        if (seen[b] != 1)
            throw std::logic_error("stability case " + name + ": box " + spec.boxes[b].name + " is " +
                                   std::to_string(seen[b]) + " regions");
    return names;
}

Pvs truth_from_lines(const std::string& name, const CaseSpec& spec, const Zone& zone)
{
    const auto regions = uint32_t(zone.regions.size());
    const size_t words = bits::words_for(regions);
    std::vector<uint64_t> matrix(size_t(regions) * words, 0);
    const auto set = [&](uint32_t a, uint32_t b) { bits::set(std::span(matrix).subspan(size_t(a) * words, words), b); };
    for (uint32_t r = 0; r < regions; ++r)
        set(r, r);
    const TreeTracer tracer(zone.tree, zone.regions, SkyPortals::SkyToSky);
    TreeTracer::Scratch scratch;
    for (const auto& [from, to] : spec.lines) {
        std::vector<uint32_t> crossed;
        const TraceEnd end = tracer.trace(glm::dvec3(from), glm::dvec3(to) - glm::dvec3(from), 1.0, scratch,
                                          [&](int32_t region, double, double) { crossed.push_back(uint32_t(region)); });
        if (end.blocked)
            throw std::logic_error("stability case " + name + ": a sight line of its truth is blocked");
        for (uint32_t a : crossed)
            for (uint32_t b : crossed)
                set(a, b);
    }
    return Pvs::build(regions, [&](uint32_t r, std::span<uint64_t> row) {
        std::copy_n(matrix.begin() + std::ptrdiff_t(size_t(r) * words), words, row.begin());
        return true;
    });
}

} // namespace

std::span<const std::string_view> stability_case_names() { return kCaseNames; }

StabilityCase make_stability_case(std::string_view name)
{
    CaseSpec spec = case_spec(name);
    if (spec.world.empty())
        for (const BoxSpec& b : spec.boxes) {
            spec.world.grow(b.lo - kRock);
            spec.world.grow(b.hi + kRock);
        }
    GridAxes axes;
    for (int a = 0; a < 3; ++a)
        axes.lines[size_t(a)] = axis_lines(spec, a);
    VoxelLevel level;
    level.dims = axes.dims();
    level.cells.assign(size_t(level.dims.x) * size_t(level.dims.y) * size_t(level.dims.z), Cell::Solid);
    std::vector<uint32_t> labels(level.cells.size(), 0);
    StabilityCase out;
    out.name = std::string(name);
    for (size_t b = 0; b < spec.boxes.size(); ++b) {
        const BoxSpec& box = spec.boxes[b];
        glm::ivec3 lo(0), hi(0);
        for (int a = 0; a < 3; ++a) {
            lo[a] = line_index(axes.lines[size_t(a)], box.lo[a]);
            hi[a] = line_index(axes.lines[size_t(a)], box.hi[a]);
        }
        for (int z = lo.z; z < hi.z; ++z)
            for (int y = lo.y; y < hi.y; ++y)
                for (int x = lo.x; x < hi.x; ++x) {
                    if (labels[level.index(x, y, z)] != 0)
                        throw std::logic_error("stability case " + out.name + ": box " + box.name + " overlaps another");
                    level.set(x, y, z, Cell::Air);
                    labels[level.index(x, y, z)] = uint32_t(b + 1);
                }
    }
    out.zone = build_grid_zone(level, axes, labels);
    out.zone.source.format = "pvscope stability case";
    out.zone.source.version = "1";
    out.zone.source.path = "case:" + out.name;
    out.zone.source.counts = {{"boxes", spec.boxes.size()}, {"sight lines", spec.lines.size()}, {"cells", level.cells.size()}};
    out.zone.source.notes = {"stability case " + out.name + ": " + spec.failure, "no PVS: bake one (the truth is known by construction)"};
    out.failure = spec.failure;
    out.region_names = name_regions(out.name, spec, out.zone);
    out.truth = truth_from_lines(out.name, spec, out.zone);
    out.sight_lines = spec.lines;
    out.camera = camera_looking(spec.eye, spec.target);
    out.zone.shrink_to_fit();
    return out;
}

} // namespace pvs::gen
