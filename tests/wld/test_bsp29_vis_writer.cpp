// Writing a PVS into a Quake BSP 29 file (wld/quake/bsp29_vis_writer.h), on maps compiled
// elsewhere (../shared/data): the file's own PVS written back reads back row for row; another
// PVS (seeded random rows with repeats and missing rows) reads back as given; every lump but
// VISIBILITY and the leaves' visofs is byte-identical to the original; identical rows share one
// offset; hostile input gives a FileError naming the offset.
#include "wld/quake/bsp29_vis_writer.h"

#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/file_error.h"
#include "wld/quake/bsp29_reader.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <set>
#include <stdexcept>

namespace pvs {
namespace {

constexpr int kLumps = 15, kVis = 4, kLeafs = 10;

struct Lump {
    int32_t offset, length;
};

Lump lump(const std::vector<uint8_t>& bsp, int index)
{
    Lump l;
    std::memcpy(&l.offset, bsp.data() + 4 + 8 * index, 4);
    std::memcpy(&l.length, bsp.data() + 8 + 8 * index, 4);
    return l;
}

std::vector<uint8_t> lump_bytes(const std::vector<uint8_t>& bsp, int index)
{
    const Lump l = lump(bsp, index);
    return {bsp.begin() + l.offset, bsp.begin() + l.offset + l.length};
}

int32_t visofs(const std::vector<uint8_t>& bsp, uint32_t leaf)
{
    int32_t v;
    std::memcpy(&v, bsp.data() + lump(bsp, kLeafs).offset + 28 * leaf + 4, 4);
    return v;
}

std::vector<std::vector<uint64_t>> rows_of(const Pvs& pvs)
{
    std::vector<std::vector<uint64_t>> rows(pvs.region_count(), std::vector<uint64_t>(pvs.words_per_row()));
    for (uint32_t r = 0; r < pvs.region_count(); ++r)
        pvs.decode_row(r, rows[r]);
    return rows;
}

// Everything but the VISIBILITY lump and the visofs field of each leaf is the original's.
void expect_other_bytes_unchanged(const std::vector<uint8_t>& original, const std::vector<uint8_t>& written)
{
    for (int i = 0; i < kLumps; ++i) {
        if (i == kVis)
            continue;
        std::vector<uint8_t> a = lump_bytes(original, i), b = lump_bytes(written, i);
        ASSERT_EQ(a.size(), b.size()) << "lump " << i;
        EXPECT_EQ(lump(written, i).offset % 4, 0) << "lump " << i << " is not 4-byte aligned";
        if (i == kLeafs)
            for (size_t leaf = 0; leaf < a.size() / 28; ++leaf) {
                std::memset(a.data() + 28 * leaf + 4, 0, 4);
                std::memset(b.data() + 28 * leaf + 4, 0, 4);
            }
        EXPECT_TRUE(a == b) << "lump " << i << " changed";
    }
}

class VisWriter : public ::testing::TestWithParam<std::string> {};

TEST_P(VisWriter, TheFilesOwnPvsReadsBackRowForRow)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const std::vector<uint8_t> original = test::read_bytes(path);
    const Zone zone = quake::load_bsp29(original, path);
    ASSERT_TRUE(zone.baked_pvs.has_value());
    quake::Bsp29VisStats stats;
    const std::vector<uint8_t> written = quake::write_bsp29_vis(original, *zone.baked_pvs, "out.bsp", &stats);
    const Zone back = quake::load_bsp29(written, "out.bsp");
    ASSERT_TRUE(back.baked_pvs.has_value());
    EXPECT_EQ(rows_of(*back.baked_pvs), rows_of(*zone.baked_pvs));
    EXPECT_EQ(back.baked_pvs->missing_row_count(), zone.baked_pvs->missing_row_count());
    expect_other_bytes_unchanged(original, written);
    EXPECT_EQ(visofs(written, 0), -1);
    EXPECT_EQ(stats.rows, zone.region_count() - zone.baked_pvs->missing_row_count());
    EXPECT_EQ(stats.visdata_bytes, size_t(lump(written, kVis).length));
    // The same mesh, tree and regions come back (the other lumps are the original's).
    EXPECT_EQ(back.mesh.positions, zone.mesh.positions);
    EXPECT_EQ(back.region_faces, zone.region_faces);
}

INSTANTIATE_TEST_SUITE_P(Maps, VisWriter, ::testing::Values("quake/e1m1.bsp", "visdemo/example.bsp"),
                         [](const auto& p) { return test::param_name(p.param); });

// With ambient levels, leaf r+1's four ambient bytes are the ones given and nothing else changes
// beyond visofs: computed from a PVS that is not the file's (every leaf sees only itself), the
// levels are those of each leaf's own surfaces, and read back as written.
TEST(VisWriter, AmbientLevelsGoIntoTheLeavesAndNothingElseMoves)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    const std::vector<uint8_t> original = test::read_bytes(path);
    const Zone zone = quake::load_bsp29(original, path);
    const uint32_t n = uint32_t(zone.region_count());
    const Pvs alone = Pvs::build(n, [](uint32_t r, std::span<uint64_t> row) {
        bits::set(row, r);
        return true;
    });
    const std::vector<quake::AmbientLevels> levels = quake::compute_ambient_levels(original, alone, {}, path);
    const std::vector<uint8_t> written = quake::write_bsp29_vis(original, alone, "out.bsp", nullptr, levels);
    EXPECT_EQ(quake::read_ambient_levels(written, "out.bsp"), levels);
    // A leaf alone hears only its own surfaces: fewer than with the file's PVS, but some.
    size_t heard = 0, heard_by_file = 0;
    for (const quake::AmbientLevels& l : levels)
        heard += l != quake::AmbientLevels{0, 0, 0, 0};
    for (const quake::AmbientLevels& l : quake::read_ambient_levels(original, path))
        heard_by_file += l != quake::AmbientLevels{0, 0, 0, 0};
    EXPECT_GT(heard, 0u);
    EXPECT_LT(heard, heard_by_file);
    // Blank the ambient bytes of both; then only VISIBILITY and visofs may differ.
    std::vector<uint8_t> a = original, b = written;
    for (std::vector<uint8_t>* file : {&a, &b})
        for (uint32_t leaf = 1; leaf <= n; ++leaf)
            std::memset(file->data() + lump(*file, kLeafs).offset + 28 * leaf + 24, 0, 4);
    expect_other_bytes_unchanged(a, b);
    EXPECT_THROW(quake::write_bsp29_vis(original, alone, "out.bsp", nullptr,
                                        std::span<const quake::AmbientLevels>(levels).first(3)),
                 std::invalid_argument);
}

