#include "visibility/math/frustum_boxes.h"

#include <cmath>

#include <algorithm>
#include <bit>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace pvs {

FrustumBoxes::FrustumBoxes(std::span<const Aabb> boxes)
    : boxes_(boxes.size()), min_x_(boxes.size()), min_y_(boxes.size()), min_z_(boxes.size()), max_x_(boxes.size()),
      max_y_(boxes.size()), max_z_(boxes.size())
{
    for (size_t i = 0; i < boxes.size(); ++i) {
        const Aabb& b = boxes[i];
        boxes_[i] = {{b.min.x, b.min.y, b.min.z, 0.0f}, {b.max.x, b.max.y, b.max.z, 0.0f}};
        min_x_[i] = b.min.x, min_y_[i] = b.min.y, min_z_[i] = b.min.z;
        max_x_[i] = b.max.x, max_y_[i] = b.max.y, max_z_[i] = b.max.z;
    }
}

FrustumBoxes::PlaneGroups FrustumBoxes::prepare(const Frustum& frustum, Planes planes, float coordinate_scale)
{
    PlaneGroups g;
    prepare(frustum, planes, coordinate_scale, g);
    return g;
}

void FrustumBoxes::prepare(const Frustum& frustum, Planes planes, float coordinate_scale, PlaneGroups& g)
{
    const int plane_count = planes == Planes::All ? 6 : 4;
    g.group_count = planes == Planes::All ? 2 : 1;
    g.plane_count = plane_count;
    // Only the groups tested are filled (group_count), and the spread values only for real planes.
    for (int lane = 0; lane < 4 * g.group_count; ++lane) {
        const int group = lane / 4, k = lane % 4;
        // A lane without a plane: n = 0 and dist = -1, so every distance is +1 (in front).
        const Plane p = lane < plane_count ? frustum.planes[size_t(lane)] : Plane{{0.0f, 0.0f, 0.0f}, -1.0f};
        g.pos_x[group][k] = std::max(p.normal.x, 0.0f);
        g.pos_y[group][k] = std::max(p.normal.y, 0.0f);
        g.pos_z[group][k] = std::max(p.normal.z, 0.0f);
        g.neg_x[group][k] = std::min(p.normal.x, 0.0f);
        g.neg_y[group][k] = std::min(p.normal.y, 0.0f);
        g.neg_z[group][k] = std::min(p.normal.z, 0.0f);
        g.dist[group][k] = p.dist;
        // A distance is six products and a dist summed in float: each step rounds by at most
        // 2^-24 of the running magnitude, below 8 * 2^-24 * (|n| . scale + |dist|) in all; the
        // margin is 16 times that.
        const float magnitude = (std::abs(p.normal.x) + std::abs(p.normal.y) + std::abs(p.normal.z)) * coordinate_scale +
                                std::abs(p.dist);
        g.margin[group][k] = 1e-5f * magnitude;
        if (lane >= plane_count)
            continue;
        const float values[7] = {g.pos_x[group][k], g.pos_y[group][k], g.pos_z[group][k], g.neg_x[group][k],
                                 g.neg_y[group][k], g.neg_z[group][k], g.dist[group][k]};
        for (int v = 0; v < 7; ++v)
            std::fill_n(g.splat[lane][v], 4, values[v]);
    }
}

FrustumBoxes::Side FrustumBoxes::classify(uint32_t box, const PlaneGroups& planes) const
{
    unsigned crossing = all_planes(planes);
    return classify(box, planes, crossing);
}

#if defined(__SSE2__)

