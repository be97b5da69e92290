#include "visibility/reference/portal_sampler.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace pvs {

PortalSampler::PortalSampler(const PortalSet& set, uint32_t region_count)
{
    std::vector<std::vector<Link>> per_region(region_count);
    triangle_first_.assign(set.portals.size() + 1, 0);

    for (size_t i = 0; i < set.portals.size(); ++i) {
        const Portal& p = set.portals[i];
        const bool regions_ok = p.regions[0] >= 0 && p.regions[1] >= 0 && uint32_t(p.regions[0]) < region_count &&
                                uint32_t(p.regions[1]) < region_count && p.regions[0] != p.regions[1];
        double area = 0.0;
        if (regions_ok && p.point_count >= 3 && size_t(p.first_point) + p.point_count <= set.points.size()) {
            const glm::dvec3 p0(set.points[p.first_point]);
            for (uint32_t k = 1; k + 1 < p.point_count; ++k) {
                const glm::dvec3 p1(set.points[p.first_point + k]), p2(set.points[p.first_point + k + 1]);
                const double triangle = 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
                if (!(triangle > 0.0) || !std::isfinite(triangle))
                    continue;
                area += triangle;
                triangles_.insert(triangles_.end(), {p0, p1, p2});
                cumulative_area_.push_back(area);
            }
        }
        triangle_first_[i + 1] = uint32_t(cumulative_area_.size());
        if (area > 0.0) {
            per_region[size_t(p.regions[0])].push_back({uint32_t(i), uint32_t(p.regions[1])});
            per_region[size_t(p.regions[1])].push_back({uint32_t(i), uint32_t(p.regions[0])});
        }
    }
    link_first_.assign(size_t(region_count) + 1, 0);
    for (uint32_t r = 0; r < region_count; ++r) {
        link_first_[r + 1] = link_first_[r] + uint32_t(per_region[r].size());
        links_.insert(links_.end(), per_region[r].begin(), per_region[r].end());
    }
}

glm::dvec3 PortalSampler::point(uint32_t portal, double u0, double u1, double u2) const
{
    const uint32_t first = triangle_first_[portal], last = triangle_first_[portal + 1];
    const double target = u0 * cumulative_area_[last - 1];
    const auto it = std::upper_bound(cumulative_area_.begin() + first, cumulative_area_.begin() + last, target);
    const size_t k = std::min<size_t>(size_t(it - cumulative_area_.begin()), last - 1);
    double s = u1, t = u2;
    if (s + t > 1.0) { // fold the unit square onto the triangle
        s = 1.0 - s;
        t = 1.0 - t;
    }
    const glm::dvec3& a = triangles_[3 * k];
    return a + s * (triangles_[3 * k + 1] - a) + t * (triangles_[3 * k + 2] - a);
}

size_t PortalSampler::memory_bytes() const
{
    return links_.capacity() * sizeof(Link) + link_first_.capacity() * sizeof(uint32_t) +
           triangle_first_.capacity() * sizeof(uint32_t) + triangles_.capacity() * sizeof(glm::dvec3) +
           cumulative_area_.capacity() * sizeof(double);
}

} // namespace pvs
