// The source portals of a base vis batch (base_vis_batch.h) as lanes of SSE vectors, and the
// sphere tests of quick_verdict (base_vis_tables.h) asked of many lanes at once.
//
// Why. A batch tests 9 lanes on average where its flood meets a portal (5000 generated rooms);
// one lane at a time, each test's branches follow the geometry and do not predict. Four lanes
// to a vector, the spheres' verdicts come out as bit masks with no branch per lane.
//
// Contract. For every lane in `lanes`, lanes_in_front gives SourcePortal::leaf_in_front and
// sphere_verdicts gives quick_verdict's answer where the spheres decide it (might_see /
// cannot_see; a lane in neither is left to verdict_near_planes), computed with the same float
// operations in the same order, so the masks are bit for bit what the scalar code answers.
// Lanes outside `lanes` come out unset. SSE is part of x86-64's baseline; elsewhere each lane
// asks the scalar functions of base_vis_tables.h (leaf_in_front, sphere_verdict) in turn.
#pragma once

#include "visibility/portal/base_vis_tables.h"

#include <bit>
#include <cstdint>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace pvs::portal_vis {

struct SphereVerdicts {
    uint64_t might_see = 0, cannot_see = 0;
};

class SourceLanes {
public:
    static constexpr uint32_t kLanes = 64;

    void set(uint32_t lane, const SourcePortal& p)
    {
        sx_[lane] = p.sphere.x, sy_[lane] = p.sphere.y, sz_[lane] = p.sphere.z, sr_[lane] = p.sphere.w;
        px_[lane] = p.plane.x, py_[lane] = p.plane.y, pz_[lane] = p.plane.z, pw_[lane] = p.plane.w;
    }

    // SourcePortal::leaf_in_front of the leaf whose header sphere is `leaf`, for each lane.
    uint64_t lanes_in_front(const BaseVisTables& tables, const Float4& leaf, uint64_t lanes) const
    {
        uint64_t front = 0;
        for_each_quad(lanes, [&](uint32_t q) {
#if defined(__SSE__)
            const __m128 d = distance4(px_ + q, py_ + q, pz_ + q, pw_ + q, leaf);
            const __m128 over = _mm_cmpgt_ps(_mm_sub_ps(d, _mm_set1_ps(leaf.w)), _mm_set1_ps(tables.beyond_f));
            front |= uint64_t(unsigned(_mm_movemask_ps(over))) << q;
#else
            for (uint32_t l = q; l < q + 4; ++l)
                front |= uint64_t(leaf_in_front(tables, plane(l), leaf)) << l;
#endif
        });
        return front & lanes;
    }

    // quick_verdict's sphere tests of the portal of slot t for each lane; `front`: the lanes for
    // which t's leaf lies in front (lanes_in_front).
    SphereVerdicts sphere_verdicts(const BaseVisTables& tables, const FloodSlot& t, uint64_t lanes,
                                   uint64_t front) const
    {
#if defined(__SSE__)
        uint64_t cannot_a = 0, behind = 0, cannot_b = 0, see_b = 0;
        for_each_quad(lanes, [&](uint32_t q) {
            const __m128 slack = _mm_set1_ps(tables.slack_f), beyond = _mm_set1_ps(tables.beyond_f);
            const __m128 r = _mm_loadu_ps(sr_ + q), t_r = _mm_set1_ps(t.sphere.w);
            // 2. d2: p's sphere centre against t's plane; 1. d1: t's sphere centre against p's plane.
            const __m128 d2 = distance4(t.plane, sx_ + q, sy_ + q, sz_ + q);
            const __m128 d1 = distance4(px_ + q, py_ + q, pz_ + q, pw_ + q, t.sphere);
            const __m128 minus_d2 = _mm_sub_ps(_mm_setzero_ps(), d2);
            cannot_a |= mask(_mm_cmpgt_ps(_mm_sub_ps(d2, slack), r), q);
            behind |= mask(_mm_cmpgt_ps(_mm_sub_ps(minus_d2, r), beyond), q);
            cannot_b |= mask(_mm_cmplt_ps(_mm_add_ps(d1, slack), _mm_sub_ps(_mm_setzero_ps(), t_r)), q);
            see_b |= mask(_mm_cmpgt_ps(_mm_sub_ps(d1, t_r), beyond), q);
        });
        // As sphere_verdict: test 2's sphere first; then, where t's leaf is in front, test 2's
        // verdict alone, else t's own sphere against p's plane.
        const uint64_t might = ~cannot_a & behind & (front | see_b);
        const uint64_t cannot = cannot_a | (~front & cannot_b);
        return {might & lanes, cannot & ~might & lanes};
#else
        SphereVerdicts out;
        for (uint64_t rest = lanes; rest != 0; rest &= rest - 1) {
            const uint32_t l = uint32_t(std::countr_zero(rest));
            const Verdict v = sphere_verdict(tables, plane(l), {sx_[l], sy_[l], sz_[l], sr_[l]}, t, (front >> l) & 1);
            out.might_see |= uint64_t(v == Verdict::kMightSee) << l;
            out.cannot_see |= uint64_t(v == Verdict::kCannotSee) << l;
        }
        return out;
#endif
    }

private:
    Float4 plane(uint32_t l) const { return {px_[l], py_[l], pz_[l], pw_[l]}; }
    // visit(4q) for each quad of lanes (4q .. 4q + 3) with a lane in `lanes`.
    template <class Visit>
    static void for_each_quad(uint64_t lanes, Visit&& visit)
    {
        while (lanes != 0) {
            const uint32_t first = uint32_t(std::countr_zero(lanes)) & ~3u;
            visit(first);
            lanes &= ~(uint64_t{15} << first);
        }
    }
#if defined(__SSE__)
    static uint64_t mask(__m128 m, uint32_t q) { return uint64_t(unsigned(_mm_movemask_ps(m))) << q; }
    // ((a.x * b.x + a.y * b.y) + a.z * b.z) - a.w, as distance() in base_vis_tables.h.
    static __m128 distance4(const float* x, const float* y, const float* z, const float* w, const Float4& point)
    {
        const __m128 xy = _mm_add_ps(_mm_mul_ps(_mm_loadu_ps(x), _mm_set1_ps(point.x)),
                                     _mm_mul_ps(_mm_loadu_ps(y), _mm_set1_ps(point.y)));
        return _mm_sub_ps(_mm_add_ps(xy, _mm_mul_ps(_mm_loadu_ps(z), _mm_set1_ps(point.z))), _mm_loadu_ps(w));
    }
    static __m128 distance4(const Float4& plane, const float* x, const float* y, const float* z)
    {
        const __m128 xy = _mm_add_ps(_mm_mul_ps(_mm_set1_ps(plane.x), _mm_loadu_ps(x)),
                                     _mm_mul_ps(_mm_set1_ps(plane.y), _mm_loadu_ps(y)));
        return _mm_sub_ps(_mm_add_ps(xy, _mm_mul_ps(_mm_set1_ps(plane.z), _mm_loadu_ps(z))), _mm_set1_ps(plane.w));
    }
#endif

    float sx_[kLanes] = {}, sy_[kLanes] = {}, sz_[kLanes] = {}, sr_[kLanes] = {};
    float px_[kLanes] = {}, py_[kLanes] = {}, pz_[kLanes] = {}, pw_[kLanes] = {};
};

} // namespace pvs::portal_vis