// Four planes at a time: the far (positive) and near (negative) vertex's distances, summed in
// the scalar form's order (x, y, z; max part, then min part), so both forms decide alike.
FrustumBoxes::Side FrustumBoxes::classify(uint32_t box, const PlaneGroups& planes, unsigned& crossing) const
{
    const PackedBox& b = boxes_[box];
    const __m128 lo = _mm_load_ps(b.min), hi = _mm_load_ps(b.max);
    const __m128 lo_x = _mm_shuffle_ps(lo, lo, 0x00), lo_y = _mm_shuffle_ps(lo, lo, 0x55), lo_z = _mm_shuffle_ps(lo, lo, 0xAA);
    const __m128 hi_x = _mm_shuffle_ps(hi, hi, 0x00), hi_y = _mm_shuffle_ps(hi, hi, 0x55), hi_z = _mm_shuffle_ps(hi, hi, 0xAA);
    unsigned outside = 0, still = 0;
    for (int g = 0; g < planes.group_count; ++g) {
        const __m128 px = _mm_load_ps(planes.pos_x[g]), py = _mm_load_ps(planes.pos_y[g]), pz = _mm_load_ps(planes.pos_z[g]);
        const __m128 nx = _mm_load_ps(planes.neg_x[g]), ny = _mm_load_ps(planes.neg_y[g]), nz = _mm_load_ps(planes.neg_z[g]);
        const __m128 dist = _mm_load_ps(planes.dist[g]), margin = _mm_load_ps(planes.margin[g]);
        __m128 far = _mm_add_ps(_mm_mul_ps(hi_x, px), _mm_mul_ps(lo_x, nx));
        far = _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_add_ps(far, _mm_mul_ps(hi_y, py)), _mm_mul_ps(lo_y, ny)), _mm_mul_ps(hi_z, pz)),
                         _mm_mul_ps(lo_z, nz));
        far = _mm_sub_ps(far, dist);
        __m128 near = _mm_add_ps(_mm_mul_ps(lo_x, px), _mm_mul_ps(hi_x, nx));
        near = _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_add_ps(near, _mm_mul_ps(lo_y, py)), _mm_mul_ps(hi_y, ny)), _mm_mul_ps(lo_z, pz)),
                          _mm_mul_ps(hi_z, nz));
        near = _mm_sub_ps(near, dist);
        const __m128 negative_margin = _mm_sub_ps(_mm_setzero_ps(), margin);
        outside |= unsigned(_mm_movemask_ps(_mm_cmplt_ps(far, negative_margin))) << (4 * g);
        // !(near > margin): a NaN distance counts as crossing, as the scalar form has it.
        still |= unsigned(_mm_movemask_ps(_mm_cmpngt_ps(near, margin))) << (4 * g);
    }
    if ((outside & crossing) != 0)
        return Side::Outside;
    crossing &= still;
    return crossing == 0 ? Side::Inside : Side::Partial;
}

#else

FrustumBoxes::Side FrustumBoxes::classify(uint32_t box, const PlaneGroups& planes, unsigned& crossing) const
{
    const PackedBox& b = boxes_[box];
    unsigned still = 0;
    for (unsigned rest = crossing; rest != 0; rest &= rest - 1) {
        const int p = std::countr_zero(rest), g = p / 4, k = p % 4;
        {
            // Positive vertex (the box's farthest point along the normal) and negative vertex.
            const float far = b.max[0] * planes.pos_x[g][k] + b.min[0] * planes.neg_x[g][k] +
                              b.max[1] * planes.pos_y[g][k] + b.min[1] * planes.neg_y[g][k] +
                              b.max[2] * planes.pos_z[g][k] + b.min[2] * planes.neg_z[g][k] - planes.dist[g][k];
            if (far < -planes.margin[g][k])
                return Side::Outside;
            const float near = b.min[0] * planes.pos_x[g][k] + b.max[0] * planes.neg_x[g][k] +
                               b.min[1] * planes.pos_y[g][k] + b.max[1] * planes.neg_y[g][k] +
                               b.min[2] * planes.pos_z[g][k] + b.max[2] * planes.neg_z[g][k] - planes.dist[g][k];
            if (!(near > planes.margin[g][k]))
                still |= 1u << p;
        }
    }
    crossing = still;
    return still == 0 ? Side::Inside : Side::Partial;
}

#endif

#if defined(__SSE2__)

