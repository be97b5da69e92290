// Procedural outdoor zones (terrain_level.h).
#include "gen/terrain_level.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace pvs::gen {

namespace {

struct Builder {
    VoxelLevel& level;
    std::mt19937_64& rng;
    int n, top;
    std::vector<int> ground; // first open z per column

    int& ground_at(int x, int y) { return ground[size_t(y) * size_t(n) + size_t(x)]; }
    // A seeded integer in [lo, hi]; lo when the range is empty (small zones squeeze the ranges).
    int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, std::max(lo, hi))(rng); }
    double real(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

    // Rolling hills: a base plus seeded Gaussian bumps, and a ridge across the middle that
    // separates the two halves but for a pass, so that valleys hide each other.
    void heightfield()
    {
        const double base = 3.0, peak = top - 4.0;
        struct Bump { double x, y, r, h; };
        std::vector<Bump> bumps;
        for (int i = 0; i < std::max(8, n / 4); ++i)
            bumps.push_back({real(0, n), real(0, n), real(n * 0.06, n * 0.16), real(2.0, peak - base)});
        const double pass = real(n * 0.3, n * 0.7);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                double h = base;
                for (const Bump& b : bumps)
                    h += b.h * std::exp(-((x - b.x) * (x - b.x) + (y - b.y) * (y - b.y)) / (b.r * b.r));
                const double ridge = (peak - base) * std::exp(-std::pow((x - n * 0.5) / (n * 0.04), 2.0));
                const double gap = 1.0 - std::exp(-std::pow((y - pass) / (n * 0.06), 2.0));
                h = std::max(h, base + ridge * gap);
                ground_at(x, y) = std::clamp(int(std::lround(h)), 1, top - 4);
            }
    }

    void flatten(int x0, int y0, int x1, int y1, int z)
    {
        for (int y = std::max(y0, 0); y < std::min(y1, n); ++y)
            for (int x = std::max(x0, 0); x < std::min(x1, n); ++x)
                ground_at(x, y) = z;
    }

    // Solid below the ground, air above it, in the columns x0 <= x < x1, y0 <= y < y1.
    void fill_columns(int x0, int y0, int x1, int y1)
    {
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                for (int z = 0; z < level.dims.z; ++z)
                    level.set(x, y, z, z < ground_at(x, y) ? Cell::Solid : Cell::Air);
    }

    // A bowl dug into the ground and filled with `liquid` up to `surface` (exclusive).
    void pool(glm::ivec2 c, int radius, int floor, int surface, Cell liquid)
    {
        for (int y = c.y - radius; y <= c.y + radius; ++y)
            for (int x = c.x - radius; x <= c.x + radius; ++x) {
                if (x < 1 || y < 1 || x >= n - 1 || y >= n - 1)
                    continue;
                const double d = std::hypot(x - c.x, y - c.y) / radius;
                if (d > 1.0)
                    continue;
                const int bottom = std::max(1, floor + int(std::lround(d * (surface - floor))));
                ground_at(x, y) = std::min(ground_at(x, y), bottom);
                for (int z = 0; z < level.dims.z; ++z)
                    level.set(x, y, z, z < ground_at(x, y) ? Cell::Solid : z < surface ? liquid : Cell::Air);
            }
    }

    // A walled town on flattened ground: a wall ring three cells high with a gate, hollow
    // buildings (walls, a roof, a door) inside.
    void town(TerrainFeatures& f)
    {
        const int side = std::max(10, n / 4);
        const int x0 = uniform(2, n / 2 - side - 2), y0 = uniform(2, n - side - 2);
        int z = 0;
        for (int y = y0; y < y0 + side; ++y)
            for (int x = x0; x < x0 + side; ++x)
                z = std::max(z, ground_at(x, y));
        z = std::min(z, top - 7);
        flatten(x0, y0, x0 + side, y0 + side, z);
        fill_columns(x0, y0, x0 + side, y0 + side);
        const int gate = y0 + side / 2;
        for (int i = 0; i < side; ++i)
            for (int h = 0; h < 3; ++h) {
                level.set(x0 + i, y0, z + h, Cell::Solid);
                level.set(x0 + i, y0 + side - 1, z + h, Cell::Solid);
                level.set(x0, y0 + i, z + h, Cell::Solid);
                if (std::abs(y0 + i - gate) > 0)
                    level.set(x0 + side - 1, y0 + i, z + h, Cell::Solid);
            }
        f.town_lo = {x0 + 1, y0 + 1, z};
        f.town_hi = {x0 + side - 1, y0 + side - 1, z + 3};
        // Buildings on a lattice inside the walls: 4x4 cells outside, 2x2x2 hollow inside.
        for (int by = y0 + 2; by + 4 <= y0 + side - 2; by += 6)
            for (int bx = x0 + 2; bx + 4 <= x0 + side - 2; bx += 6) {
                for (int y = by; y < by + 4; ++y)
                    for (int x = bx; x < bx + 4; ++x)
                        for (int h = 0; h < 4; ++h) {
                            const bool inside = x > bx && x < bx + 3 && y > by && y < by + 3 && h < 3;
                            level.set(x, y, z + h, inside ? Cell::Air : Cell::Solid);
                        }
                level.set(bx + 1, by, z, Cell::Air); // the door
                ++f.buildings;
            }
    }

    // A deck of solid cells across the lake, one cell thick, with open water and air below.
    void bridge(TerrainFeatures& f)
    {
        const int z = f.water_level + 2;
        f.bridge_z = z;
        for (int x = f.lake_center.x - f.lake_radius - 1; x <= f.lake_center.x + f.lake_radius + 1; ++x)
            for (int y = f.lake_center.y - 1; y <= f.lake_center.y; ++y)
                if (x >= 0 && x < n && z < level.dims.z && level.at(x, y, z) != Cell::Solid)
                    level.set(x, y, z, Cell::Solid);
    }

    // An overhang: a slab of rock two cells above the ground over a few columns.
    void arch(TerrainFeatures& f)
    {
        const int x0 = std::min(uniform(n / 2 + 4, n - 10), n - 6), y0 = std::min(uniform(4, n - 10), n - 6);
        int z = 0;
        for (int y = y0; y < y0 + 5; ++y)
            for (int x = x0; x < x0 + 5; ++x)
                z = std::max(z, ground_at(x, y));
        z = std::min(z + 2, top - 2);
        for (int y = y0; y < y0 + 5; ++y)
            for (int x = x0; x < x0 + 5; ++x)
                level.set(x, y, z, Cell::Solid);
        f.arch_lo = {x0, y0, 0};
        f.arch_hi = {x0 + 5, y0 + 5, z};
    }

    // Zone lines: the open cells next to the ground along the x = 0 and x = n-1 edges.
    void zone_lines()
    {
        for (int x : {0, n - 1})
            for (int y = n / 4; y < 3 * n / 4; ++y)
                for (int z = ground_at(x, y); z < std::min(ground_at(x, y) + 2, level.dims.z); ++z)
                    if (level.at(x, y, z) == Cell::Air)
                        level.set(x, y, z, Cell::ZoneLine);
    }
};

} // namespace

