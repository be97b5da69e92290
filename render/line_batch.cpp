#include "render/line_batch.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <utility>

namespace pvs::ui {

namespace {

bool finite(const glm::vec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// A float's bits as an unsigned integer that orders as the float does (-0 just below +0; no NaN
// gets here), and back.
uint32_t ordered_bits(float f)
{
    const uint32_t b = std::bit_cast<uint32_t>(f);
    return b & 0x80000000u ? ~b : b | 0x80000000u;
}

float from_ordered_bits(uint32_t o)
{
    return std::bit_cast<float>(o & 0x80000000u ? o & 0x7FFFFFFFu : ~o);
}

// The point at `along` on axis `axis` of the line whose other two coordinates `line` holds.
glm::vec3 point_on(uint32_t axis, uint64_t line, uint32_t along)
{
    glm::vec3 p;
    p[int(axis)] = from_ordered_bits(along);
    p[int((axis + 1) % 3)] = from_ordered_bits(uint32_t(line >> 32));
    p[int((axis + 2) % 3)] = from_ordered_bits(uint32_t(line));
    return p;
}

// Byte `d` of an edge's sort key (line, lo), least significant first.
uint32_t key_byte(uint64_t line, uint32_t lo, uint32_t d)
{
    return d < 4 ? (lo >> (8 * d)) & 0xFF : uint32_t(line >> (8 * (d - 4))) & 0xFF;
}

} // namespace

void LineBatch::clear()
{
    for (std::vector<Edge>& list : edges_)
        list.clear();
    loose_.clear();
    group_rgb_.clear();
    group_of_rgb_.clear();
    segments_.clear();
    joined_ = false;
}

uint32_t LineBatch::group_of(uint32_t rgb)
{
    const auto [at, fresh] = group_of_rgb_.try_emplace(rgb, uint32_t(group_rgb_.size()));
    if (fresh) {
        group_rgb_.push_back(rgb);
        if (edges_.size() < group_rgb_.size() * 3)
            edges_.resize(group_rgb_.size() * 3);
    }
    joined_ = false;
    return at->second;
}

void LineBatch::add_axis_edge(uint32_t group, uint32_t axis, float u, float v, float lo, float hi)
{
    edges_[group * 3 + axis].push_back({uint64_t(ordered_bits(u)) << 32 | ordered_bits(v), ordered_bits(lo), ordered_bits(hi)});
}

void LineBatch::add_box(const Aabb& box, uint32_t rgb)
{
    if (box.empty() || !finite(box.min) || !finite(box.max))
        return;
    const uint32_t group = group_of(rgb);
    for (uint32_t axis = 0; axis < 3; ++axis) {
        const int ku = int((axis + 1) % 3), kv = int((axis + 2) % 3);
        for (float u : {box.min[ku], box.max[ku]})
            for (float v : {box.min[kv], box.max[kv]})
                add_axis_edge(group, axis, u, v, box.min[int(axis)], box.max[int(axis)]);
    }
}

void LineBatch::add_segment(const glm::vec3& a, const glm::vec3& b, uint32_t rgb)
{
    if (!finite(a) || !finite(b) || a == b)
        return;
    const uint32_t group = group_of(rgb);
    for (uint32_t axis = 0; axis < 3; ++axis) {
        const int ku = int((axis + 1) % 3), kv = int((axis + 2) % 3);
        if (a[ku] == b[ku] && a[kv] == b[kv]) {
            add_axis_edge(group, axis, a[ku], a[kv], std::min(a[int(axis)], b[int(axis)]),
                          std::max(a[int(axis)], b[int(axis)]));
            return;
        }
    }
    loose_.push_back({group, a, b});
}

void LineBatch::add_outline(std::span<const glm::vec3> polygon, uint32_t rgb)
{
    if (polygon.size() < 2)
        return;
    for (size_t i = 0; i < polygon.size(); ++i)
        add_segment(polygon[i], polygon[(i + 1) % polygon.size()], rgb);
}

// One line class's edges by (line, lo): a byte-wise LSD radix sort for long lists (a frame's
// 100 000+ edges sort in a fraction of std::sort's time), std::sort for short ones. Bytes every
// edge shares cost no pass: grid coordinates leave many of their bytes alike.
void LineBatch::sort_lines(uint32_t line_class)
{
    std::vector<Edge>& edges = edges_[line_class];
    if (edges.size() < 256) {
        std::sort(edges.begin(), edges.end(),
                  [](const Edge& a, const Edge& b) { return a.line != b.line ? a.line < b.line : a.lo < b.lo; });
        return;
    }
    constexpr uint32_t kBytes = 12;
    std::array<uint32_t, kBytes> varying{};
    uint32_t count = 0;
    {
        uint64_t line_differs = 0;
        uint32_t lo_differs = 0;
        for (const Edge& e : edges) {
            line_differs |= e.line ^ edges.front().line;
            lo_differs |= e.lo ^ edges.front().lo;
        }
        for (uint32_t d = 0; d < kBytes; ++d)
            if (key_byte(line_differs, lo_differs, d) != 0)
                varying[count++] = d;
    }
    std::array<std::array<uint32_t, 256>, kBytes> histogram{};
    for (const Edge& e : edges)
        for (uint32_t k = 0; k < count; ++k)
            ++histogram[k][key_byte(e.line, e.lo, varying[k])];
    spare_.resize(edges.size());
    for (uint32_t k = 0; k < count; ++k) {
        uint32_t start = 0;
        for (uint32_t& c : histogram[k])
            start += std::exchange(c, start);
        for (const Edge& e : edges)
            spare_[histogram[k][key_byte(e.line, e.lo, varying[k])]++] = e;
        edges.swap(spare_);
    }
}

std::span<const ColoredSegment> LineBatch::segments()
{
    if (joined_)
        return segments_;
    std::stable_sort(loose_.begin(), loose_.end(), [](const Loose& a, const Loose& b) { return a.group < b.group; });
    segments_.clear();
    size_t next_loose = 0;
    const auto loose_until = [&](uint32_t group) { // the loose segments of colours before `group`
        for (; next_loose < loose_.size() && loose_[next_loose].group < group; ++next_loose)
            segments_.push_back({loose_[next_loose].a, loose_[next_loose].b, group_rgb_[loose_[next_loose].group]});
    };
    for (uint32_t line_class = 0; line_class < group_rgb_.size() * 3; ++line_class) {
        const uint32_t group = line_class / 3, axis = line_class % 3;
        loose_until(group);
        sort_lines(line_class);
        const std::vector<Edge>& edges = edges_[line_class];
        for (size_t i = 0; i < edges.size();) {
            const Edge& first = edges[i];
            uint32_t hi = first.hi;
            size_t j = i + 1;
            // Same line, and starting no later than the run so far ends: one segment.
            while (j < edges.size() && edges[j].line == first.line && edges[j].lo <= hi)
                hi = std::max(hi, edges[j++].hi);
            segments_.push_back({point_on(axis, first.line, first.lo), point_on(axis, first.line, hi), group_rgb_[group]});
            i = j;
        }
    }
    loose_until(uint32_t(group_rgb_.size()));
    joined_ = true;
    return segments_;
}

uint32_t LineBatch::draw(Image& image, const LineProjection& view)
{
    uint32_t set = 0;
    for (const ColoredSegment& s : segments())
        set += draw_line_3d(image, view, s.a, s.b, s.rgb);
    return set;
}

} // namespace pvs::ui
