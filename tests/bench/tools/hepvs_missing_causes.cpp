// Why does a HateEngine .hepvs miss (cell, object) pairs that can be seen? For an OBJ level with
// its .hepvs, a mesh reference is sampled cell by cell (points uniform in the cell, kept in open
// space; rays in stratified directions; Embree's watertight trace, as mesh_reference.h) and the
// first witness (point, direction) of every pair the file lacks is kept. Each missing pair is
// then put in one class, by rays from the baker's own sample points as the format spec describes
// them (quake-doom-hepvs.md §5.6: the cell centre plus a lattice at step, 2 step, ... <= cell size
// from the cell's min corner in grid space; six 90-degree views per point, each from an eye one
// grid unit out along its axis looking back at the point; near 0.1 grid units; back faces culled):
//   1. seen from one of the baker's eyes through one of its 512 x 512 pixel centres (the baker's
//      picture should hold it: not explained by the spec's model), or 1a. only where another
//      object's front face lies within kCoplanar behind it (a depth fight the first-drawn wins),
//   2. seen from one of the baker's eyes only between its pixel centres (sub-pixel),
//   3. seen from a lattice point itself but from none of its offset eyes (the eye offset),
//   4. seen from no lattice point (a sampling gap: the witness is where no lattice point is).
// A ray "sees" the object when it meets one of the object's front faces first (48 random points
// and the centroid of each of its triangles are aimed at).
//
// Usage: hepvs_missing_causes OBJ [points_per_cell=256] [directions_per_point=1024]
// (the .hepvs beside the OBJ; prints the counts of each class and a few examples). Two threads.
#include "visibility/reference/mesh_tracer.h"
#include "wld/zone_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace pvs;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr int kBakerPixels = 512;
constexpr float kBakerNear = 0.1f; // grid units
constexpr float kCoplanar = 0.05f;  // zone units: two faces this close in depth fight for the pixel

struct Witness {
    glm::vec3 point, direction;
};
using PairKey = std::pair<uint32_t, uint32_t>; // (cell, object)

struct Level {
    Zone zone;
    const ViewGrid* grid = nullptr;
    const Pvs* file = nullptr;
    std::vector<uint32_t> face_object;
};

glm::vec3 stratified_direction(uint32_t k, uint32_t count, std::mt19937_64& rng)
{
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float z = 1.0f - 2.0f * (float(k) + u(rng)) / float(count);
    const float phi = 2.399963f * float(k) + 6.2831853f * u(rng); // golden angle spiral, jittered
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// The file's misses, each with its first witness, from cells start, start + stride, ...
void sample_cells(const Level& level, const MeshTracer& tracer, uint32_t points, uint32_t directions, uint32_t start,
                  uint32_t stride, std::mutex& lock, std::map<PairKey, Witness>& missing)
{
    const ViewGrid& grid = *level.grid;
    const float clearance = 2.0f * kBakerNear * grid.grid_size;
    std::vector<uint8_t> seen(level.zone.region_count());
    for (uint64_t c = start; c < grid.cell_count(); c += stride) {
        const uint32_t cell = uint32_t(c);
        const Aabb box = grid.cell_bounds(cell);
        std::mt19937_64 rng(cell * 7919ull + 1);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        std::fill(seen.begin(), seen.end(), 0);
        uint32_t kept = 0;
        for (uint32_t tries = 0; kept < points && tries < 32 * points; ++tries) {
            const glm::vec3 p = box.min + (box.max - box.min) * glm::vec3(u(rng), u(rng), u(rng));
            if (!tracer.in_open_space(p, clearance))
                continue;
            ++kept;
            for (uint32_t k = 0; k < directions; ++k) {
                const glm::vec3 d = stratified_direction(k, directions, rng);
                const MeshTracer::Hit hit = tracer.first_hit(p, d, kInf);
                if (!hit.hit || !hit.front)
                    continue;
                const uint32_t object = level.face_object[hit.face];
                if (object >= seen.size() || seen[object])
                    continue;
                seen[object] = 1;
                if (!level.file->visible(cell, object)) {
                    std::lock_guard<std::mutex> guard(lock);
                    missing.emplace(PairKey(cell, object), Witness{p, d});
                }
            }
        }
    }
}

// Points spread over the object's triangles, to aim rays at.
std::vector<glm::vec3> object_targets(const Zone& zone, uint32_t object, std::mt19937_64& rng)
{
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<glm::vec3> targets;
    for (uint32_t f : zone.faces_of_region(object)) {
        const auto& face = zone.mesh.faces[f];
        for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t) {
            const glm::vec3& a = zone.mesh.positions[zone.mesh.indices[3 * t]];
            const glm::vec3& b = zone.mesh.positions[zone.mesh.indices[3 * t + 1]];
            const glm::vec3& c = zone.mesh.positions[zone.mesh.indices[3 * t + 2]];
            for (int s = 0; s < 48; ++s) {
                float x = u(rng), y = u(rng);
                if (x + y > 1.0f)
                    x = 1.0f - x, y = 1.0f - y;
                targets.push_back(a + (b - a) * x + (c - a) * y);
            }
            targets.push_back((a + b + c) / 3.0f);
        }
    }
    return targets;
}