// Seeded random rows: some missing, some repeated, the rest of varied density.
Pvs random_pvs(uint32_t regions, uint32_t seed)
{
    return Pvs::build(regions, [&](uint32_t r, std::span<uint64_t> row) {
        std::mt19937 rng(seed + (r % 7 == 3 ? 0 : r)); // every 7th row from 3 on: the same row
        if (r % 11 == 5)
            return false; // missing
        const double density = double(rng() % 100) / 100.0;
        for (uint32_t j = 0; j < regions; ++j)
            if (double(rng() % 1000) / 1000.0 < density * density)
                bits::set(row, j);
        return true;
    });
}

TEST(VisWriter, AnotherPvsReadsBackAsGivenAndRepeatedRowsShareAnOffset)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    const std::vector<uint8_t> original = test::read_bytes(path);
    const uint32_t regions = 1206;
    const Pvs given = random_pvs(regions, 42);
    quake::Bsp29VisStats stats;
    const std::vector<uint8_t> written = quake::write_bsp29_vis(original, given, "out.bsp", &stats);
    const Zone back = quake::load_bsp29(written, "out.bsp");
    ASSERT_TRUE(back.baked_pvs.has_value());
    EXPECT_EQ(rows_of(*back.baked_pvs), rows_of(given));
    for (uint32_t r = 0; r < regions; ++r)
        EXPECT_EQ(back.baked_pvs->row_missing(r), r % 11 == 5) << r;
    expect_other_bytes_unchanged(original, written);

    // Missing rows are visofs -1, repeated rows one offset, distinct rows distinct offsets;
    // leaves after visleafs (brush entities) -1.
    std::set<int32_t> repeated_offsets, offsets;
    for (uint32_t r = 0; r < regions; ++r) {
        const int32_t v = visofs(written, r + 1);
        if (r % 11 == 5) {
            EXPECT_EQ(v, -1);
            continue;
        }
        offsets.insert(v);
        if (r % 7 == 3)
            repeated_offsets.insert(v);
    }
    EXPECT_EQ(repeated_offsets.size(), 1u);
    EXPECT_EQ(offsets.size(), stats.unique_rows);
    const uint32_t leaf_count = uint32_t(lump(written, kLeafs).length / 28);
    for (uint32_t leaf = regions + 1; leaf < leaf_count; ++leaf)
        EXPECT_EQ(visofs(written, leaf), -1) << leaf;
}