VoxelLevel make_terrain_level(const TerrainParams& params, TerrainFeatures* features)
{
    if (params.columns < kMinTerrainColumns || params.columns > kMaxTerrainColumns)
        throw std::invalid_argument("outdoor zone: " + std::to_string(params.columns) + " columns is outside " +
                                    std::to_string(kMinTerrainColumns) + ".." + std::to_string(kMaxTerrainColumns));
    if (params.height < kMinTerrainHeight || params.height > kMaxTerrainHeight)
        throw std::invalid_argument("outdoor zone: " + std::to_string(params.height) + " cells high is outside " +
                                    std::to_string(kMinTerrainHeight) + ".." + std::to_string(kMaxTerrainHeight));
    VoxelLevel level;
    const int n = params.columns;
    level.dims = {n, n, params.height};
    level.cells.assign(size_t(n) * size_t(n) * size_t(params.height), Cell::Solid);
    std::mt19937_64 rng(params.seed);
    Builder b{level, rng, n, params.height, std::vector<int>(size_t(n) * size_t(n), 1)};
    TerrainFeatures f;
    b.heightfield();
    b.fill_columns(0, 0, n, n);
    b.town(f); // flattens its ground and refills those columns
    f.lake_radius = std::max(3, n / 12);
    f.lake_center = {b.uniform(n / 2 + f.lake_radius + 3, n - f.lake_radius - 3),
                     b.uniform(f.lake_radius + 3, n - f.lake_radius - 3)};
    f.water_level = std::min(b.ground_at(f.lake_center.x, f.lake_center.y), params.height - 6) + 1;
    b.pool(f.lake_center, f.lake_radius, std::max(1, f.water_level - 3), f.water_level, Cell::Water);
    b.bridge(f);
    // The lava pit lies outside the town's walls (a few tries; the last one is kept).
    for (int tries = 0; tries < 64; ++tries) {
        f.lava_center = {b.uniform(3, n / 2 - 5), b.uniform(3, n - 5)};
        if (f.lava_center.x < f.town_lo.x - 5 || f.lava_center.x > f.town_hi.x + 4 ||
            f.lava_center.y < f.town_lo.y - 5 || f.lava_center.y > f.town_hi.y + 4)
            break;
    }
    const int lava_surface = b.ground_at(f.lava_center.x, f.lava_center.y);
    b.pool(f.lava_center, 2, std::max(1, lava_surface - 2), lava_surface, Cell::Lava);
    b.arch(f);
    b.zone_lines();
    f.ground = b.ground;
    if (features)
        *features = std::move(f);
    return level;
}

} // namespace pvs::gen