struct Viewer {
    const Level& level;
    const MeshTracer& tracer;
    MeshTracer::FaceFilter front{{}, true};

    bool hits_object(const glm::vec3& eye, const glm::vec3& direction, float reach, uint32_t object) const
    {
        const MeshTracer::Hit hit = tracer.first_hit(eye, direction, reach, front);
        return hit.hit && level.face_object[hit.face] == object;
    }
    // Some target seen from `eye`; with `look`, only inside that 90-degree square view past `near`.
    bool sees(const glm::vec3& eye, const std::vector<glm::vec3>& targets, uint32_t object, const glm::vec3* look,
              float near) const
    {
        for (const glm::vec3& x : targets) {
            const glm::vec3 v = x - eye;
            const float distance = glm::length(v);
            if (distance < 1e-3f)
                continue;
            if (look) {
                const float along = glm::dot(v, *look);
                const glm::vec3 lateral = v - *look * along;
                if (along <= near || std::fabs(lateral.x) > along || std::fabs(lateral.y) > along ||
                    std::fabs(lateral.z) > along)
                    continue;
            }
            if (hits_object(eye, v / distance, distance * 1.001f + 0.01f, object))
                return true;
        }
        return false;
    }
    // Pixel centres of the view (eye, look) whose rays meet the object first; `clear` counts those
    // where no other object's front face lies within kCoplanar behind the hit (a GPU's depth test
    // would otherwise let whichever object was drawn first keep the pixel).
    int pixel_hits(const glm::vec3& eye, const glm::vec3& look, const std::vector<glm::vec3>& targets, uint32_t object,
                   float near, int& clear) const
    {
        std::vector<uint8_t> others(level.face_object.size(), 1);
        for (uint32_t f : level.zone.faces_of_region(object))
            others[f] = 0;
        const MeshTracer::FaceFilter other_objects{others, true};
        clear = 0;
        const glm::vec3 up0 = std::fabs(look.z) > 0.5f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
        const glm::vec3 side = glm::normalize(glm::cross(look, up0)), up = glm::cross(side, look);
        float u0 = kInf, u1 = -kInf, v0 = kInf, v1 = -kInf; // the object's extent on the view plane
        for (const glm::vec3& x : targets) {
            const glm::vec3 v = x - eye;
            const float along = glm::dot(v, look);
            if (along <= near)
                continue;
            u0 = std::min(u0, glm::dot(v, side) / along), u1 = std::max(u1, glm::dot(v, side) / along);
            v0 = std::min(v0, glm::dot(v, up) / along), v1 = std::max(v1, glm::dot(v, up) / along);
        }
        const float half = kBakerPixels / 2.0f;
        auto column = [&](float s) { return int(std::floor((s + 1.0f) * half)); };
        int hits = 0;
        for (int i = std::max(0, column(u0) - 1); i <= std::min(kBakerPixels - 1, column(u1) + 1); ++i)
            for (int j = std::max(0, column(v0) - 1); j <= std::min(kBakerPixels - 1, column(v1) + 1); ++j) {
                const float s = (float(i) + 0.5f) / half - 1.0f, t = (float(j) + 0.5f) / half - 1.0f;
                const glm::vec3 d = glm::normalize(look + side * s + up * t);
                const MeshTracer::Hit hit = tracer.first_hit(eye, d, kInf, front);
                if (!hit.hit || level.face_object[hit.face] != object || !(hit.t * glm::dot(d, look) > near))
                    continue;
                ++hits;
                const MeshTracer::Hit behind = tracer.first_hit(eye, d, hit.t + kCoplanar, other_objects);
                clear += behind.hit ? 0 : 1;
            }
        return hits;
    }
};

