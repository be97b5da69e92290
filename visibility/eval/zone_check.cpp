#include "visibility/eval/zone_check.h"

#include "visibility/bit_row.h"
#include "visibility/portal/portalize.h"

#include <cmath>
#include <cstdio>

namespace pvs {

namespace {

std::string format(const char* pattern, auto... values)
{
    char text[256];
    std::snprintf(text, sizeof text, pattern, values...);
    return text;
}

struct ItemBuilder {
    CheckItem item;
    size_t max_examples;

    ItemBuilder(std::string name, CheckSeverity severity, size_t max) : max_examples(max)
    {
        item.name = std::move(name);
        item.severity = severity;
    }
    void fail(const std::string& example, const CheckPlace& place = {})
    {
        ++item.failed;
        if (item.examples.size() < max_examples) {
            item.examples.push_back(example);
            item.places.push_back(place);
        }
    }
    CheckItem done(std::string summary)
    {
        item.summary = std::move(summary);
        return std::move(item);
    }
};

CheckItem not_applicable(const char* name, CheckSeverity severity, const char* why)
{
    CheckItem item;
    item.name = name;
    item.severity = severity;
    item.applicable = false;
    item.summary = why;
    return item;
}

bool plane_ok(const BspNode& node)
{
    const double length = std::sqrt(double(node.normal.x) * node.normal.x + double(node.normal.y) * node.normal.y +
                                     double(node.normal.z) * node.normal.z);
    return std::isfinite(length) && std::isfinite(node.dist) && std::abs(length - 1.0) <= 1e-3;
}

// The tree from its root: every child in range, no node twice, planes and leaves valid; which
// regions some reached leaf names.
void check_tree(const Zone& zone, const CheckOptions& options, std::vector<CheckItem>& items)
{
    const BspTree& tree = zone.tree;
    ItemBuilder b("tree", CheckSeverity::Error, options.max_examples);
    const int32_t region_count = int32_t(zone.regions.size());
    std::vector<uint8_t> reached(tree.nodes.size(), 0);
    std::vector<uint8_t> region_named(zone.regions.size(), 0);
    std::vector<int32_t> stack{tree.root};
    const auto visit_leaf = [&](int32_t leaf) {
        ++b.item.checked;
        if (leaf < 0 || size_t(leaf) >= tree.leaf_region.size()) {
            b.fail(format("leaf %d out of range (%zu leaves)", leaf, tree.leaf_region.size()));
            return;
        }
        const int32_t region = tree.leaf_region[size_t(leaf)];
        if (region >= 0 && region < region_count)
            region_named[size_t(region)] = 1;
        else if (region != kLeafSolid && region != kLeafOutside)
            b.fail(format("leaf %d names region %d (%d regions)", leaf, region, region_count));
    };
    while (!stack.empty()) {
        const int32_t child = stack.back();
        stack.pop_back();
        if (BspTree::is_leaf(child)) {
            visit_leaf(BspTree::leaf_index(child));
            continue;
        }
        ++b.item.checked;
        if (size_t(child) >= tree.nodes.size()) {
            b.fail(format("node %d out of range (%zu nodes)", child, tree.nodes.size()));
            continue;
        }
        if (reached[size_t(child)]++) {
            b.fail(format("node %d reached twice from the root (a cycle or a shared subtree)", child));
            continue;
        }
        const BspNode& node = tree.nodes[size_t(child)];
        if (!plane_ok(node))
            b.fail(format("node %d: plane (%g, %g, %g) %g is not finite with a unit normal", child, double(node.normal.x),
                          double(node.normal.y), double(node.normal.z), double(node.dist)));
        stack.push_back(node.children[1]);
        stack.push_back(node.children[0]);
    }
    size_t unreached = 0;
    for (uint8_t r : reached)
        unreached += r == 0;
    items.push_back(b.done(format("%zu nodes and leaves reached from the root; %zu nodes not reached%s", b.item.checked,
                                  unreached, unreached ? " (other models' trees, or unused)" : "")));

    ItemBuilder r("tree_regions", CheckSeverity::Warning, options.max_examples);
    for (size_t i = 0; i < region_named.size(); ++i) {
        ++r.item.checked;
        if (!region_named[i])
            r.fail(format("region %zu", i), {int32_t(i)});
    }
    items.push_back(r.done(format("%zu of %zu regions have no leaf in the tree", r.item.failed,
                                  zone.regions.size())));
}

std::string crossing_example(const BlockedCrossing& c)
{
    return format("portal %u (regions %d | %d) at (%.3f, %.3f, %.3f): blocked at (%.3f, %.3f, %.3f)", c.portal, c.regions[0],
                  c.regions[1], c.centre.x, c.centre.y, c.centre.z, c.blocked_at.x, c.blocked_at.y, c.blocked_at.z);
}

void add_crossings(const char* label, const CrossingReport& report, ItemBuilder& b)
{
    b.item.checked += report.traced;
    for (const BlockedCrossing& c : report.blocked)
        b.fail(std::string(label) + " " + crossing_example(c), {c.regions[0], c.regions[1], true, glm::vec3(c.centre)});
}

void check_portals(const Zone& zone, const CheckOptions& options, ZoneHealth& health, const PortalSet& built,
                   const PortalStats& stats)
{
    health.tree_crossings = trace_portal_crossings(zone, built, options.sky, options.crossing_half_length);
    if (zone.portals)
        health.file_crossings = trace_portal_crossings(zone, *zone.portals, options.sky, options.crossing_half_length);
    ItemBuilder b("portal_crossings", CheckSeverity::Error, options.max_examples);
    add_crossings("tree", health.tree_crossings, b);
    add_crossings("file", health.file_crossings, b);
    const CrossingReport& t = health.tree_crossings;
    std::string summary = format("%zu of %zu crossings of the tree's %zu portals blocked (%zu unplaced, %zu opaque)",
                                 t.blocked.size(), t.traced, t.portals, t.unplaced, t.opaque);
    if (zone.portals) {
        const CrossingReport& f = health.file_crossings;
        summary += format("; %zu of %zu of the file's %zu portals", f.blocked.size(), f.traced, f.portals);
    }
    health.items.push_back(b.done(summary));

    ItemBuilder leaks("leaks", CheckSeverity::Warning, options.max_examples);
    for (int32_t leaf : stats.leaves_touching_world) {
        const int32_t region = zone.tree.leaf_region[size_t(leaf)];
        health.leak_regions.push_back(region);
        const Aabb& box = zone.regions[size_t(region)].bounds;
        leaks.fail(format("leaf %d (region %d, bounds (%g, %g, %g) .. (%g, %g, %g)) reaches the world box", leaf,
                          region, double(box.min.x), double(box.min.y), double(box.min.z), double(box.max.x),
                          double(box.max.y), double(box.max.z)),
                   {region, -1, true, box.center()});
    }
    leaks.item.checked = zone.regions.size();
    health.items.push_back(leaks.done(format("%zu open leaves reach the world box", stats.leaves_touching_world.size())));

    ItemBuilder outside("outside", CheckSeverity::Note, options.max_examples);
    for (int32_t leaf : stats.leaves_touching_outside)
        outside.fail(format("leaf %d (region %d)", leaf, zone.tree.leaf_region[size_t(leaf)]),
                     {zone.tree.leaf_region[size_t(leaf)]});
    outside.item.checked = zone.regions.size();
    health.items.push_back(outside.done(format("%zu open leaves share a face with an outside leaf",
                                               stats.leaves_touching_outside.size())));
}

void check_faces(const Zone& zone, const CheckOptions& options, std::vector<CheckItem>& items)
{
    ItemBuilder b("faces", CheckSeverity::Note, options.max_examples);
    const bool offsets_ok = zone.region_face_offsets.size() == zone.regions.size() + 1;
    for (uint32_t r = 0; r < zone.regions.size(); ++r) {
        ++b.item.checked;
        if (!offsets_ok || zone.faces_of_region(r).empty())
            b.fail(format("region %u", r), {int32_t(r)});
    }
    items.push_back(b.done(format("%zu of %zu regions list no face", b.item.failed, zone.regions.size())));
}

// The PVS's rows against the regions: row count and width, then (square PVS) self, neighbours
// across the tree's portals and symmetry.
void check_pvs(const Zone& zone, const CheckOptions& options, const PortalSet* built, std::vector<CheckItem>& items)
{
    if (!zone.baked_pvs) {
        for (const char* name : {"pvs_rows", "pvs_self", "pvs_neighbours", "pvs_sky_neighbours", "pvs_symmetry"})
            items.push_back(not_applicable(name, CheckSeverity::Note, "the zone has no PVS"));
        return;
    }
    const Pvs& pvs = *zone.baked_pvs;
    const uint32_t regions = uint32_t(zone.regions.size());
    const uint64_t rows_expected = zone.view_grid ? zone.view_grid->cell_count() : regions;
    ItemBuilder rows("pvs_rows", CheckSeverity::Error, options.max_examples);
    rows.item.checked = 1;
    if (pvs.row_count() != rows_expected || pvs.region_count() != regions)
        rows.fail(format("%u rows of %u bits for %zu %s of %u regions", pvs.row_count(), pvs.region_count(),
                         rows_expected, zone.view_grid ? "cells" : "rows", regions));
    items.push_back(rows.done(format("%u rows of %u bits, %u missing (read as all visible)", pvs.row_count(),
                                     pvs.region_count(), pvs.missing_row_count())));
    if (!rows.item.passed() || zone.view_grid) {
        const char* why = zone.view_grid ? "a grid PVS: rows are cells, not regions" : "the rows do not match the regions";
        for (const char* name : {"pvs_self", "pvs_neighbours", "pvs_sky_neighbours", "pvs_symmetry"})
            items.push_back(not_applicable(name, CheckSeverity::Note, why));
        return;
    }
    const size_t words = pvs.words_per_row();
    const bool keep_matrix = regions <= kSymmetryMaxRegions;
    std::vector<uint64_t> matrix(keep_matrix ? size_t(regions) * words : words);
    ItemBuilder self("pvs_self", CheckSeverity::Warning, options.max_examples);
    for (uint32_t r = 0; r < regions; ++r) {
        const std::span<uint64_t> row(matrix.data() + (keep_matrix ? size_t(r) * words : 0), words);
        pvs.decode_row(r, row);
        ++self.item.checked;
        if (!bits::test(row, r))
            self.fail(format("region %u", r), {int32_t(r)});
    }
    items.push_back(self.done(format("%zu of %u rows lack their own region", self.item.failed, regions)));
    if (!keep_matrix) {
        items.push_back(not_applicable("pvs_neighbours", CheckSeverity::Warning, "more regions than the check holds"));
        items.push_back(not_applicable("pvs_sky_neighbours", CheckSeverity::Note, "more regions than the check holds"));
        items.push_back(not_applicable("pvs_symmetry", CheckSeverity::Note, "more regions than the check holds"));
        return;
    }
    const auto sees = [&](uint32_t a, uint32_t b) { return bits::test(std::span<const uint64_t>(matrix.data() + size_t(a) * words, words), b); };
    if (built) {
        // Pairs at a sky region apart: vis tools differ on sky (id's vis saw none through it).
        ItemBuilder n("pvs_neighbours", CheckSeverity::Warning, options.max_examples);
        ItemBuilder sky("pvs_sky_neighbours", CheckSeverity::Note, options.max_examples);
        for (const Portal& p : built->portals) {
            const uint32_t a = uint32_t(p.regions[0]), b = uint32_t(p.regions[1]);
            const bool at_sky = ((zone.regions[a].flags | zone.regions[b].flags) & kRegionSky) != 0;
            ItemBuilder& item = at_sky ? sky : n;
            for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
                ++item.item.checked;
                if (!pvs.row_missing(from) && !sees(from, to))
                    item.fail(format("%u -> %u", from, to), {int32_t(from), int32_t(to)});
            }
        }
        items.push_back(n.done(format("%zu of %zu directed portal neighbours missing from the rows",
                                      n.item.failed, n.item.checked)));
        items.push_back(sky.done(format("%zu of %zu directed neighbours at sky regions missing (a PVS made as id's vis made it, bake --sky none, sees none through sky)",
                                        sky.item.failed, sky.item.checked)));
    } else
        for (const char* name : {"pvs_neighbours", "pvs_sky_neighbours"})
            items.push_back(not_applicable(name, CheckSeverity::Note, "the zone has no tree to build portals from"));
    ItemBuilder sym("pvs_symmetry", CheckSeverity::Note, options.max_examples);
    for (uint32_t a = 0; a < regions; ++a)
        bits::for_each_set(std::span<const uint64_t>(matrix.data() + size_t(a) * words, words), [&](size_t b) {
            ++sym.item.checked;
            if (b < regions && !sees(uint32_t(b), a))
                sym.fail(format("%u -> %zu", a, b), {int32_t(a), int32_t(b)});
        });
    items.push_back(sym.done(format("%zu of %zu set bits have no reverse bit", sym.item.failed,
                                    sym.item.checked)));
}

} // namespace

