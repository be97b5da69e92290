// The PVS edit stack (visibility/pvs_edits.h): pairs one way and both ways, rows filled and
// cleared, undo restoring exactly the bits that were there, redo, a new edit dropping the redo
// stack, the popping risk against a reference, and re-applying the intents to another bake.
#include "visibility/pvs_edits.h"

#include "visibility/bit_row.h"

#include <gtest/gtest.h>

namespace pvs {
namespace {

// 6 regions; region r sees r and r+1 (a chain), as bits set by hand.
Pvs chain(uint32_t n = 6)
{
    return Pvs::build(n, [n](uint32_t r, std::span<uint64_t> row) {
        bits::set(row, r);
        if (r + 1 < n)
            bits::set(row, r + 1);
        return true;
    });
}

std::vector<std::vector<bool>> matrix(const EditablePvs& e)
{
    std::vector<std::vector<bool>> m(e.row_count(), std::vector<bool>(e.region_count()));
    for (uint32_t r = 0; r < e.row_count(); ++r)
        for (uint32_t c = 0; c < e.region_count(); ++c)
            m[r][c] = e.visible(r, c);
    return m;
}

TEST(PvsEdits, PairsRowsUndoAndRedo)
{
    const Pvs base = chain();
    EditablePvs e(base);
    const auto original = matrix(e);
    e.apply(pair_edit(0, 4, true, true));
    EXPECT_TRUE(e.visible(0, 4));
    EXPECT_TRUE(e.visible(4, 0));
    EXPECT_TRUE(e.edited(4, 0));
    e.apply(pair_edit(2, 3, false, false));
    EXPECT_FALSE(e.visible(2, 3));
    EXPECT_TRUE(e.visible(3, 3));
    e.apply(cleared_row_edit(1));
    for (uint32_t c = 0; c < 6; ++c)
        EXPECT_EQ(e.visible(1, c), c == 1) << c; // a region keeps seeing itself
    e.apply(pair_edit(5, 5, false, false));
    EXPECT_TRUE(e.visible(5, 5)) << "the self bit stays";
    EXPECT_EQ(e.edit_count(), 4u);

    for (int i = 0; i < 4; ++i)
        e.undo();
    EXPECT_EQ(matrix(e), original);
    EXPECT_FALSE(e.can_undo());
    e.redo();
    e.redo();
    EXPECT_TRUE(e.visible(4, 0));
    EXPECT_FALSE(e.visible(2, 3));
    EXPECT_TRUE(e.can_redo());
    e.apply(pair_edit(3, 0, true, false));
    EXPECT_FALSE(e.can_redo()) << "a new edit drops the redo stack";
    EXPECT_EQ(e.edits().size(), 3u);
}

TEST(PvsEdits, RowFromAnotherPvsAndPoppingRisk)
{
    const Pvs base = chain();
    const Pvs everything = Pvs::build(6, [](uint32_t, std::span<uint64_t> row) {
        bits::fill(row, 6);
        return true;
    });
    EditablePvs e(base);
    e.apply(row_edit_from(everything, 2, "reference"));
    for (uint32_t c = 0; c < 6; ++c)
        EXPECT_TRUE(e.visible(2, c));
    EXPECT_EQ(e.popping_risk(everything), 0u);
    // Hides 2->5 (set by the row fill) and 5->2 (already hidden in the chain: not the edit's doing).
    e.apply(pair_edit(2, 5, false, true));
    EXPECT_EQ(e.popping_risk(everything), 1u);
    e.undo();
    EXPECT_EQ(e.popping_risk(everything), 0u);
    EXPECT_THROW(e.apply(pair_edit(0, 6, true, false)), std::invalid_argument);
}

TEST(PvsEdits, IntentsReapplyToAnotherBake)
{
    EditablePvs e(chain());
    e.apply(pair_edit(0, 3, true, false));
    e.apply(pair_edit(1, 2, false, false));
    // A "re-bake" in which 1 already saw 3 and 0 saw 2.
    const Pvs rebake = Pvs::build(6, [](uint32_t r, std::span<uint64_t> row) {
        bits::set(row, r);
        if (r == 1) {
            bits::set(row, 2);
            bits::set(row, 3);
        }
        if (r == 0)
            bits::set(row, 2);
        return true;
    });
    const Pvs out = apply_edits(rebake, e.edits());
    EXPECT_TRUE(out.visible(0, 3));
    EXPECT_TRUE(out.visible(0, 2)) << "the re-bake's own bits stay";
    EXPECT_FALSE(out.visible(1, 2));
    EXPECT_TRUE(out.visible(1, 3));
    const Pvs same = e.to_pvs();
    for (uint32_t r = 0; r < 6; ++r)
        for (uint32_t c = 0; c < 6; ++c)
            EXPECT_EQ(same.visible(r, c), e.visible(r, c));
}

} // namespace
} // namespace pvs