// The witness's nearest face of its cell in grid space: 0..5 = min x, max x, min y, max y, min z,
// max z, and its distance in grid units. The lattice has a layer on each max face and none on the
// min faces (it starts one step in).
std::pair<int, float> nearest_cell_face(const ViewGrid& grid, uint32_t cell, const glm::vec3& zone_point)
{
    const uint32_t cx = cell / (grid.counts.y * grid.counts.z), cy = (cell / grid.counts.z) % grid.counts.y,
                   cz = cell % grid.counts.z;
    const glm::vec3 min = grid.min + glm::vec3(cx, cy, cz) * grid.cell_size;
    const glm::vec3 p = grid.to_grid_space(zone_point);
    std::pair<int, float> best{-1, kInf};
    for (int axis = 0; axis < 3; ++axis) {
        const float to_min = p[axis] - min[axis], to_max = min[axis] + grid.cell_size - p[axis];
        if (to_min < best.second)
            best = {2 * axis, to_min};
        if (to_max < best.second)
            best = {2 * axis + 1, to_max};
    }
    return best;
}

// The baker's sample points of a cell, in zone space (grid space is the OBJ's y-up space / grid_size).
std::vector<glm::vec3> baker_points(const ViewGrid& grid, uint32_t cell)
{
    const uint32_t cx = cell / (grid.counts.y * grid.counts.z), cy = (cell / grid.counts.z) % grid.counts.y,
                   cz = cell % grid.counts.z;
    const glm::vec3 min = grid.min + glm::vec3(cx, cy, cz) * grid.cell_size;
    auto to_zone = [&](const glm::vec3& g) { return glm::vec3(g.x, -g.z, g.y) * grid.grid_size; };
    std::vector<glm::vec3> points{to_zone(min + glm::vec3(grid.cell_size * 0.5f))};
    const int n = int(std::lround(grid.cell_size)); // step 1 grid unit, the baker's default
    for (int i = 1; i <= n; ++i)
        for (int j = 1; j <= n; ++j)
            for (int k = 1; k <= n; ++k)
                points.push_back(to_zone(min + glm::vec3(float(i), float(j), float(k))));
    return points;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s LEVEL.obj [points_per_cell] [directions_per_point]\n", argv[0]);
        return 2;
    }
    const uint32_t points = argc > 2 ? uint32_t(std::atoi(argv[2])) : 256;
    const uint32_t directions = argc > 3 ? uint32_t(std::atoi(argv[3])) : 1024;
    Level level;
    try {
        level.zone = load_zone(argv[1]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    if (!level.zone.view_grid || !level.zone.baked_pvs) {
        std::fprintf(stderr, "%s: no .hepvs beside it\n", argv[1]);
        return 1;
    }
    level.grid = &*level.zone.view_grid;
    level.file = &*level.zone.baked_pvs;
    level.face_object.assign(level.zone.mesh.faces.size(), UINT32_MAX);
    for (uint32_t r = 0; r < level.zone.region_count(); ++r)
        for (uint32_t f : level.zone.faces_of_region(r))
            level.face_object[f] = r;
    const MeshTracer tracer(level.zone);

    std::map<PairKey, Witness> missing;
    std::mutex lock;
    std::thread other(sample_cells, std::cref(level), std::cref(tracer), points, directions, 1u, 2u, std::ref(lock),
                      std::ref(missing));
    sample_cells(level, tracer, points, directions, 0, 2, lock, missing);
    other.join();
    std::printf("%zu (cell, object) pairs seen from open space that the file lacks (%u points a cell, %u rays each)\n",
                missing.size(), points, directions);

    const Viewer viewer{level, tracer};
    const float unit = level.grid->grid_size, near = kBakerNear * unit;
    const std::array<glm::vec3, 6> axes{{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
    std::map<std::string, int> classes;
    std::map<std::string, std::map<uint32_t, int>> class_objects; // per class: object -> pairs
    std::mt19937_64 rng(5);
    int gaps_near_face = 0, gaps_near_min_face = 0;
    for (const auto& [key, witness] : missing) {
        const auto [cell, object] = key;
        const std::vector<glm::vec3> targets = object_targets(level.zone, object, rng);
        const std::vector<glm::vec3> lattice = baker_points(*level.grid, cell);
        int pixels = -1, clear = 0;
        for (size_t i = 0; i < lattice.size() && pixels < 0; ++i)
            for (const glm::vec3& axis : axes) {
                const glm::vec3 eye = lattice[i] + axis * unit, look = -axis;
                if (viewer.sees(eye, targets, object, &look, near)) {
                    pixels = viewer.pixel_hits(eye, look, targets, object, near, clear);
                    break;
                }
            }
        std::string name;
        if (pixels > 0 && clear == 0)
            name = "1a. seen from a baker eye only where another object's face is coplanar (depth fight)";
        else if (pixels > 0)
            name = "1. seen from a baker eye through its pixel centres (" +
                   std::string(pixels <= 4 ? "1-4" : pixels <= 16 ? "5-16" : "over 16") + " pixels)";
        else if (pixels == 0)
            name = "2. seen from a baker eye only between its pixel centres";
        else if (std::any_of(lattice.begin(), lattice.end(),
                             [&](const glm::vec3& q) { return viewer.sees(q, targets, object, nullptr, 0.0f); }))
            name = "3. seen from a lattice point, not from its offset eyes";
        else {
            name = "4. seen from no lattice point (sampling gap)";
            const auto [face, distance] = nearest_cell_face(*level.grid, cell, witness.point);
            gaps_near_face += distance < 0.5f ? 1 : 0;
            gaps_near_min_face += distance < 0.5f && face % 2 == 0 ? 1 : 0;
        }
        ++class_objects[name][object];
        if (++classes[name] <= 2)
            std::printf("  e.g. %s: cell %u object %u, witness (%.1f %.1f %.1f) looking (%.2f %.2f %.2f)\n", name.c_str(),
                        cell, object, double(witness.point.x), double(witness.point.y), double(witness.point.z),
                        double(witness.direction.x), double(witness.direction.y), double(witness.direction.z));
    }
    for (const auto& [name, count] : classes) {
        std::vector<std::pair<int, uint32_t>> objects;
        for (const auto& [object, pairs] : class_objects[name])
            objects.push_back({pairs, object});
        std::sort(objects.rbegin(), objects.rend());
        std::printf("%6d  %s: %zu objects, most:", count, name.c_str(), objects.size());
        for (size_t i = 0; i < objects.size() && i < 5; ++i)
            std::printf(" %s (%d)", level.zone.region_names.size() > objects[i].second
                                        ? level.zone.region_names[objects[i].second].c_str()
                                        : std::to_string(objects[i].second).c_str(),
                        objects[i].first);
        std::printf("\n");
    }
    std::printf("sampling gaps: %d of %d witnesses within half a grid unit of a cell face, %d of them a min face "
                "(where the lattice has no layer)\n",
                gaps_near_face, classes["4. seen from no lattice point (sampling gap)"], gaps_near_min_face);
    return 0;
}