bool FrustumBoxes::intersects(uint32_t box, const PlaneGroups& planes) const
{
    const PackedBox& b = boxes_[box];
    const __m128 lo = _mm_load_ps(b.min), hi = _mm_load_ps(b.max);
    const __m128 lo_x = _mm_shuffle_ps(lo, lo, 0x00), lo_y = _mm_shuffle_ps(lo, lo, 0x55), lo_z = _mm_shuffle_ps(lo, lo, 0xAA);
    const __m128 hi_x = _mm_shuffle_ps(hi, hi, 0x00), hi_y = _mm_shuffle_ps(hi, hi, 0x55), hi_z = _mm_shuffle_ps(hi, hi, 0xAA);
    __m128 outside = _mm_setzero_ps();
    for (int g = 0; g < planes.group_count; ++g) {
        // The same summation order as glm::dot(normal, positive) - dist: x, then y, then z;
        // each axis adds its two products, one of which is an exact zero.
        __m128 d = _mm_add_ps(_mm_mul_ps(hi_x, _mm_load_ps(planes.pos_x[g])), _mm_mul_ps(lo_x, _mm_load_ps(planes.neg_x[g])));
        d = _mm_add_ps(d, _mm_mul_ps(hi_y, _mm_load_ps(planes.pos_y[g])));
        d = _mm_add_ps(d, _mm_mul_ps(lo_y, _mm_load_ps(planes.neg_y[g])));
        d = _mm_add_ps(d, _mm_mul_ps(hi_z, _mm_load_ps(planes.pos_z[g])));
        d = _mm_add_ps(d, _mm_mul_ps(lo_z, _mm_load_ps(planes.neg_z[g])));
        d = _mm_sub_ps(d, _mm_load_ps(planes.dist[g]));
        outside = _mm_or_ps(outside, _mm_cmplt_ps(d, _mm_setzero_ps()));
    }
    return _mm_movemask_ps(outside) == 0;
}

unsigned FrustumBoxes::intersect_four(size_t at, const PlaneGroups& planes, unsigned crossing) const
{
    const __m128 lo_x = _mm_loadu_ps(&min_x_[at]), lo_y = _mm_loadu_ps(&min_y_[at]), lo_z = _mm_loadu_ps(&min_z_[at]);
    const __m128 hi_x = _mm_loadu_ps(&max_x_[at]), hi_y = _mm_loadu_ps(&max_y_[at]), hi_z = _mm_loadu_ps(&max_z_[at]);
    __m128 outside = _mm_setzero_ps();
    for (unsigned rest = crossing; rest != 0; rest &= rest - 1) {
        const auto& v = planes.splat[std::countr_zero(rest)];
        // intersects()'s sum, in the same order, for four boxes against plane p.
        __m128 d = _mm_add_ps(_mm_mul_ps(hi_x, _mm_load_ps(v[0])), _mm_mul_ps(lo_x, _mm_load_ps(v[3])));
        d = _mm_add_ps(d, _mm_mul_ps(hi_y, _mm_load_ps(v[1])));
        d = _mm_add_ps(d, _mm_mul_ps(lo_y, _mm_load_ps(v[4])));
        d = _mm_add_ps(d, _mm_mul_ps(hi_z, _mm_load_ps(v[2])));
        d = _mm_add_ps(d, _mm_mul_ps(lo_z, _mm_load_ps(v[5])));
        d = _mm_sub_ps(d, _mm_load_ps(v[6]));
        outside = _mm_or_ps(outside, _mm_cmplt_ps(d, _mm_setzero_ps()));
    }
    return ~unsigned(_mm_movemask_ps(outside)) & 15u;
}

size_t FrustumBoxes::collect_all(const PlaneGroups& planes, uint32_t* out) const
{
    const size_t n = boxes_.size();
    size_t kept = 0, i = 0;
    const unsigned every_plane = all_planes(planes);
    for (; i + 4 <= n; i += 4) {
        const unsigned inside = intersect_four(i, planes, every_plane);
        for (unsigned lane = 0; lane < 4; ++lane) { // branch-free append
            out[kept] = uint32_t(i + lane);
            kept += (inside >> lane) & 1u;
        }
    }
    for (; i < n; ++i) {
        out[kept] = uint32_t(i);
        kept += size_t(intersects(uint32_t(i), planes));
    }
    return kept;
}


