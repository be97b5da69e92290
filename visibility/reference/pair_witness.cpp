// A sight line between two given regions (pair_witness.h).
#include "visibility/reference/pair_witness.h"

#include "visibility/reference/line_witness.h"
#include "visibility/reference/sample_sequence.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace pvs {
namespace {

using sampling::hash_unit;
using sampling::sample_key;

// Polygons to draw points from, each with its share of the total area.
class PolygonPicker {
public:
    explicit PolygonPicker(std::span<const std::vector<glm::dvec3>> polygons) : polygons_(polygons)
    {
        double total = 0.0;
        for (const auto& polygon : polygons) {
            total += area(polygon);
            cumulative_.push_back(total);
        }
    }
    bool empty() const { return cumulative_.empty() || !(cumulative_.back() > 0.0); }

    // A point of a polygon, chosen by area; in it, a triangle of its fan, then a uniform point
    // of that triangle (the fan's triangles are taken alike: close to uniform for a portal).
    glm::dvec3 point(double u0, double u1, double u2, double u3) const
    {
        const auto at = std::upper_bound(cumulative_.begin(), cumulative_.end(), u0 * cumulative_.back());
        const auto& poly = polygons_[size_t(std::min<ptrdiff_t>(at - cumulative_.begin(), ptrdiff_t(polygons_.size()) - 1))];
        if (poly.size() < 3)
            return poly.empty() ? glm::dvec3(0.0) : poly[0];
        const size_t tri = std::min(poly.size() - 3, size_t(u1 * double(poly.size() - 2)));
        double s = u2, t = u3;
        if (s + t > 1.0) {
            s = 1.0 - s;
            t = 1.0 - t;
        }
        return poly[0] + s * (poly[tri + 1] - poly[0]) + t * (poly[tri + 2] - poly[0]);
    }

private:
    static double area(const std::vector<glm::dvec3>& p)
    {
        glm::dvec3 twice(0.0);
        for (size_t i = 1; i + 1 < p.size(); ++i)
            twice += glm::cross(p[i] - p[0], p[i + 1] - p[0]);
        return 0.5 * glm::length(twice);
    }
    std::span<const std::vector<glm::dvec3>> polygons_;
    std::vector<double> cumulative_;
};

// The segment between the middles of the line's runs through a and b, when its stretch holds both.
bool ends_on_stretch(const Stretch& stretch, const glm::dvec3& point, const glm::dvec3& direction, uint32_t a,
                     uint32_t b, glm::dvec3& from, glm::dvec3& to)
{
    const auto ia = std::find(stretch.regions.begin(), stretch.regions.end(), a);
    const auto ib = std::find(stretch.regions.begin(), stretch.regions.end(), b);
    if (ia == stretch.regions.end() || ib == stretch.regions.end())
        return false;
    from = point + stretch.t_mid[size_t(ia - stretch.regions.begin())] * direction;
    to = point + stretch.t_mid[size_t(ib - stretch.regions.begin())] * direction;
    return true;
}

} // namespace

bool proves_sight(const TreeTracer& tracer, const glm::dvec3& from, const glm::dvec3& to, uint32_t a, uint32_t b,
                  TreeTracer::Scratch& scratch)
{
    if (tracer.region_at(from) != int32_t(a) || tracer.region_at(to) != int32_t(b))
        return false;
    const glm::dvec3 along = to - from;
    const double length = glm::length(along);
    if (!(length > 0.0))
        return a == b;
    const glm::dvec3 direction = along / length;
    const TraceEnd end = tracer.trace(from, direction, length, scratch, [](int32_t, double, double) {});
    return !end.blocked && tracer.open_beam(from, direction, length, kBeamMargin, scratch);
}

std::optional<SightWitness> find_sight_line(const TreeTracer& tracer, const RegionSampler& sampler, uint32_t a,
                                            uint32_t b, const WitnessSearch& search, uint64_t* tries)
{
    if (tries)
        *tries = 0;
    if (!tracer.has_tree() || a >= sampler.region_count() || b >= sampler.region_count())
        return std::nullopt;
    const bool volumes = sampler.has_volume(a) && sampler.has_volume(b);
    const PolygonPicker near_a(search.near_a), near_b(search.near_b);
    const bool polygons = !near_a.empty() && !near_b.empty();
    TreeTracer::Scratch scratch;
    Stretch stretch;
    for (uint64_t i = 0; i < search.budget; ++i) {
        if (tries)
            *tries = i + 1;
        const uint64_t key = sample_key(search.seed, a, b, i);
        glm::dvec3 from, to;
        const bool through_polygons = polygons && (!volumes || (i & 1) != 0);
        if (through_polygons) {
            const glm::dvec3 p = near_a.point(hash_unit(key, 0), hash_unit(key, 1), hash_unit(key, 2), hash_unit(key, 3));
            const glm::dvec3 q = near_b.point(hash_unit(key, 4), hash_unit(key, 5), hash_unit(key, 6), hash_unit(key, 7));
            const double length = glm::length(q - p);
            if (!(length > 1e-9))
                continue;
            const glm::dvec3 direction = (q - p) / length;
            const glm::dvec3 middle = 0.5 * (p + q); // open space when the line is a sight line
            const bool open = search.world.empty()
                                  ? open_stretch(tracer, middle, direction, search.reach, scratch, stretch)
                                  : open_stretch(tracer, middle, direction, search.world, scratch, stretch);
            if (!open ||
                !ends_on_stretch(stretch, middle, direction, a, b, from, to))
                continue;
        } else if (volumes) {
            from = sampler.point(a, hash_unit(key, 0), hash_unit(key, 1), hash_unit(key, 2), hash_unit(key, 3));
            to = sampler.point(b, hash_unit(key, 4), hash_unit(key, 5), hash_unit(key, 6), hash_unit(key, 7));
        } else {
            break; // nothing to draw lines from
        }
        if (proves_sight(tracer, from, to, a, b, scratch))
            return SightWitness{from, to, i + 1};
    }
    return std::nullopt;
}

} // namespace pvs
