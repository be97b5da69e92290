// The horizon sweep's dependency table (terrain/horizon_parents.h): every segment from a point of
// the footprint to a point of a column crosses each of the column's strips through its parents,
// and parents come first in the sweep. Checked by marching segments finely (a cell whose inside a
// sample falls in was crossed), for several footprint sizes, against the definition of strips.
#include "visibility/terrain/horizon_parents.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

namespace pvs {
namespace {

TEST(HorizonParents, GapsAreColumnGapsFromTheFootprint)
{
    const HorizonParents t(3, 2, 12, 12);
    EXPECT_EQ(t.gap(0, 0), 0u);
    EXPECT_EQ(t.gap(2, 1), 0u);
    EXPECT_EQ(t.gap(3, 1), 1u);
    EXPECT_EQ(t.gap(-1, -1), 2u);
    EXPECT_EQ(t.gap(5, 0), 3u);
    EXPECT_EQ(t.gap(1, -4), 4u);
    EXPECT_EQ(t.gap(-2, 6), 7u);
    EXPECT_EQ(t.strip_count(t.offset_index(3, 0)), 0u) << "no whole column between";
    EXPECT_EQ(t.strip_count(t.offset_index(4, 0)), 1u);
    EXPECT_EQ(t.strip_count(t.offset_index(4, 3)), 2u);
    EXPECT_EQ(t.strip_count(t.offset_index(-2, -2)), 2u);
}

TEST(HorizonParents, HullTestMatchesTheDefinition)
{
    // The hull of the 1x1 footprint and the column at (4, 0) is the strip 0 <= y <= 1, 0 <= x <= 5.
    const HorizonParents t(1, 1, 10, 10);
    EXPECT_TRUE(t.meets_hull(4, 0, 2, 0, true));
    EXPECT_TRUE(t.meets_hull(4, 0, 2, 1));        // touches the strip's top edge
    EXPECT_FALSE(t.meets_hull(4, 0, 2, 1, true)); // but its inside does not meet it
    EXPECT_FALSE(t.meets_hull(4, 0, 2, 2));
    EXPECT_TRUE(t.meets_hull(4, 0, 2, -1));       // touches its bottom edge
    // Diagonal: the hull of (0,0) and (3,3) is the band between the lines y = x - 1 and y = x + 1.
    EXPECT_TRUE(t.meets_hull(3, 3, 1, 1, true));
    EXPECT_TRUE(t.meets_hull(3, 3, 0, 2));        // its corner (1, 2) is on the line y = x + 1
    EXPECT_FALSE(t.meets_hull(3, 3, 0, 2, true));
    EXPECT_FALSE(t.meets_hull(3, 3, 0, 3));       // its nearest corner (1, 3) is above it
    EXPECT_TRUE(t.meets_hull(3, 3, 2, 0));        // its corner (2, 1) is on y = x - 1
    EXPECT_FALSE(t.meets_hull(3, 3, 3, 0));
}

// Every segment from R to C crosses each strip of C through insides of that strip's "inside"
// parents, or along an edge between two of its parents; and every parent read for its slope
// comes earlier in the sweep order than C.
TEST(HorizonParents, EverySegmentCrossesEachStripThroughItsParents)
{
    const int n = 14;
    for (const auto& [w, h] : {std::pair{1u, 1u}, {2u, 1u}, {1u, 3u}, {3u, 2u}}) {
        const HorizonParents t(w, h, n, n);
        std::vector<uint32_t> rank(t.order().size());
        for (uint32_t i = 0; i < t.order().size(); ++i)
            rank[t.order()[i]] = i;
        std::mt19937 rng(w * 7 + h);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        int segments = 0, edge_runs = 0;
        for (int dy = -(n - 1); dy <= n - 1; ++dy)
            for (int dx = -(n - 1); dx <= n - 1; ++dx) {
                const uint32_t index = t.offset_index(dx, dy);
                std::set<std::pair<uint32_t, int>> inside, any; // (offset, strip)
                for (const auto* p = t.parents_begin(index); p != t.parents_end(index); ++p) {
                    any.insert({p->offset, p->strip});
                    if (p->inside) {
                        inside.insert({p->offset, p->strip});
                        ASSERT_LT(rank[p->offset], rank[index]) << "a parent is swept before its child";
                    }
                }
                // The strips, as in the table: a column strip first, then a row strip.
                std::vector<std::pair<bool, int>> strips; // (column strip, position)
                if (dx >= int(w) + 1)
                    strips.push_back({true, dx - 1});
                else if (dx <= -2)
                    strips.push_back({true, dx + 1});
                if (dy >= int(h) + 1)
                    strips.push_back({false, dy - 1});
                else if (dy <= -2)
                    strips.push_back({false, dy + 1});
                ASSERT_EQ(strips.size(), t.strip_count(index));
                for (int s = 0; s < 8 && !strips.empty(); ++s, ++segments) {
                    // Corners as well as inner points: the extreme segments run along the hull's edges.
                    const bool corner = s < 3;
                    const double px = corner ? double(rng() % (w + 1)) : unit(rng) * w;
                    const double py = corner ? double(rng() % (h + 1)) : unit(rng) * h;
                    const double qx = dx + (corner ? double(rng() % 2) : unit(rng));
                    const double qy = dy + (corner ? double(rng() % 2) : unit(rng));
                    for (size_t k = 0; k < strips.size(); ++k) {
                        const auto [column_strip, at] = strips[k];
                        bool crossed = false;
                        for (int i = 1; i < 3000; ++i) {
                            const double a = i / 3000.0;
                            const double x = px + (qx - px) * a, y = py + (qy - py) * a;
                            const double across = column_strip ? x : y, along = column_strip ? y : x;
                            if (across <= at || across >= at + 1)
                                continue;
                            const int cell_along = int(std::floor(along));
                            auto offset = [&](int c) { return column_strip ? t.offset_index(at, c) : t.offset_index(c, at); };
                            if (along == std::floor(along)) { // on an edge between two strip cells
                                ++edge_runs;
                                ASSERT_TRUE(any.count({offset(cell_along), int(k)}) && any.count({offset(cell_along - 1), int(k)}))
                                    << dx << "," << dy << " strip " << k;
                                crossed = true;
                                continue;
                            }
                            crossed = true;
                            ASSERT_TRUE(inside.count({offset(cell_along), int(k)}))
                                << "footprint " << w << "x" << h << ", column (" << dx << "," << dy << "), strip " << k
                                << ": the segment crosses cell " << cell_along << " which is not an inside parent";
                        }
                        ASSERT_TRUE(crossed);
                    }
                }
            }
        EXPECT_GT(segments, 1000);
        EXPECT_GT(edge_runs, 0) << "some segments run along grid lines";
    }
}

} // namespace
} // namespace pvs