#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define PVS_EIGHT_BOXES_AVX 1

namespace {

// intersect_four's test on eight boxes with AVX (no FMA, so every sum is rounded as the SSE and
// scalar forms round it: the same answers), for the CPUs that have it (checked once at run time).
__attribute__((target("avx"))) unsigned intersect_eight_avx(const float* lo_x_at, const float* lo_y_at,
                                                            const float* lo_z_at, const float* hi_x_at,
                                                            const float* hi_y_at, const float* hi_z_at,
                                                            const FrustumBoxes::PlaneGroups& planes, unsigned crossing)
{
    const __m256 lo_x = _mm256_loadu_ps(lo_x_at), lo_y = _mm256_loadu_ps(lo_y_at), lo_z = _mm256_loadu_ps(lo_z_at);
    const __m256 hi_x = _mm256_loadu_ps(hi_x_at), hi_y = _mm256_loadu_ps(hi_y_at), hi_z = _mm256_loadu_ps(hi_z_at);
    __m256 outside = _mm256_setzero_ps();
    for (unsigned rest = crossing; rest != 0; rest &= rest - 1) {
        const auto& v = planes.splat[std::countr_zero(rest)];
        __m256 d = _mm256_add_ps(_mm256_mul_ps(hi_x, _mm256_broadcast_ss(&v[0][0])),
                                 _mm256_mul_ps(lo_x, _mm256_broadcast_ss(&v[3][0])));
        d = _mm256_add_ps(d, _mm256_mul_ps(hi_y, _mm256_broadcast_ss(&v[1][0])));
        d = _mm256_add_ps(d, _mm256_mul_ps(lo_y, _mm256_broadcast_ss(&v[4][0])));
        d = _mm256_add_ps(d, _mm256_mul_ps(hi_z, _mm256_broadcast_ss(&v[2][0])));
        d = _mm256_add_ps(d, _mm256_mul_ps(lo_z, _mm256_broadcast_ss(&v[5][0])));
        d = _mm256_sub_ps(d, _mm256_broadcast_ss(&v[6][0]));
        outside = _mm256_or_ps(outside, _mm256_cmp_ps(d, _mm256_setzero_ps(), _CMP_LT_OQ));
    }
    return ~unsigned(_mm256_movemask_ps(outside)) & 255u;
}

// Whether this CPU runs the AVX path. __builtin_cpu_init first: this initializer may run before
// libgcc's own CPU detection, and __builtin_cpu_supports would then answer false.
bool cpu_has_avx()
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx");
}

const bool kHasAvx = cpu_has_avx();

} // namespace
#endif

uint64_t FrustumBoxes::intersect_mask(uint32_t first, uint32_t count, const PlaneGroups& planes, unsigned crossing,
                                      uint64_t wanted) const
{
    // The groups (eight with AVX, else four) that hold a wanted box, found a word operation at a
    // time; after the last whole four, box by box.
    const auto low_bits = [](uint32_t n) { return n >= 64 ? ~uint64_t{0} : (uint64_t{1} << n) - 1; };
    const uint32_t whole = count & ~3u;
    uint64_t mask = 0, rest = wanted & low_bits(whole);
#if defined(PVS_EIGHT_BOXES_AVX)
    if (kHasAvx)
        for (uint64_t left = rest & low_bits(count & ~7u); left != 0;) {
            const uint32_t i = uint32_t(std::countr_zero(left)) & ~7u;
            left &= ~(uint64_t{255} << i);
            rest &= ~(uint64_t{255} << i);
            const size_t at = size_t(first) + i;
            // Only the fours `wanted` names keep their bits, as the four-box path gives them.
            const unsigned fours = ((wanted >> i) & 15u ? 15u : 0u) | ((wanted >> (i + 4)) & 15u ? 240u : 0u);
            mask |= uint64_t(intersect_eight_avx(&min_x_[at], &min_y_[at], &min_z_[at], &max_x_[at], &max_y_[at],
                                                 &max_z_[at], planes, crossing) &
                             fours)
                    << i;
        }
#endif
    for (uint64_t left = rest; left != 0;) {
        const uint32_t i = uint32_t(std::countr_zero(left)) & ~3u;
        left &= ~(uint64_t{15} << i);
        mask |= uint64_t(intersect_four(size_t(first) + i, planes, crossing)) << i;
    }
    for (uint32_t i = whole; i < count; ++i)
        if ((wanted >> i) & 1u)
            mask |= uint64_t(intersects(first + i, planes)) << i;
    return mask;
}

