// The part file (.pvsp) of a sharded bake: what is written reads back the same, and hostile bytes
// (every truncation, a bad magic or version, lengths that lie, sources out of order, corrupt zlib)
// give a FileError naming the file and the offset - never a crash or a huge allocation.
#include "visibility/file_error.h"
#include "wld/pvs_part_file.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace pvs::test {
namespace {

PvsPart sample_part()
{
    PvsPart part;
    part.zone_hash = 0x0123456789abcdefull;
    part.shard = 1;
    part.shards = 3;
    part.join = PartRows::Union;
    part.row_count = 130;
    part.region_count = 130; // three words a row, the last one partial
    part.settings = R"({"method":"raster"})";
    part.sources = {1, 4, 129};
    for (size_t i = 0; i < part.sources.size() * 3; ++i)
        part.rows.push_back(0x9e3779b97f4a7c15ull * (i + 1) & (i % 3 == 2 ? 0x3ull : ~0ull));
    return part;
}

uint32_t u32_at(const std::vector<uint8_t>& bytes, size_t at)
{
    uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}

void put_u32_at(std::vector<uint8_t>& bytes, size_t at, uint32_t v) { std::memcpy(bytes.data() + at, &v, 4); }

TEST(PvsPartFile, RoundTrip)
{
    const PvsPart part = sample_part();
    const PvsPart back = decode_pvs_part(encode_pvs_part(part), "p.pvsp");
    EXPECT_EQ(back.zone_hash, part.zone_hash);
    EXPECT_EQ(back.join, part.join);
    EXPECT_EQ(back.shard, part.shard);
    EXPECT_EQ(back.shards, part.shards);
    EXPECT_EQ(back.row_count, part.row_count);
    EXPECT_EQ(back.region_count, part.region_count);
    EXPECT_EQ(back.settings, part.settings);
    EXPECT_EQ(back.sources, part.sources);
    EXPECT_EQ(back.rows, part.rows);
}

TEST(PvsPartFile, EveryTruncationIsAnErrorNamingTheFile)
{
    const std::vector<uint8_t> bytes = encode_pvs_part(sample_part());
    for (size_t size = 0; size < bytes.size(); ++size) {
        try {
            decode_pvs_part(std::span(bytes.data(), size), "cut.pvsp");
            ADD_FAILURE() << "a file cut to " << size << " bytes was read";
        } catch (const FileError& e) {
            EXPECT_EQ(e.file(), "cut.pvsp");
            EXPECT_LE(e.offset(), size);
        }
    }
    std::vector<uint8_t> longer = bytes;
    longer.push_back(0);
    EXPECT_THROW(decode_pvs_part(longer, "long.pvsp"), FileError);
}

TEST(PvsPartFile, HostileHeadersAreRefusedWithTheirOffset)
{
    const std::vector<uint8_t> good = encode_pvs_part(sample_part());
    const size_t settings_size = sample_part().settings.size();
    const size_t sources_at = 44 + settings_size + 4;
    struct Case {
        const char* what;
        size_t at;
        uint32_t value;
        uint64_t offset; // where the error must point
    } cases[] = {
        {"magic", 0, 0x58585858, 0},
        {"version", 8, 2, 8},
        {"shard past the count", 20, 3, 20},
        {"an unknown join rule", 36, 2, 36},
        {"settings longer than the file", 40, 0x7fffffff, 40},
        {"more sources than rows", 44 + settings_size, 131, 44 + settings_size},
        {"a source past the last row", sources_at, 130, sources_at},
        {"sources out of order", sources_at + 4, 1, sources_at + 4},
    };
    for (const Case& c : cases) {
        std::vector<uint8_t> bytes = good;
        put_u32_at(bytes, c.at, c.value);
        try {
            decode_pvs_part(bytes, "bad.pvsp");
            ADD_FAILURE() << c.what << ": read";
        } catch (const FileError& e) {
            EXPECT_EQ(e.offset(), c.offset) << c.what << ": " << e.what();
        }
    }
    // The rows' zlib stream damaged: refused, not read as other rows.
    std::vector<uint8_t> bytes = good;
    const size_t packed_at = sources_at + 3 * 4 + 8;
    ASSERT_EQ(u32_at(bytes, sources_at + 3 * 4), bytes.size() - packed_at);
    for (size_t i = packed_at + 2; i < bytes.size(); ++i)
        bytes[i] ^= 0x5a;
    EXPECT_THROW(decode_pvs_part(bytes, "zlib.pvsp"), FileError);
}

TEST(PvsPartFile, EveryByteFlippedIsReadOrRefusedNeverACrash)
{
    const std::vector<uint8_t> good = encode_pvs_part(sample_part());
    size_t refused = 0;
    for (size_t at = 0; at < good.size(); ++at) {
        std::vector<uint8_t> bytes = good;
        bytes[at] ^= 0xff;
        try {
            const PvsPart part = decode_pvs_part(bytes, "flip.pvsp");
            EXPECT_EQ(part.rows.size(), part.sources.size() * part.words_per_row()) << "flip at " << at;
        } catch (const FileError& e) {
            EXPECT_EQ(e.file(), "flip.pvsp");
            ++refused;
        }
    }
    EXPECT_GT(refused, good.size() / 2) << "most flips break a checked field or the zlib stream";
}

TEST(PvsPartFile, ABitPastTheLastRegionIsRefused)
{
    PvsPart part = sample_part();
    part.rows[2] |= uint64_t{1} << 2; // row 0's third word: region 130 of 130
    try {
        decode_pvs_part(encode_pvs_part(part), "past.pvsp");
        ADD_FAILURE() << "a bit past the last region was read";
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("past region 129"), std::string::npos) << e.what();
    }
}

TEST(PvsPartFile, FnvKnownAnswers)
{
    // FNV-1a 64 test vectors (the FNV authors' published values).
    EXPECT_EQ(fnv1a64({}), 0xcbf29ce484222325ull);
    const uint8_t a[] = {'a'};
    EXPECT_EQ(fnv1a64(a), 0xaf63dc4c8601ec8cull);
    const uint8_t foobar[] = {'f', 'o', 'o', 'b', 'a', 'r'};
    EXPECT_EQ(fnv1a64(foobar), 0x85944171f73967e8ull);
}

} // namespace
} // namespace pvs::test
