#include "visibility/geometry/winding.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace pvs {

namespace {

enum Side : uint8_t { kFront = 0, kBack = 1, kOn = 2 };

using dvec3 = glm::dvec3;

bool is_finite(const Plane& plane)
{
    return std::isfinite(plane.normal.x) && std::isfinite(plane.normal.y) && std::isfinite(plane.normal.z) &&
           std::isfinite(plane.dist);
}

double sanitized(float epsilon) { return epsilon > 0.0f ? double(epsilon) : 0.0; } // NaN -> 0

double distance(const Plane& plane, const glm::vec3& p)
{
    return double(plane.normal.x) * p.x + double(plane.normal.y) * p.y + double(plane.normal.z) * p.z -
           double(plane.dist);
}

Side side_of(double d, double eps)
{
    if (d > eps)
        return kFront;
    if (d < -eps)
        return kBack;
    return kOn; // also NaN
}

bool crosses(Side a, Side b) { return (a == kFront && b == kBack) || (a == kBack && b == kFront); }

// The point at d == 0 on the edge a -> b (da and db of strictly opposite signs). Always called
// with the edge in the winding's order, so split's two parts share the same new point.
glm::vec3 intersect(const glm::vec3& a, const glm::vec3& b, double da, double db, const Plane& plane)
{
    const double t = da / (da - db);
    glm::vec3 out;
    for (int k = 0; k < 3; ++k) {
        // Axial planes: the coordinate is known exactly (ericw ClipStackWinding).
        if (plane.normal[k] == 1.0f)
            out[k] = plane.dist;
        else if (plane.normal[k] == -1.0f)
            out[k] = -plane.dist;
        else
            out[k] = static_cast<float>(double(a[k]) + t * (double(b[k]) - double(a[k])));
    }
    return out;
}

struct Classification {
    size_t counts[3] = {0, 0, 0}; // by Side
    size_t crossings = 0;         // edges whose ends are strictly FRONT and BACK
};

Classification classify(const std::vector<glm::vec3>& points, const Plane& plane, double eps)
{
    Classification c;
    const size_t n = points.size();
    Side prev = side_of(distance(plane, points[n - 1]), eps);
    for (size_t i = 0; i < n; ++i) {
        const Side s = side_of(distance(plane, points[i]), eps);
        ++c.counts[s];
        c.crossings += crosses(prev, s);
        prev = s;
    }
    return c;
}

// Writes the kept points of one side (kFront: front + on; kBack: back + on) plus the new points.
void emit_side(const std::vector<glm::vec3>& points, const Plane& plane, double eps, Side keep, size_t reserve,
               std::vector<glm::vec3>& out)
{
    const Side drop = keep == kFront ? kBack : kFront;
    out.clear();
    out.reserve(reserve);
    const size_t n = points.size();
    double d_first = distance(plane, points[0]);
    double d_i = d_first;
    for (size_t i = 0; i < n; ++i) {
        const size_t j = i + 1 == n ? 0 : i + 1;
        const double d_j = j == 0 ? d_first : distance(plane, points[j]);
        const Side s_i = side_of(d_i, eps), s_j = side_of(d_j, eps);
        if (s_i != drop)
            out.push_back(points[i]);
        if (crosses(s_i, s_j))
            out.push_back(intersect(points[i], points[j], d_i, d_j, plane));
        d_i = d_j;
    }
    if (out.size() < 3)
        out.clear();
}

// Newell's sum relative to the first point: twice the vector area.
dvec3 vector_area2(const std::vector<glm::vec3>& points)
{
    dvec3 sum(0.0);
    if (points.size() < 3)
        return sum;
    const dvec3 p0(points[0]);
    for (size_t i = 1; i + 1 < points.size(); ++i)
        sum += glm::cross(dvec3(points[i]) - p0, dvec3(points[i + 1]) - p0);
    return sum;
}

} // namespace

void Winding::clip_into(const Plane& plane, float epsilon, Winding& out) const
{
    if (empty()) {
        out.points.clear();
        return;
    }
    if (!is_finite(plane)) {
        out.points = points;
        return;
    }
    const double eps = sanitized(epsilon);
    const Classification c = classify(points, plane, eps);
    if (c.counts[kBack] == 0) {
        out.points = points; // all front or on: unchanged
        return;
    }
    if (c.counts[kFront] == 0) {
        out.points.clear();
        return;
    }
    emit_side(points, plane, eps, kFront, c.counts[kFront] + c.counts[kOn] + c.crossings, out.points);
}

Winding Winding::clip(const Plane& plane, float epsilon) const
{
    Winding out;
    clip_into(plane, epsilon, out);
    return out;
}

bool Winding::clip_in_place(const Plane& plane, float epsilon, Winding& scratch)
{
    if (empty()) {
        points.clear();
        return false;
    }
    if (!is_finite(plane))
        return true;
    const double eps = sanitized(epsilon);
    const Classification c = classify(points, plane, eps);
    if (c.counts[kBack] == 0)
        return true;
    if (c.counts[kFront] == 0) {
        points.clear();
        return false;
    }
    emit_side(points, plane, eps, kFront, c.counts[kFront] + c.counts[kOn] + c.crossings, scratch.points);
    points.swap(scratch.points);
    return !empty();
}

