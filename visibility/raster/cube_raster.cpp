#include "visibility/raster/cube_raster.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <tuple>

namespace pvs {

namespace {

// View k looks along axis kViewAxis[k] with sign kViewSign[k]; u and v are the other two axes.
constexpr int kViewAxis[6] = {0, 0, 1, 1, 2, 2};
constexpr float kViewSign[6] = {1.0f, -1.0f, 1.0f, -1.0f, 1.0f, -1.0f};

// Depth, u and v of an eye-relative point in view k (before the divide).
struct ViewPoint {
    float w, x, y;
};
ViewPoint to_view(int k, const glm::vec3& d)
{
    const int a = kViewAxis[k];
    return {kViewSign[k] * d[a], d[(a + 1) % 3], d[(a + 2) % 3]};
}

} // namespace

CubeRaster::CubeRaster(const Zone& zone, const CubeRasterOptions& options)
    : resolution_(std::max(options.resolution, 1u)), cull_back_faces_(options.cull_back_faces),
      near_(options.near_distance > 0.0f ? options.near_distance : 0.05f)
{
    const std::vector<uint8_t> translucent = translucent_face_mask(zone);
    const auto is_translucent = [&](uint32_t f) { return !translucent.empty() && translucent[f] != 0; };
    // The opaque faces' triangles first, then the translucent ones: render() draws them last.
    for (uint32_t f = 0; f < zone.mesh.faces.size(); ++f)
        if (!is_translucent(f))
            add_face(zone.mesh, f);
    first_translucent_ = triangle_face_.size();
    for (uint32_t f = 0; f < zone.mesh.faces.size(); ++f)
        if (is_translucent(f))
            add_face(zone.mesh, f);
    const size_t pixels = size_t(resolution_) * resolution_;
    depth_.assign(6 * pixels, 0.0f);
    id_.assign(6 * pixels, 0);
}

// Appends the face's triangles (those whose indices are in range).
void CubeRaster::add_face(const Mesh& mesh, uint32_t f)
{
    const Face& face = mesh.faces[f];
    for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t) {
        if (3 * size_t(t) + 2 >= mesh.indices.size())
            break;
        glm::vec3 p[3];
        bool ok = true;
        for (int k = 0; k < 3; ++k) {
            const uint32_t i = mesh.indices[3 * size_t(t) + size_t(k)];
            ok = ok && i < mesh.positions.size();
            p[k] = ok ? mesh.positions[i] : glm::vec3(0.0f);
        }
        if (!ok)
            continue;
        corners_.insert(corners_.end(), {p[0], p[1], p[2]});
        triangle_face_.push_back(f);
        triangle_normal_.push_back(glm::cross(p[1] - p[0], p[2] - p[0]));
    }
}

void CubeRaster::render(const glm::vec3& eye, std::vector<uint8_t>& seen)
{
    std::fill(depth_.begin(), depth_.end(), 0.0f);
    std::fill(id_.begin(), id_.end(), 0u);
    seen_ = &seen;
    for (size_t t = 0; t < triangle_face_.size(); ++t) {
        // Translucent triangles come last: depth-tested against everything opaque, marking their
        // face seen where they pass, but writing no depth or id, so what lies behind stays seen.
        translucent_pass_ = t >= first_translucent_;
        const glm::vec3 d[3] = {corners_[3 * t] - eye, corners_[3 * t + 1] - eye, corners_[3 * t + 2] - eye};
        // Counter-clockwise from the front: the eye is in front when it is on the normal's side.
        if (cull_back_faces_ && !(glm::dot(triangle_normal_[t], -d[0]) > 0.0f))
            continue;
        for (int k = 0; k < 6; ++k)
            draw(k, d, triangle_face_[t]);
    }
    for (uint32_t id : id_)
        if (id != 0)
            seen[id - 1] = 1;
}

// Rejects a triangle outside one of the view's side planes or behind the near plane, clips it
// (below), and fills the result as a fan.
void CubeRaster::draw(int view, const glm::vec3 (&d)[3], uint32_t face)
{
    ViewPoint p[3];
    for (int k = 0; k < 3; ++k)
        p[k] = to_view(view, d[k]);
    const auto all = [&](auto outside) { return outside(p[0]) && outside(p[1]) && outside(p[2]); };
    if (all([](const ViewPoint& q) { return q.x > q.w; }) || all([](const ViewPoint& q) { return q.x < -q.w; }) ||
        all([](const ViewPoint& q) { return q.y > q.w; }) || all([](const ViewPoint& q) { return q.y < -q.w; }) ||
        all([this](const ViewPoint& q) { return q.w < near_; }))
        return;
    // Clip at the near plane and at the four side planes widened by a pixel (a guard band): the
    // screen coordinates then stay within the picture, where float edge functions are exact
    // enough. Without the side planes a wall reaching past the eye projects thousands of pixels
    // out and its edge functions lose the bits that keep two triangles of one face gap-free
    // (a face behind the wall then shows through: seen on the stability case wall-1).
    const float band = 1.0f + 2.0f / float(resolution_);
    ViewPoint buffers[2][9];
    int n = 3;
    std::copy(p, p + 3, buffers[0]);
    int current = 0;
    const auto clip = [&](auto distance) { // keeps distance(q) >= 0
        ViewPoint* in = buffers[current];
        ViewPoint* out = buffers[1 - current];
        int m = 0;
        for (int k = 0; k < n; ++k) {
            const ViewPoint& a = in[k];
            const ViewPoint& b = in[(k + 1) % n];
            const float da = distance(a), db = distance(b);
            if (da >= 0.0f)
                out[m++] = a;
            if ((da >= 0.0f) != (db >= 0.0f)) {
                // From the endpoints in one fixed order, so that the triangle on the other side
                // of this edge cuts it at exactly the same point (no crack along the cut).
                const bool in_order = std::tie(a.w, a.x, a.y) < std::tie(b.w, b.x, b.y);
                const ViewPoint& p0 = in_order ? a : b;
                const ViewPoint& p1 = in_order ? b : a;
                const float d0 = in_order ? da : db, d1 = in_order ? db : da;
                const float s = d0 / (d0 - d1);
                out[m++] = {p0.w + s * (p1.w - p0.w), p0.x + s * (p1.x - p0.x), p0.y + s * (p1.y - p0.y)};
            }
        }
        n = m;
        current = 1 - current;
    };
    clip([this](const ViewPoint& q) { return q.w - near_; });
    clip([band](const ViewPoint& q) { return band * q.w - q.x; });
    clip([band](const ViewPoint& q) { return band * q.w + q.x; });
    clip([band](const ViewPoint& q) { return band * q.w - q.y; });
    clip([band](const ViewPoint& q) { return band * q.w + q.y; });
    if (n < 3)
        return;
    const ViewPoint* poly = buffers[current];
    const float half = 0.5f * float(resolution_);
    Vertex v[9];
    for (int k = 0; k < n; ++k) {
        const float inv_w = 1.0f / poly[k].w;
        v[k] = {(poly[k].x * inv_w + 1.0f) * half, (poly[k].y * inv_w + 1.0f) * half, inv_w};
    }
    for (int k = 1; k + 1 < n; ++k)
        fill(view, v[0], v[k], v[k + 1], face);
}

