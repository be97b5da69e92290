#include "report/region_report.h"

#include "visibility/bit_row.h"
#include "visibility/portal/portalize.h"

#include <algorithm>
#include <string>

namespace pvs {

namespace {

void count_visibility(const Zone& zone, std::vector<RegionRow>& rows)
{
    if (!zone.baked_pvs)
        return;
    const Pvs& pvs = *zone.baked_pvs;
    if (pvs.region_count() != rows.size())
        return; // a PVS over something else: nothing to say per region
    for (RegionRow& row : rows)
        row.visible_from = 0;
    std::vector<uint64_t> words(pvs.words_per_row());
    for (uint32_t r = 0; r < pvs.row_count(); ++r) {
        pvs.decode_row(r, words);
        if (pvs.square())
            rows[r].visible = int64_t(bits::count(words));
        bits::for_each_set(words, [&](size_t region) {
            if (region < rows.size())
                ++rows[region].visible_from;
        });
    }
}

void count_neighbours(const Zone& zone, std::vector<RegionRow>& rows)
{
    if (!zone.portals && !zone.tree.exists())
        return;
    const PortalSet built = zone.portals ? PortalSet{} : build_zone_portals(zone);
    const PortalSet& set = zone.portals ? *zone.portals : built;
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (const Portal& p : set.portals) {
        const int32_t a = p.regions[0], b = p.regions[1];
        if (a < 0 || b < 0 || a == b || size_t(a) >= rows.size() || size_t(b) >= rows.size())
            continue;
        pairs.emplace_back(uint32_t(a), uint32_t(b));
        pairs.emplace_back(uint32_t(b), uint32_t(a));
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    for (RegionRow& row : rows)
        row.portal_neighbours = 0;
    for (const auto& [from, to] : pairs)
        ++rows[from].portal_neighbours;
}

std::string flag_list(uint32_t flags)
{
    std::string out;
    for (uint32_t bit = 0; bit < kRegionFlagCount; ++bit)
        if (flags & (1u << bit)) {
            if (!out.empty())
                out += '|';
            out += region_flag_name(1u << bit);
        }
    return out;
}

std::string count_cell(int64_t value) { return value < 0 ? std::string() : std::to_string(value); }

std::string number(float v)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(v));
    return text;
}

} // namespace

std::vector<RegionRow> region_rows(const Zone& zone)
{
    std::vector<RegionRow> rows(zone.region_count());
    for (uint32_t r = 0; r < rows.size(); ++r) {
        RegionRow& row = rows[r];
        row.region = r;
        row.flags = zone.regions[r].flags;
        row.bounds = zone.regions[r].bounds;
        if (r + 1 < zone.region_face_offsets.size()) {
            for (uint32_t face : zone.faces_of_region(r)) {
                ++row.faces;
                row.triangles += zone.mesh.faces[face].triangle_count;
            }
        }
    }
    count_visibility(zone, rows);
    count_neighbours(zone, rows);
    return rows;
}

CsvFields region_fields(const Zone& zone, const RegionRow& row)
{
    CsvFields f;
    f.emplace_back("region", std::to_string(row.region));
    if (!zone.region_names.empty())
        f.emplace_back("name", csv_cell(row.region < zone.region_names.size() ? zone.region_names[row.region] : ""));
    f.emplace_back("flags", csv_cell(flag_list(row.flags)));
    const bool has_bounds = !row.bounds.empty();
    const char* axes[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
        f.emplace_back(std::string("min_") + axes[a], has_bounds ? number(row.bounds.min[a]) : "");
    for (int a = 0; a < 3; ++a)
        f.emplace_back(std::string("max_") + axes[a], has_bounds ? number(row.bounds.max[a]) : "");
    f.emplace_back("faces", std::to_string(row.faces));
    f.emplace_back("triangles", std::to_string(row.triangles));
    f.emplace_back("visible", count_cell(row.visible));
    f.emplace_back("visible_from", count_cell(row.visible_from));
    f.emplace_back("portal_neighbours", count_cell(row.portal_neighbours));
    return f;
}

} // namespace pvs
