// PRT2 and PRT1-AM portal files (wld/quake/prt_file.h, ../shared/formats/quake-doom-hepvs.md
// §2.2, §2.3): hand-written files in the layouts the spec gives (ericw-tools writes PRT2, reads
// PRT1-AM), their cluster maps, a PRT2 written and read back, and bad files: each a FileError
// naming the file, the offset and the problem. A PRT2 next to a .bsp is not shown as its portals
// (they join clusters, not regions).
#include "tests/support/test_data.h"
#include "visibility/file_error.h"
#include "wld/quake/prt_file.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace pvs {
namespace {

using quake::PrtFile;
using quake::PrtVersion;

// 4 leaves in 3 clusters ({0, 2}, {1}, {3}); portals between clusters 0-1 and 1-2.
const std::string kPrt2 = "PRT2\n4\n3\n2\n"
                          "4 0 1 (0 0 0 ) (0 4 0 ) (0 4 4 ) (0 0 4 ) \n"
                          "3 1 2 (0 5 0 ) (2 5 0 ) (2 5 2 ) \n"
                          "0 2 -1\n1 -1\n3 -1\n";
// The same in PRT1-AM: clusters, portals, leafs, portal lines, then the cluster of each leaf.
const std::string kPrt1Am = "PRT1-AM\n3\n2\n4\n"
                            "4 0 1 (0 0 0 ) (0 4 0 ) (0 4 4 ) (0 0 4 ) \n"
                            "3 1 2 (0 5 0 ) (2 5 0 ) (2 5 2 ) \n"
                            "0 1 0 2\n";

struct ParseError {
    bool thrown = false;
    size_t offset = 0;
    std::string reason, what;
};

ParseError error_of(const std::string& text)
{
    ParseError error;
    try {
        quake::parse_prt(text, "bad.prt");
    } catch (const FileError& e) {
        error.thrown = true;
        error.offset = e.offset();
        error.reason = e.reason();
        error.what = e.what();
    }
    return error;
}

#define EXPECT_PRT2_ERROR(text, fragment, at)                                                                \
    do {                                                                                                     \
        const ParseError error_ = error_of(text);                                                            \
        EXPECT_TRUE(error_.thrown) << "parsed without error";                                                \
        EXPECT_NE(error_.reason.find(fragment), std::string::npos) << "reason: " << error_.reason;            \
        EXPECT_EQ(error_.offset, size_t(at)) << "reason: " << error_.reason;                                 \
        EXPECT_NE(error_.what.find("bad.prt"), std::string::npos) << error_.what;                            \
    } while (0)

void expect_small_clustered(const PrtFile& prt)
{
    EXPECT_TRUE(prt.has_clusters());
    EXPECT_EQ(prt.leaf_count, 4u);
    EXPECT_EQ(prt.cluster_count, 3u);
    EXPECT_EQ(prt.cluster_of_leaf, (std::vector<uint32_t>{0, 1, 0, 2}));
    ASSERT_EQ(prt.portals.portals.size(), 2u);
    EXPECT_EQ(prt.portals.portals[0].regions[0], 0);
    EXPECT_EQ(prt.portals.portals[0].regions[1], 1);
    EXPECT_EQ(prt.portals.portals[1].regions[0], 1);
    EXPECT_EQ(prt.portals.portals[1].regions[1], 2);
    EXPECT_EQ(prt.portals.portals[1].point_count, 3u);
    ASSERT_EQ(prt.portals.points.size(), 7u);
    EXPECT_EQ(prt.portals.points[6], glm::vec3(2, 5, 2));
}

TEST(Prt2File, Prt2AndPrt1AmGiveTheSameClusters)
{
    const PrtFile prt2 = quake::parse_prt(kPrt2, "small.prt");
    EXPECT_EQ(prt2.version, PrtVersion::Prt2);
    expect_small_clustered(prt2);
    const PrtFile am = quake::parse_prt(kPrt1Am, "small-am.prt");
    EXPECT_EQ(am.version, PrtVersion::Prt1Am);
    expect_small_clustered(am);
}

TEST(Prt2File, WritingGivesPrt2ThatReadsBack)
{
    const PrtFile am = quake::parse_prt(kPrt1Am, "small-am.prt");
    const std::string text = quake::format_prt(am); // PRT1-AM is written as PRT2
    EXPECT_EQ(text, kPrt2);
    const PrtFile back = quake::parse_prt(text, "written.prt");
    EXPECT_EQ(back.version, PrtVersion::Prt2);
    expect_small_clustered(back);

    PrtFile bad = back;
    bad.cluster_of_leaf[3] = 3;
    EXPECT_THROW(quake::format_prt(bad), std::invalid_argument);
    bad = back;
    bad.cluster_of_leaf.pop_back();
    EXPECT_THROW(quake::format_prt(bad), std::invalid_argument);
    bad = back;
    bad.portals.portals[1].regions[1] = 3; // a cluster number past the 3 clusters
    EXPECT_THROW(quake::format_prt(bad), std::invalid_argument);
}

TEST(Prt2File, BadClusterMapsAreRefusedWithOffsets)
{
    const std::string head = "PRT2\n4\n3\n2\n"
                             "4 0 1 (0 0 0 ) (0 4 0 ) (0 4 4 ) (0 0 4 ) \n"
                             "3 1 2 (0 5 0 ) (2 5 0 ) (2 5 2 ) \n";
    const size_t map_at = head.size();
    EXPECT_PRT2_ERROR(head + "0 2 -1\n1 -1\n", "file ends early in cluster 2 of 3", map_at + 12);
    EXPECT_PRT2_ERROR(head + "0 2 -1\n1 -1\n4 -1\n", "cluster 2 of 3: leaf number 4 is out of range", map_at + 12);
    EXPECT_PRT2_ERROR(head + "0 2 -1\n1 0 -1\n3 -1\n", "cluster 1 of 3: leaf 0 is already in cluster 0", map_at + 9);
    EXPECT_PRT2_ERROR(head + "0 -1\n1 -1\n3 -1\n", "leaf 2 is in no cluster", map_at + 14);
    EXPECT_PRT2_ERROR(head + "0 2 -1\n1 -1\n3 -1\n7\n", "unexpected '7' after the last of the cluster map", map_at + 17);
    EXPECT_PRT2_ERROR(head + "0 x -1\n", "expected the leaf number or -1 (an integer), found 'x'", map_at + 2);
    // Portal endpoints are clusters: 3 is past the 3 clusters even though there are 4 leaves.
    EXPECT_PRT2_ERROR("PRT2\n4\n3\n1\n3 0 3 (0 0 0) (1 0 0) (1 1 0)\n", "cluster number 3 is out of range", 15);

    const std::string am_head = "PRT1-AM\n3\n2\n4\n"
                                "4 0 1 (0 0 0 ) (0 4 0 ) (0 4 4 ) (0 0 4 ) \n"
                                "3 1 2 (0 5 0 ) (2 5 0 ) (2 5 2 ) \n";
    EXPECT_PRT2_ERROR(am_head + "0 1 0\n", "file ends early in the cluster map, leaf 3 of 4", am_head.size() + 6);
    EXPECT_PRT2_ERROR(am_head + "0 1 5 2\n", "leaf 2 of 4: cluster number 5 is out of range", am_head.size() + 4);
    EXPECT_PRT2_ERROR(am_head + "0 1 -1 2\n", "cluster number -1 is out of range", am_head.size() + 4);
}

TEST(Prt2File, AHostileClusterCountDoesNotAllocate)
{
    // 2^31-1 leaves and clusters declared in a tiny file: it must fail on the missing text, not
    // on memory (PRT2 would assign its map per declared leaf: refused before that).
    EXPECT_PRT2_ERROR("PRT1-AM\n2147483647\n0\n2147483647\n", "file ends early in the cluster map, leaf 0", 32);
    EXPECT_PRT2_ERROR("PRT2\n2147483647\n1\n0\n", "declares 2147483647 leaves, but the 0 bytes left cannot list them", 20);
    // More clusters than leaves: a bake over them would cost clusters^2 bits, so the header is
    // refused at the cluster count, whatever follows.
    EXPECT_PRT2_ERROR("PRT2\n2\n2147483647\n0\n0 -1\n1 -1\n", "declares 2147483647 clusters for 2 leaves", 7);
    EXPECT_PRT2_ERROR("PRT1-AM\n3\n0\n2\n0 1\n", "declares 3 clusters for 2 leaves", 8);
}

TEST(Prt2File, AClusteredSiblingPortalFileIsNotTakenForLeafPortals)
{
    SHARED_DATA_OR_SKIP(bsp, "visdemo/example.bsp");
    SHARED_DATA_OR_SKIP(prt1, "visdemo/example.prt");
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("pvscope_prt2_sibling_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::filesystem::copy_file(bsp, dir / "example.bsp", std::filesystem::copy_options::overwrite_existing);
    PrtFile clustered = quake::load_prt(prt1);
    clustered.version = PrtVersion::Prt2; // every leaf its own cluster
    clustered.cluster_count = clustered.leaf_count;
    clustered.cluster_of_leaf.resize(clustered.leaf_count);
    std::iota(clustered.cluster_of_leaf.begin(), clustered.cluster_of_leaf.end(), 0u);
    quake::save_prt((dir / "example.prt").string(), clustered);

    const Zone zone = load_zone((dir / "example.bsp").string());
    std::filesystem::remove_all(dir);
    EXPECT_FALSE(zone.portals.has_value());
    EXPECT_TRUE(std::any_of(zone.source.notes.begin(), zone.source.notes.end(), [](const std::string& note) {
        return note.find("clustered portal file") != std::string::npos;
    }));
}

} // namespace
} // namespace pvs