#else

bool FrustumBoxes::intersects(uint32_t box, const PlaneGroups& planes) const
{
    const PackedBox& b = boxes_[box];
    bool outside = false;
    for (int g = 0; g < planes.group_count; ++g)
        for (int k = 0; k < 4; ++k) {
            float d = (b.max[0] * planes.pos_x[g][k] + b.min[0] * planes.neg_x[g][k]);
            d += b.max[1] * planes.pos_y[g][k];
            d += b.min[1] * planes.neg_y[g][k];
            d += b.max[2] * planes.pos_z[g][k];
            d += b.min[2] * planes.neg_z[g][k];
            outside |= d - planes.dist[g][k] < 0.0f;
        }
    return !outside;
}

size_t FrustumBoxes::collect_all(const PlaneGroups& planes, uint32_t* out) const
{
    size_t kept = 0;
    for (size_t i = 0; i < boxes_.size(); ++i) {
        out[kept] = uint32_t(i);
        kept += size_t(intersects(uint32_t(i), planes));
    }
    return kept;
}


uint64_t FrustumBoxes::intersect_mask(uint32_t first, uint32_t count, const PlaneGroups& planes, unsigned,
                                      uint64_t wanted) const
{
    uint64_t mask = 0;
    for (uint32_t i = 0; i < count; ++i)
        if ((wanted >> i) & 1u)
            mask |= uint64_t(intersects(first + i, planes)) << i;
    return mask;
}

#endif

uint64_t FrustumBoxes::near_mask(uint32_t first, uint32_t count, const glm::vec3& p, float limit) const
{
    uint64_t mask = 0;
    uint32_t i = 0;
#if defined(__SSE2__)
    const __m128 zero = _mm_setzero_ps(), bound = _mm_set1_ps(limit);
    const __m128 px = _mm_set1_ps(p.x), py = _mm_set1_ps(p.y), pz = _mm_set1_ps(p.z);
    // squared_distance's max(min - p, p - max, 0) per axis; max(0, NaN) is NaN here (SSE's max
    // returns its second operand when one is NaN), so a NaN eye is never near, as in the scalar form.
    const auto axis = [&](const float* lo, const float* hi, __m128 at) {
        const __m128 d = _mm_max_ps(zero, _mm_max_ps(_mm_sub_ps(_mm_loadu_ps(lo), at), _mm_sub_ps(at, _mm_loadu_ps(hi))));
        return _mm_mul_ps(d, d);
    };
    for (; i + 4 <= count; i += 4) {
        const size_t at = size_t(first) + i;
        const __m128 sum = _mm_add_ps(_mm_add_ps(axis(&min_x_[at], &max_x_[at], px), axis(&min_y_[at], &max_y_[at], py)),
                                      axis(&min_z_[at], &max_z_[at], pz));
        mask |= uint64_t(_mm_movemask_ps(_mm_cmple_ps(sum, bound))) << i;
    }
#endif
    for (; i < count; ++i)
        mask |= uint64_t(squared_distance(first + i, p) <= limit) << i;
    return mask;
}

uint64_t FrustumBoxes::intersect_mask(uint32_t first, uint32_t count, const PlaneGroups& planes) const
{
    return intersect_mask(first, count, planes, all_planes(planes), ~uint64_t{0});
}

} // namespace pvs