namespace {

// The edge function of p -> q at a pixel centre, computed from the edge's endpoints in one fixed
// order whichever triangle asks, so that two triangles sharing the edge get exactly opposite
// values: a pixel centre on the edge then belongs to exactly one of them (below), and a face made
// of several triangles has no cracks along its diagonals for a face behind it to show through.
struct Edge {
    float pu, pv, du, dv; // canonical start and direction
    float sign;           // +1 when p -> q is the canonical order, -1 when reversed
    float at(float x, float y) const { return sign * (du * (y - pv) - dv * (x - pu)); }
    // Whether a pixel exactly on the edge (value 0) is inside: the triangle on one side only.
    bool owns_ties(float orientation) const { return sign * orientation > 0.0f; }
};

template <class V>
Edge make_edge(const V& p, const V& q)
{
    const bool in_order = p.u < q.u || (p.u == q.u && p.v < q.v);
    const V& a = in_order ? p : q;
    const V& b = in_order ? q : p;
    return {a.u, a.v, b.u - a.u, b.v - a.v, in_order ? 1.0f : -1.0f};
}

// Twice the signed area (square pixels) below which a triangle is dropped as a sliver.
constexpr float kMinArea = 1e-3f;

} // namespace

void CubeRaster::fill(int view, const Vertex& a, const Vertex& b, const Vertex& c, uint32_t face)
{
    const Edge e_ab = make_edge(a, b), e_bc = make_edge(b, c), e_ca = make_edge(c, a);
    // Twice the signed area, from the same edge functions: positive when a, b, c turn left.
    const float area = e_ab.at(c.u, c.v);
    // Slivers (clipping can leave two vertices a rounding error apart) cover no pixel centre
    // honestly: their weights would be noise divided by almost nothing.
    if (!(std::abs(area) > kMinArea))
        return;
    const float orientation = area > 0.0f ? 1.0f : -1.0f;
    const float size = float(resolution_);
    const int x0 = int(std::max(0.0f, std::floor(std::min({a.u, b.u, c.u}))));
    const int x1 = int(std::min(size - 1.0f, std::ceil(std::max({a.u, b.u, c.u}))));
    const int y0 = int(std::max(0.0f, std::floor(std::min({a.v, b.v, c.v}))));
    const int y1 = int(std::min(size - 1.0f, std::ceil(std::max({a.v, b.v, c.v}))));
    if (x0 > x1 || y0 > y1)
        return;
    const float inv_area = 1.0f / area;
    const float z_min = std::min({a.inv_w, b.inv_w, c.inv_w}), z_max = std::max({a.inv_w, b.inv_w, c.inv_w});
    const bool tie_ab = e_ab.owns_ties(orientation), tie_bc = e_bc.owns_ties(orientation),
               tie_ca = e_ca.owns_ties(orientation);
    float* depth = depth_.data() + size_t(view) * resolution_ * resolution_;
    uint32_t* id = id_.data() + size_t(view) * resolution_ * resolution_;
    for (int y = y0; y <= y1; ++y) {
        const float py = float(y) + 0.5f;
        for (int x = x0; x <= x1; ++x) {
            const float px = float(x) + 0.5f;
            const float f_bc = e_bc.at(px, py), f_ca = e_ca.at(px, py), f_ab = e_ab.at(px, py);
            const auto inside = [orientation](float f, bool ties) {
                const float g = f * orientation;
                return g > 0.0f || (g == 0.0f && ties);
            };
            if (!inside(f_bc, tie_bc) || !inside(f_ca, tie_ca) || !inside(f_ab, tie_ab))
                continue;
            // Barycentric weights: each edge function over the area.
            // Clamped to the triangle's own depths: rounding at an edge can push the weights out.
            const float z = std::clamp((f_bc * a.inv_w + f_ca * b.inv_w + f_ab * c.inv_w) * inv_area, z_min, z_max);
            const size_t i = size_t(y) * resolution_ + size_t(x);
            if (z > depth[i]) {
                if (translucent_pass_) {
                    (*seen_)[face] = 1;
                    continue;
                }
                depth[i] = z;
                id[i] = face + 1;
            }
        }
    }
}

} // namespace pvs
