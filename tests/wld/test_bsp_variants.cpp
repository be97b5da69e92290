// BSP2 and 2PSB (wld/quake/bsp_layout.h) against files made elsewhere: ericw-tools' qbsp wrote
// lqdm2 three times (BSP 29, -bsp2, -2psb: ../shared/data/modern-quake/q1) from one map, with one
// .prt. Each variant must read as the same level, bake the same rows from that .prt, and be
// written back in its own variant with every byte but the visibility lump and the leaves' visofs
// and ambient levels unchanged.
#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/file_error.h"
#include "visibility/methods/vis_method.h"
#include "visibility/portal/portal_vis.h"
#include "wld/quake/ambient_sounds.h"
#include "wld/quake/bsp29_reader.h"
#include "wld/quake/bsp29_vis_writer.h"
#include "wld/quake/bsp_lumps.h"
#include "wld/quake/prt_file.h"

#include <gtest/gtest.h>

#include <cstring>

namespace pvs::quake {
namespace {

const char* const kVariants[] = {"modern-quake/q1/lqdm2.bsp", "modern-quake/q1/lqdm2-bsp2.bsp",
                                 "modern-quake/q1/lqdm2-2psb.bsp"};

std::vector<std::vector<uint64_t>> rows_of(const Pvs& pvs)
{
    std::vector<std::vector<uint64_t>> rows(pvs.row_count(), std::vector<uint64_t>(pvs.words_per_row()));
    for (uint32_t r = 0; r < pvs.row_count(); ++r)
        pvs.decode_row(r, rows[r]);
    return rows;
}

TEST(BspVariants, TheThreeFilesReadAsOneLevel)
{
    std::vector<Zone> zones;
    for (const char* variant : kVariants) {
        SHARED_DATA_OR_SKIP(path, variant);
        zones.push_back(load_bsp29(test::read_bytes(path), path));
    }
    EXPECT_EQ(zones[0].source.version, "29");
    EXPECT_EQ(zones[1].source.version, "BSP2");
    EXPECT_EQ(zones[2].source.version, "2PSB");
    for (size_t v = 1; v < zones.size(); ++v) {
        const Zone &a = zones[0], &b = zones[v];
        ASSERT_EQ(b.region_count(), a.region_count()) << kVariants[v];
        EXPECT_EQ(b.region_count(), 848u);
        for (uint32_t r = 0; r < a.region_count(); ++r) {
            ASSERT_EQ(b.regions[r].flags, a.regions[r].flags) << "region " << r;
            // BSP2 stores leaf bounds as floats, the others as shorts rounded outward.
            ASSERT_NEAR(b.regions[r].bounds.min.x, a.regions[r].bounds.min.x, 1.0f) << "region " << r;
            ASSERT_NEAR(b.regions[r].bounds.max.z, a.regions[r].bounds.max.z, 1.0f) << "region " << r;
        }
        ASSERT_EQ(b.tree.nodes.size(), a.tree.nodes.size());
        for (size_t n = 0; n < a.tree.nodes.size(); ++n) {
            ASSERT_EQ(b.tree.nodes[n].normal, a.tree.nodes[n].normal) << "node " << n;
            ASSERT_EQ(b.tree.nodes[n].dist, a.tree.nodes[n].dist) << "node " << n;
            ASSERT_EQ(b.tree.nodes[n].children[0], a.tree.nodes[n].children[0]) << "node " << n;
            ASSERT_EQ(b.tree.nodes[n].children[1], a.tree.nodes[n].children[1]) << "node " << n;
        }
        EXPECT_EQ(b.tree.leaf_region, a.tree.leaf_region);
        EXPECT_EQ(b.mesh.positions, a.mesh.positions);
        EXPECT_EQ(b.mesh.indices, a.mesh.indices);
        EXPECT_EQ(b.region_faces, a.region_faces);
        EXPECT_EQ(b.region_face_offsets, a.region_face_offsets);
        ASSERT_EQ(b.materials.size(), a.materials.size());
        for (size_t m = 0; m < a.materials.size(); ++m)
            EXPECT_EQ(b.materials[m].name, a.materials[m].name);
    }
}

// The leaf records of `bytes` with visofs and the ambient levels blanked, and every other lump:
// what a vis may not change.
std::vector<std::vector<uint8_t>> untouchable(const std::vector<uint8_t>& bytes)
{
    const ByteReader in(bytes, "x.bsp");
    const BspLumps bsp = read_bsp_lumps(in);
    std::vector<std::vector<uint8_t>> lumps;
    for (int i = 0; i < kBspLumpCount; ++i) {
        if (i == kLumpVisibility)
            continue;
        const BspLumpSpan& l = bsp.lumps[i];
        std::vector<uint8_t> body(bytes.begin() + std::ptrdiff_t(l.offset), bytes.begin() + std::ptrdiff_t(l.offset + l.length));
        if (i == kLumpLeafs)
            for (uint32_t leaf = 0; leaf < l.count; ++leaf) {
                std::memset(body.data() + leaf * bsp.layout.leaf_size + 4, 0, 4);
                std::memset(body.data() + leaf * bsp.layout.leaf_size + bsp.layout.leaf_ambient, 0, 4);
            }
        lumps.push_back(std::move(body));
    }
    return lumps;
}

TEST(BspVariants, TheSamePrtBakesTheSameRowsAndEachIsWrittenBackInItsVariant)
{
    SHARED_DATA_OR_SKIP(prt_path, "modern-quake/q1/lqdm2.prt");
    std::vector<std::vector<std::vector<uint64_t>>> baked;
    std::vector<std::vector<AmbientLevels>> sounds;
    for (const char* variant : kVariants) {
        SHARED_DATA_OR_SKIP(path, variant);
        const std::vector<uint8_t> bytes = test::read_bytes(path);
        const Zone zone = load_bsp29(bytes, path);
        PrtFile prt = load_prt(prt_path);
        ASSERT_EQ(prt.leaf_count, zone.region_count());
        VisParams params;
        params.threads = 2;
        const Pvs pvs = bake_portal_vis(prt.portals, uint32_t(zone.region_count()), params);
        baked.push_back(rows_of(pvs));
        const std::vector<AmbientLevels> levels = compute_ambient_levels(bytes, pvs, {}, path);
        sounds.push_back(levels);
        const std::vector<uint8_t> written = write_bsp29_vis(bytes, pvs, "out.bsp", nullptr, levels);
        EXPECT_EQ(std::memcmp(written.data(), bytes.data(), 4), 0) << variant << ": the variant is kept";
        EXPECT_EQ(untouchable(written), untouchable(bytes)) << variant;
        const Zone back = load_bsp29(written, "out.bsp");
        ASSERT_TRUE(back.baked_pvs.has_value());
        EXPECT_EQ(rows_of(*back.baked_pvs), baked.back()) << variant;
        EXPECT_EQ(read_ambient_levels(written, "out.bsp"), levels) << variant;
    }
    EXPECT_EQ(baked[1], baked[0]);
    EXPECT_EQ(baked[2], baked[0]);
    EXPECT_EQ(sounds[1], sounds[0]);
    EXPECT_EQ(sounds[2], sounds[0]);
}

// ericw's vis of each variant: its ambient levels come back from its own PVS (the BSP2 file's
// PVS differs from the others by a few bits, README: mean 480.6 against 480.85).
TEST(BspVariants, EricwsAmbientLevelsComeBackInEveryVariant)
{
    for (const char* variant : {"modern-quake/q1/lqdm2-bsp2.ericw-vis.bsp", "modern-quake/q1/lqdm2-2psb.ericw-vis.bsp"}) {
        SHARED_DATA_OR_SKIP(path, variant);
        const std::vector<uint8_t> bytes = test::read_bytes(path);
        const Zone zone = load_bsp29(bytes, path);
        ASSERT_TRUE(zone.baked_pvs.has_value());
        EXPECT_EQ(compute_ambient_levels(bytes, *zone.baked_pvs, {}, path), read_ambient_levels(bytes, path)) << variant;
    }
}

TEST(BspVariants, OtherFormatsAreNamedInTheError)
{
    const auto error_of = [](std::vector<uint8_t> header) {
        header.resize(200, 0);
        try {
            load_bsp29(header, "x.bsp");
        } catch (const FileError& e) {
            return std::string(e.what());
        }
        return std::string("(loaded)");
    };
    EXPECT_NE(error_of({'I', 'B', 'S', 'P', 38, 0, 0, 0}).find("Quake 2 IBSP version 38"), std::string::npos);
    EXPECT_NE(error_of({'I', 'B', 'S', 'P', 46, 0, 0, 0}).find("Quake 3 IBSP version 46"), std::string::npos);
    EXPECT_NE(error_of({30, 0, 0, 0}).find("Half-Life BSP 30"), std::string::npos);
    EXPECT_NE(error_of({'B', 'S', 'P', '2'}), "(loaded)") << "an empty BSP2 is no level";
}

} // namespace
} // namespace pvs::quake