WindingSplit Winding::split(const Plane& plane, float epsilon) const
{
    WindingSplit out;
    if (empty())
        return out;
    if (!is_finite(plane)) {
        out.front = *this;
        return out;
    }
    const double eps = sanitized(epsilon);
    const Classification c = classify(points, plane, eps);
    if (c.counts[kFront] == 0 && c.counts[kBack] == 0) {
        // All on the plane: to the side the polygon faces.
        (glm::dot(normal(), plane.normal) >= 0.0f ? out.front : out.back) = *this;
        return out;
    }
    if (c.counts[kBack] == 0) {
        out.front = *this;
        return out;
    }
    if (c.counts[kFront] == 0) {
        out.back = *this;
        return out;
    }
    emit_side(points, plane, eps, kFront, c.counts[kFront] + c.counts[kOn] + c.crossings, out.front.points);
    emit_side(points, plane, eps, kBack, c.counts[kBack] + c.counts[kOn] + c.crossings, out.back.points);
    return out;
}

float Winding::area() const { return static_cast<float>(0.5 * glm::length(vector_area2(points))); }

glm::vec3 Winding::normal() const
{
    const dvec3 n = vector_area2(points);
    const double len = glm::length(n);
    if (!(len > 0.0) || !std::isfinite(len))
        return glm::vec3(0.0f);
    return glm::vec3(n / len);
}

glm::vec3 Winding::centroid() const
{
    if (points.empty())
        return glm::vec3(0.0f);
    const dvec3 p0(points[0]);
    const dvec3 n = vector_area2(points);
    const double len = glm::length(n);
    if (len > 0.0 && std::isfinite(len)) {
        const dvec3 unit = n / len;
        dvec3 weighted(0.0);
        double total = 0.0;
        for (size_t i = 1; i + 1 < points.size(); ++i) {
            const dvec3 a = dvec3(points[i]) - p0, b = dvec3(points[i + 1]) - p0;
            const double w = glm::dot(glm::cross(a, b), unit); // twice the signed triangle area
            weighted += w * (a + b);
            total += w;
        }
        if (total != 0.0)
            return glm::vec3(p0 + weighted / (3.0 * total));
    }
    dvec3 sum(0.0);
    for (const glm::vec3& p : points)
        sum += dvec3(p) - p0;
    return glm::vec3(p0 + sum / double(points.size()));
}

Plane Winding::plane() const
{
    const glm::vec3 n = normal();
    if (n == glm::vec3(0.0f))
        return {n, 0.0f};
    return {n, glm::dot(n, centroid())};
}

Aabb Winding::bounds() const
{
    Aabb box;
    for (const glm::vec3& p : points)
        box.grow(p);
    return box;
}

Winding Winding::reversed() const { return Winding(std::vector<glm::vec3>(points.rbegin(), points.rend())); }

size_t Winding::remove_degenerate_points(float epsilon)
{
    const size_t before = points.size();
    const double eps = sanitized(epsilon);
    // One pass removes every degenerate point whose neighbours both stay, so that a run of
    // nearly colinear points cannot drift by more than epsilon per removal; passes repeat until
    // nothing changes. Each pass is O(n); windings are short.
    std::vector<glm::vec3> src;
    bool changed = true;
    while (changed && points.size() >= 3) {
        changed = false;
        src.swap(points);
        points.clear();
        const size_t n = src.size();
        bool removed_first = false, removed_prev = false;
        for (size_t i = 0; i < n; ++i) {
            const bool last = i + 1 == n;
            bool remove = false;
            if (!removed_prev && !(last && removed_first)) {
                const dvec3 prev(src[i == 0 ? n - 1 : i - 1]), cur(src[i]), next(src[last ? 0 : i + 1]);
                const dvec3 chord = next - prev;
                const double chord_len = glm::length(chord);
                if (glm::length(cur - prev) <= eps || chord_len <= eps)
                    remove = true; // duplicate of its predecessor, or the tip of a spike
                else
                    remove = glm::length(glm::cross(cur - prev, chord)) / chord_len <= eps; // colinear
            }
            if (remove) {
                changed = true;
                removed_first |= i == 0;
            } else {
                points.push_back(src[i]);
            }
            removed_prev = remove;
        }
    }
    if (points.size() < 3)
        points.clear();
    return before - points.size();
}

Winding base_winding_for_plane(const Plane& plane, float half_size, const glm::vec3& center)
{
    if (!is_finite(plane) || !(half_size > 0.0f) || !std::isfinite(half_size) || !std::isfinite(center.x) ||
        !std::isfinite(center.y) || !std::isfinite(center.z))
        return {};
    const dvec3 raw(plane.normal);
    const double len = glm::length(raw);
    if (!(len > 0.0) || !std::isfinite(len))
        return {};
    const dvec3 n = raw / len;
    const double dist = double(plane.dist) / len;

    // The major axis picks an up vector not parallel to the normal (id's BaseWindingForPlane).
    const dvec3 a = glm::abs(n);
    dvec3 up = (a.z >= a.x && a.z >= a.y) ? dvec3(1.0, 0.0, 0.0) : dvec3(0.0, 0.0, 1.0);
    up = glm::normalize(up - n * glm::dot(up, n));
    const dvec3 right = glm::cross(up, n); // right x up = n: counter-clockwise seen from the front

    const dvec3 c(center);
    const dvec3 origin = c - n * (glm::dot(n, c) - dist);
    const double h = half_size;
    const dvec3 corners[4] = {origin - right * h - up * h, origin + right * h - up * h, origin + right * h + up * h,
                              origin - right * h + up * h};
    Winding w;
    w.points.reserve(4);
    for (const dvec3& p : corners) {
        glm::vec3 q(p);
        for (int k = 0; k < 3; ++k) // an axial plane's points lie on it exactly
            if (plane.normal[k] != 0.0f && n[k] == 1.0)
                q[k] = static_cast<float>(dist);
            else if (plane.normal[k] != 0.0f && n[k] == -1.0)
                q[k] = static_cast<float>(-dist);
        w.points.push_back(q);
    }
    return w;
}

} // namespace pvs