const char* check_severity_name(CheckSeverity severity)
{
    switch (severity) {
    case CheckSeverity::Note: return "note";
    case CheckSeverity::Warning: return "warning";
    case CheckSeverity::Error: return "error";
    }
    return "?";
}

size_t ZoneHealth::count(CheckSeverity severity) const
{
    size_t n = 0;
    for (const CheckItem& item : items)
        n += item.severity == severity && !item.passed();
    return n;
}

const CheckItem* ZoneHealth::item(const std::string& name) const
{
    for (const CheckItem& item : items)
        if (item.name == name)
            return &item;
    return nullptr;
}

ZoneHealth check_zone(const Zone& zone, const CheckOptions& options)
{
    ZoneHealth health;
    PortalSet built;
    const bool has_tree = zone.tree.exists() && !zone.view_grid;
    if (has_tree) {
        check_tree(zone, options, health.items);
        const bool tree_sound = health.items.front().passed();
        if (tree_sound) {
            PortalOptions portal_options;
            portal_options.sky = options.sky;
            PortalStats stats;
            built = build_zone_portals(zone, portal_options, &stats);
            check_portals(zone, options, health, built, stats);
        } else {
            for (const char* name : {"portal_crossings", "leaks", "outside"})
                health.items.push_back(not_applicable(name, CheckSeverity::Warning, "the tree is broken: not portalized"));
        }
    } else {
        for (const char* name : {"tree", "tree_regions", "portal_crossings", "leaks", "outside"})
            health.items.push_back(not_applicable(name, CheckSeverity::Note, "the zone has no BSP tree"));
    }
    check_faces(zone, options, health.items);
    const bool portals_usable = has_tree && health.items.front().passed();
    check_pvs(zone, options, portals_usable ? &built : nullptr, health.items);
    return health;
}

} // namespace pvs