TEST(VisWriter, APvsOfAnotherSizeIsRefused)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.bsp");
    const std::vector<uint8_t> original = test::read_bytes(path);
    const Pvs wrong = random_pvs(5, 1);
    EXPECT_THROW(quake::write_bsp29_vis(original, wrong, path), std::invalid_argument);
}

std::string error_of(const std::vector<uint8_t>& bytes, const Pvs& pvs)
{
    try {
        quake::write_bsp29_vis(bytes, pvs, "bad.bsp");
    } catch (const FileError& e) {
        return e.what();
    }
    return "no error";
}

TEST(VisWriter, HostileFilesGiveAnErrorNamingTheOffset)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.bsp");
    const std::vector<uint8_t> original = test::read_bytes(path);
    const Zone zone = quake::load_bsp29(original, path);
    ASSERT_TRUE(zone.baked_pvs.has_value());
    const Pvs& pvs = *zone.baked_pvs;

    EXPECT_NE(error_of({}, pvs).find("offset 0"), std::string::npos) << error_of({}, pvs);
    EXPECT_NE(error_of({original.begin(), original.begin() + 60}, pvs).find("header"), std::string::npos);

    std::vector<uint8_t> bad = original;
    bad[0] = 30;
    EXPECT_NE(error_of(bad, pvs).find("Half-Life BSP 30"), std::string::npos) << error_of(bad, pvs);

    bad = original;
    const int32_t negative = -8;
    std::memcpy(bad.data() + 4 + 8 * kLeafs, &negative, 4);
    EXPECT_NE(error_of(bad, pvs).find("negative offset"), std::string::npos) << error_of(bad, pvs);

    bad = original;
    const int32_t huge = int32_t(original.size());
    std::memcpy(bad.data() + 8 + 8 * kLeafs, &huge, 4);
    EXPECT_NE(error_of(bad, pvs).find("runs past the end"), std::string::npos) << error_of(bad, pvs);

    bad = original;
    const int32_t too_many = 1 << 20;
    std::memcpy(bad.data() + lump(original, 14).offset + 52, &too_many, 4);
    EXPECT_NE(error_of(bad, pvs).find("visleafs"), std::string::npos) << error_of(bad, pvs);

    bad = original;
    const int32_t odd_length = lump(original, kLeafs).length - 1;
    std::memcpy(bad.data() + 8 + 8 * kLeafs, &odd_length, 4);
    EXPECT_NE(error_of(bad, pvs).find("is not a multiple of its BSP 29 record size 28"), std::string::npos) << error_of(bad, pvs);
}

} // namespace
} // namespace pvs
