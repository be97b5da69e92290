#include "visibility/reference/region_sampler.h"

#include "visibility/geometry/bsp_volume.h"
#include "visibility/portal/portalize.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace pvs {

namespace {

// Fan tetrahedra of one convex cell, appended to `out` (degenerate ones are skipped).
template <class Tet>
void cell_tetrahedra(const ConvexCell& cell, std::vector<Tet>& out, std::vector<double>& volumes)
{
    glm::dvec3 centre(0.0);
    size_t count = 0;
    for (const Winding& face : cell.faces)
        for (const glm::vec3& p : face.points) {
            centre += glm::dvec3(p);
            ++count;
        }
    if (count == 0)
        return;
    centre /= double(count);
    for (const Winding& face : cell.faces) {
        if (face.size() < 3)
            continue;
        const glm::dvec3 p0(face.points[0]);
        for (size_t i = 1; i + 1 < face.size(); ++i) {
            const glm::dvec3 p1(face.points[i]), p2(face.points[i + 1]);
            const double volume = std::abs(glm::dot(p0 - centre, glm::cross(p1 - centre, p2 - centre))) / 6.0;
            if (!(volume > 0.0) || !std::isfinite(volume))
                continue;
            out.push_back({{centre, p0, p1, p2}});
            volumes.push_back(volume);
        }
    }
}

} // namespace

RegionSampler::RegionSampler(const Zone& zone)
{
    const size_t regions = zone.region_count();
    std::vector<std::vector<Tetrahedron>> per_region(regions);
    std::vector<std::vector<double>> per_region_volume(regions);
    const Aabb world = zone_portal_world(zone);
    if (!world.empty() && !zone.tree.leaf_region.empty())
        for_each_leaf_cell(zone.tree, world, [&](int32_t leaf, const ConvexCell& cell) {
            if (leaf < 0 || size_t(leaf) >= zone.tree.leaf_region.size())
                return;
            const int32_t region = zone.tree.leaf_region[size_t(leaf)];
            if (region < 0 || size_t(region) >= regions)
                return;
            cell_tetrahedra(cell, per_region[size_t(region)], per_region_volume[size_t(region)]);
        });
    region_first_.assign(regions + 1, 0);
    for (size_t r = 0; r < regions; ++r) {
        region_first_[r + 1] = region_first_[r] + uint32_t(per_region[r].size());
        double running = 0.0;
        for (size_t k = 0; k < per_region[r].size(); ++k) {
            running += per_region_volume[r][k];
            tetrahedra_.push_back(per_region[r][k]);
            cumulative_.push_back(running);
        }
    }
}

double RegionSampler::volume(uint32_t region) const
{
    return has_volume(region) ? cumulative_[region_first_[region + 1] - 1] : 0.0;
}

glm::dvec3 RegionSampler::point(uint32_t region, double u0, double u1, double u2, double u3) const
{
    const uint32_t first = region_first_[region], last = region_first_[region + 1];
    const double target = u0 * cumulative_[last - 1];
    const auto it = std::upper_bound(cumulative_.begin() + first, cumulative_.begin() + last, target);
    const size_t k = std::min<size_t>(size_t(it - cumulative_.begin()), last - 1);
    const Tetrahedron& t = tetrahedra_[k];
    // Fold the unit cube onto the tetrahedron (Rocchini & Cignoni 2000): uniform barycentrics.
    double s = u1, w = u2, u = u3;
    if (s + w > 1.0) {
        s = 1.0 - s;
        w = 1.0 - w;
    }
    if (w + u > 1.0) {
        const double keep = u;
        u = 1.0 - s - w;
        w = 1.0 - keep;
    } else if (s + w + u > 1.0) {
        const double keep = u;
        u = s + w + u - 1.0;
        s = 1.0 - w - keep;
    }
    const double a = 1.0 - s - w - u;
    return a * t.v[0] + s * t.v[1] + w * t.v[2] + u * t.v[3];
}

} // namespace pvs
