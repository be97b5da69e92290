#include "wld/hepvs/hepvs_zone.h"

#include "visibility/bit_row.h"
#include "visibility/file_error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <unordered_map>

namespace pvs {

void attach_hepvs(Zone& zone, const HepvsFile& hepvs, const std::string& hepvs_path, float grid_size)
{
    if (zone.region_names.size() != zone.region_count())
        throw FileError(hepvs_path, 0, "the zone it is attached to has no object names to match");
    std::unordered_map<std::string, uint32_t> region_of;
    for (uint32_t r = 0; r < zone.region_count(); ++r)
        region_of.try_emplace(zone.region_names[r], r); // the first object of a name wins
    std::vector<int64_t> column(hepvs.names.size(), -1);
    size_t unknown = 0;
    for (size_t i = 0; i < hepvs.names.size(); ++i) {
        const auto it = region_of.find(hepvs.names[i]);
        if (it != region_of.end())
            column[i] = it->second;
        else
            ++unknown;
    }
    if (!hepvs.names.empty() && unknown == hepvs.names.size())
        throw FileError(hepvs_path, kHepvsHeaderBytes, "none of its " + std::to_string(hepvs.names.size()) +
                                                           " object names is an object of " + zone.source.path);
    ViewGrid grid;
    grid.min = hepvs.min;
    grid.cell_size = hepvs.cell_size;
    grid.counts = hepvs.counts;
    grid.grid_size = grid_size;
    zone.baked_pvs = Pvs::build_rows(uint32_t(hepvs.cell_count()), uint32_t(zone.region_count()),
                                     [&](uint32_t cell, std::span<uint64_t> row) {
                                         for (uint16_t index : hepvs.cell(cell))
                                             if (column[index] >= 0)
                                                 bits::set(row, size_t(column[index]));
                                         return true;
                                     });
    zone.view_grid = grid;
    char note[320];
    std::snprintf(note, sizeof note, "PVS from %s (HateEngine .hepvs, version %u): %u x %u x %u cells of %g grid units, %g OBJ units to a grid unit",
                  hepvs_path.c_str(), hepvs.version, hepvs.counts.x, hepvs.counts.y, hepvs.counts.z,
                  double(hepvs.cell_size), double(grid_size));
    zone.source.notes.push_back(note);
    if (unknown > 0)
        zone.source.notes.push_back(std::to_string(unknown) + " of its object names are not in the OBJ (ignored)");
    std::vector<uint8_t> named(zone.region_count(), 0);
    for (const int64_t r : column)
        if (r >= 0)
            named[size_t(r)] = 1;
    const size_t unnamed = size_t(std::count(named.begin(), named.end(), uint8_t{0}));
    if (unnamed > 0)
        zone.source.notes.push_back("warning: " + std::to_string(unnamed) + " of the OBJ's " +
                                    std::to_string(zone.region_count()) + " objects are not in " + hepvs_path +
                                    ": no cell sees them, so the culler never draws them (a .hepvs of another "
                                    "version of the level?)");
    for (const std::string& w : hepvs.warnings)
        zone.source.notes.push_back(hepvs_path + ": " + w);
}

HepvsFile hepvs_from_zone(const Zone& zone)
{
    if (!zone.view_grid || !zone.baked_pvs || zone.baked_pvs->row_count() != zone.view_grid->cell_count() ||
        zone.baked_pvs->region_count() != zone.region_count())
        throw std::invalid_argument(".hepvs: the zone has no view grid with one PVS row per cell");
    if (zone.region_names.size() != zone.region_count())
        throw std::invalid_argument(".hepvs: the zone's objects have no names");
    if (zone.region_count() > 0xffff)
        throw std::invalid_argument(".hepvs: more than 65535 objects");
    HepvsFile h;
    h.min = zone.view_grid->min;
    h.cell_size = zone.view_grid->cell_size;
    h.counts = zone.view_grid->counts;
    h.names = zone.region_names;
    h.cell_offsets.push_back(0);
    std::vector<uint64_t> row(zone.baked_pvs->words_per_row());
    for (uint32_t c = 0; c < zone.baked_pvs->row_count(); ++c) {
        zone.baked_pvs->decode_row(c, row);
        bits::for_each_set(row, [&](size_t r) {
            if (r < zone.region_count())
                h.cell_objects.push_back(uint16_t(r));
        });
        h.cell_offsets.push_back(uint32_t(h.cell_objects.size()));
    }
    return h;
}

HepvsFile hepvs_over_regions(const Zone& zone, float cell_size, float grid_size)
{
    if (!zone.baked_pvs || !zone.baked_pvs->square() || zone.baked_pvs->region_count() != zone.region_count() ||
        zone.view_grid)
        throw std::invalid_argument(".hepvs: the zone has no PVS over its regions");
    if (!(cell_size > 0.0f) || !(grid_size > 0.0f) || zone.mesh.positions.empty())
        throw std::invalid_argument(".hepvs: a positive cell size and grid size, and some geometry, are needed");
    if (zone.region_count() > 0xffff)
        throw std::invalid_argument(".hepvs: more than 65535 objects");
    const std::optional<ViewGrid> made = grid_over_points(zone.mesh.positions, cell_size, grid_size);
    if (!made)
        throw std::invalid_argument(".hepvs: the grid needs 1 to 65535 cells a side");
    const ViewGrid& grid = *made;
    const size_t words = zone.baked_pvs->words_per_row();
    std::vector<uint64_t> cells(grid.cell_count() * words, 0), row(words);
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        zone.baked_pvs->decode_row(r, row);
        bits::set(row, r); // the camera's own region is drawn
        Aabb g; // the region's box in grid space
        g.grow(grid.to_grid_space(zone.regions[r].bounds.min));
        g.grow(grid.to_grid_space(zone.regions[r].bounds.max));
        glm::uvec3 lo, hi;
        for (int a = 0; a < 3; ++a) {
            const float first = std::floor((g.min[a] - grid.min[a]) / cell_size);
            const float last = std::floor((g.max[a] - grid.min[a]) / cell_size);
            lo[a] = uint32_t(std::clamp(first, 0.0f, float(grid.counts[a] - 1)));
            hi[a] = uint32_t(std::clamp(last, 0.0f, float(grid.counts[a] - 1)));
        }
        for (uint32_t x = lo.x; x <= hi.x; ++x)
            for (uint32_t y = lo.y; y <= hi.y; ++y)
                for (uint32_t z = lo.z; z <= hi.z; ++z) {
                    uint64_t* cell = cells.data() + size_t(grid.index(x, y, z)) * words;
                    for (size_t w = 0; w < words; ++w)
                        cell[w] |= row[w];
                }
    }
    HepvsFile h;
    h.min = grid.min;
    h.cell_size = cell_size;
    h.counts = grid.counts;
    for (uint32_t r = 0; r < zone.region_count(); ++r)
        h.names.push_back(r < zone.region_names.size() ? zone.region_names[r] : "region_" + std::to_string(r));
    h.cell_offsets.push_back(0);
    for (uint64_t c = 0; c < grid.cell_count(); ++c) {
        bits::for_each_set(std::span<const uint64_t>(cells.data() + c * words, words), [&](size_t r) {
            if (r < zone.region_count())
                h.cell_objects.push_back(uint16_t(r));
        });
        h.cell_offsets.push_back(uint32_t(h.cell_objects.size()));
    }
    return h;
}

} // namespace pvs
