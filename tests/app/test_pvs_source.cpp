// The `--pvs` sources of walk and render: "baked" is the file's own PVS, "none" is none, and
// the two bakes on visdemo's example.bsp give PVSs of the zone's size where portal-full is a
// subset of portal-fast row by row (the base flow is a superset of the full flow, §3.2-§3.4 of
// quake-doom-hepvs.md) and every region sees itself.
#include "app/pvs_source.h"

#include "tests/support/test_data.h"
#include "visibility/bit_row.h"

#include <gtest/gtest.h>

namespace pvs::app {
namespace {

TEST(PvsSource, BakedIsTheFilesAndNoneIsNone)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.bsp");
    const Zone& zone = *test::shared_zone("visdemo/example.bsp");
    ASSERT_TRUE(zone.baked_pvs);
    EXPECT_EQ(make_pvs_source(zone, "baked").pvs, &*zone.baked_pvs);
    EXPECT_EQ(make_pvs_source(zone, "none").pvs, nullptr);
    EXPECT_THROW(make_pvs_source(zone, "portal-medium"), std::invalid_argument);
}

TEST(PvsSource, PortalFullIsASubsetOfPortalFastAndEveryRegionSeesItself)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.bsp");
    const Zone& zone = *test::shared_zone("visdemo/example.bsp");
    const PvsSource fast = make_pvs_source(zone, "portal-fast");
    const PvsSource full = make_pvs_source(zone, "portal-full");
    ASSERT_NE(fast.pvs, nullptr);
    ASSERT_NE(full.pvs, nullptr);
    ASSERT_EQ(fast.pvs->region_count(), zone.region_count());
    ASSERT_EQ(full.pvs->region_count(), zone.region_count());
    EXPECT_NE(full.note.find("portal-full"), std::string::npos);
    std::vector<uint64_t> a(fast.pvs->words_per_row()), b(full.pvs->words_per_row());
    size_t fast_bits = 0, full_bits = 0;
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        fast.pvs->decode_row(r, a);
        full.pvs->decode_row(r, b);
        EXPECT_TRUE(bits::test(b, r)) << "region " << r;
        for (size_t w = 0; w < a.size(); ++w)
            EXPECT_EQ(b[w] & ~a[w], 0u) << "region " << r << " word " << w;
        fast_bits += bits::count(a);
        full_bits += bits::count(b);
    }
    EXPECT_LE(full_bits, fast_bits);
    EXPECT_LT(full_bits, zone.region_count() * zone.region_count()); // something is hidden
}

} // namespace
} // namespace pvs::app
