// EverQuest PFS archives (.s3d), ../shared/formats/eq-s3d-wld.md §1 and §8.3: the filename CRC's
// known answers, the spec's 103-byte archive read and reproduced, round trips through the writer
// (checked against §1.9 by a separate little parser here, not by the reader under test), and bad
// input: hand-made corruptions with the message a user should see, plus a sweep of truncations
// and random byte changes that must either read or throw FileError (CI runs it under ASan+UBSan).
#include "visibility/file_error.h"
#include "wld/eq/pfs_archive.h"
#include "wld/eq/pfs_crc.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace pvs {
namespace {

using eq::PfsArchive;
using eq::PfsMember;
using eq::write_pfs;

std::vector<uint8_t> bytes_of(std::string_view text) { return {text.begin(), text.end()}; }

uint32_t get32(const std::vector<uint8_t>& bytes, size_t at)
{
    uint32_t value = 0;
    std::memcpy(&value, bytes.data() + at, sizeof value);
    return value;
}

void put32(std::vector<uint8_t>& bytes, size_t at, uint32_t value)
{
    std::memcpy(bytes.data() + at, &value, sizeof value);
}

void append32(std::vector<uint8_t>& bytes, uint32_t value)
{
    bytes.resize(bytes.size() + 4);
    put32(bytes, bytes.size() - 4, value);
}

// ---------------------------------------------------------------------------------------------
// §1.6 / §8.3 CRC known answers

TEST(PfsCrc, SpecKnownAnswers)
{
    EXPECT_EQ(eq::pfs_filename_crc("gfaydark.wld"), 0x5942C027u);
    EXPECT_EQ(eq::pfs_crc("gfaydark.wld"), 0x3189B1B0u); // without the NUL
    EXPECT_EQ(eq::pfs_crc("123456789"), 0x89A1897Fu);    // the check value with init 0, not MPEG-2's 0x0376E6E7
    EXPECT_EQ(eq::pfs_filename_crc("objects.wld"), 0x613159E6u);
    EXPECT_EQ(eq::pfs_filename_crc("lights.wld"), 0xDC771C49u);
    EXPECT_EQ(eq::pfs_filename_crc("gfaydark_obj.wld"), 0xE6D60748u);
    EXPECT_EQ(eq::pfs_filename_crc("a.txt"), 0x89779799u);
    EXPECT_EQ(eq::pfs_filename_crc("GFAYDARK.WLD"), 0xEFC08F23u); // case matters to the CRC itself
    EXPECT_EQ(eq::pfs_filename_crc(""), 0u);                      // a lone NUL
}

TEST(PfsCrc, UpdateContinuesAcrossPieces)
{
    EXPECT_EQ(eq::pfs_crc_update(eq::pfs_crc("1234"), "56789"), 0x89A1897Fu);
    EXPECT_EQ(eq::pfs_crc_update(eq::pfs_crc("gfaydark.wld"), std::string_view("\0", 1)), 0x5942C027u);
}

// ---------------------------------------------------------------------------------------------
// A small independent parser for checking what the writer produced against §1.9.

struct RawEntry {
    uint32_t crc, offset, size;
};

std::vector<RawEntry> raw_index(const std::vector<uint8_t>& bytes)
{
    const uint32_t at = get32(bytes, 0);
    std::vector<RawEntry> entries(get32(bytes, at));
    for (size_t i = 0; i < entries.size(); ++i)
        entries[i] = {get32(bytes, at + 4 + 12 * i), get32(bytes, at + 8 + 12 * i), get32(bytes, at + 12 + 12 * i)};
    return entries;
}

// Inflates the run at `offset` holding `size` bytes with zlib's own uncompress, expecting blocks of
// exactly 8192 bytes except the last (§1.9 rule 3). `end` receives where the run ends.
std::vector<uint8_t> raw_run(const std::vector<uint8_t>& bytes, uint32_t offset, uint32_t size, size_t& end)
{
    std::vector<uint8_t> data;
    size_t at = offset;
    while (data.size() < size) {
        const uint32_t compressed = get32(bytes, at), inflated = get32(bytes, at + 4);
        const bool last = data.size() + inflated == size;
        EXPECT_TRUE(last ? inflated >= 1 && inflated <= 8192 : inflated == 8192) << "block at " << at;
        std::vector<uint8_t> block(inflated);
        uLongf length = inflated;
        EXPECT_EQ(uncompress(block.data(), &length, bytes.data() + at + 8, compressed), Z_OK) << "block at " << at;
        EXPECT_EQ(length, inflated);
        data.insert(data.end(), block.begin(), block.end());
        at += 8 + compressed;
        if (data.size() > size) {
            ADD_FAILURE() << "run at " << offset << " overshoots its size";
            break;
        }
    }
    end = at;
    return data;
}

std::vector<uint8_t> name_list_of(const std::vector<std::string>& names)
{
    std::vector<uint8_t> list;
    append32(list, static_cast<uint32_t>(names.size()));
    for (const std::string& name : names) {
        append32(list, static_cast<uint32_t>(name.size() + 1));
        list.insert(list.end(), name.begin(), name.end());
        list.push_back(0);
    }
    return list;
}

// Checks §1.9 on a written archive without footer: header, data from offset 12 in the given name
// order with no gaps, the name list right after, then the index sorted by CRC, then nothing.
void expect_section_1_9_layout(const std::vector<uint8_t>& bytes, const std::vector<PfsMember>& members)
{
    ASSERT_GE(bytes.size(), 16u);
    EXPECT_EQ(std::memcmp(bytes.data() + 4, "PFS ", 4), 0);
    EXPECT_EQ(get32(bytes, 8), 0x00020000u);
    const uint32_t index_offset = get32(bytes, 0);
    const std::vector<RawEntry> index = raw_index(bytes);
    ASSERT_EQ(index.size(), members.size() + 1);
    EXPECT_EQ(bytes.size(), index_offset + 4 + 12 * index.size()) << "nothing may follow the index";
    std::map<uint32_t, RawEntry> by_crc;
    for (size_t i = 0; i < index.size(); ++i) {
        if (i > 0) {
            EXPECT_LT(index[i - 1].crc, index[i].crc) << "index sorted by unsigned CRC";
        }
        by_crc[index[i].crc] = index[i];
    }

    size_t at = 12;
    std::vector<std::string> names;
    for (const PfsMember& member : members) {
        std::string lower = member.name;
        for (char& c : lower)
            c = c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
        names.push_back(lower);
        ASSERT_TRUE(by_crc.contains(eq::pfs_filename_crc(lower))) << lower;
        const RawEntry& e = by_crc[eq::pfs_filename_crc(lower)];
        EXPECT_EQ(e.offset, at) << lower << ": data in name-list order, no gaps";
        EXPECT_EQ(e.size, member.data.size());
        EXPECT_EQ(raw_run(bytes, e.offset, e.size, at), member.data) << lower;
    }
    ASSERT_TRUE(by_crc.contains(eq::kPfsNameListCrc));
    const RawEntry& list = by_crc[eq::kPfsNameListCrc];
    EXPECT_EQ(list.offset, at) << "the name list follows the data";
    EXPECT_EQ(raw_run(bytes, list.offset, list.size, at), name_list_of(names));
    EXPECT_EQ(index_offset, at) << "the index follows the name list";
}

// ---------------------------------------------------------------------------------------------
// §1.10: the 103-byte known-answer archive, built here byte by byte as the spec lists it.

const std::vector<uint8_t> kSpecArchive = {
    0x42, 0x00, 0x00, 0x00, 0x50, 0x46, 0x53, 0x20, 0x00, 0x00, 0x02, 0x00, 0x0d, 0x00, 0x00, 0x00, // 0x00
    0x02, 0x00, 0x00, 0x00, 0x78, 0x01, 0x01, 0x02, 0x00, 0xfd, 0xff, 0x68, 0x69, 0x01, 0x3b, 0x00, // 0x10
    0xd2, 0x19, 0x00, 0x00, 0x00, 0x0e, 0x00, 0x00, 0x00, 0x78, 0x01, 0x01, 0x0e, 0x00, 0xf1, 0xff, // 0x20
    0x01, 0x00, 0x00, 0x00, 0x06, 0x00, 0x00, 0x00, 0x61, 0x2e, 0x74, 0x78, 0x74, 0x00, 0x07, 0xa4, // 0x30
    0x01, 0xf7, 0x02, 0x00, 0x00, 0x00, 0xc9, 0x0a, 0x58, 0x61, 0x21, 0x00, 0x00, 0x00, 0x0e, 0x00, // 0x40
    0x00, 0x00, 0x99, 0x97, 0x77, 0x89, 0x0c, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x53, 0x54, // 0x50
    0x45, 0x56, 0x45, 0x3e, 0x00, 0x00, 0x00,                                                       // 0x60
};

TEST(PfsSpecArchive, OpensAndReadsA_txt)
{
    ASSERT_EQ(kSpecArchive.size(), 103u);
    const PfsArchive archive(kSpecArchive, "spec.s3d");
    EXPECT_EQ(archive.members(), std::vector<std::string>{"a.txt"});
    EXPECT_EQ(archive.read("a.txt"), bytes_of("hi"));
    EXPECT_TRUE(archive.contains("a.txt"));
    EXPECT_TRUE(archive.contains("A.TXT"));
    EXPECT_FALSE(archive.contains("b.txt"));
    EXPECT_EQ(archive.read("A.Txt"), bytes_of("hi"));
    EXPECT_EQ(archive.footer_timestamp(), 0x3E000000u);
    ASSERT_EQ(archive.entries().size(), 1u);
    const eq::PfsEntry& e = archive.entries()[0];
    EXPECT_EQ(e.crc, 0x89779799u);
    EXPECT_EQ(e.data_offset, 12u);
    EXPECT_EQ(e.size, 2u);
    EXPECT_EQ(e.stored_size, 21u);
    EXPECT_EQ(e.block_count, 1u);
}

// The spec's archive follows every §1.9 rule, but stores its blocks with zlib level 0 and carries
// the optional footer, where write_pfs by default compresses at level 9 and writes no footer. With
// those two choices set to the spec's, §1.9 determines every byte, and the writer must match.
TEST(PfsSpecArchive, WriterReproducesItWithTheSpecsLevelAndFooter)
{
    eq::PfsWriteOptions options;
    options.zlib_level = 0;
    options.footer_timestamp = 0x3E000000;
    EXPECT_EQ(write_pfs({{"a.txt", bytes_of("hi")}}, options), kSpecArchive);
    EXPECT_EQ(write_pfs({{"A.TXT", bytes_of("hi")}}, options), kSpecArchive); // names are stored lowercase
}

// With the defaults only the zlib bytes (and so the offsets) and the footer differ; the rest of the
// layout is what the spec's archive shows.
TEST(PfsSpecArchive, DefaultWriterKeepsTheDeterminedLayout)
{
    const std::vector<PfsMember> members = {{"a.txt", bytes_of("hi")}};
    const std::vector<uint8_t> bytes = write_pfs(members);
    expect_section_1_9_layout(bytes, members);
    EXPECT_TRUE(std::equal(bytes.begin() + 4, bytes.begin() + 12, kSpecArchive.begin() + 4)); // "PFS ", version
    EXPECT_EQ(get32(bytes, 16), 2u);                                                          // a.txt's block: 2 bytes
    const std::vector<RawEntry> index = raw_index(bytes), spec_index = raw_index(kSpecArchive);
    ASSERT_EQ(index.size(), spec_index.size());
    for (size_t i = 0; i < index.size(); ++i) {
        EXPECT_EQ(index[i].crc, spec_index[i].crc);
        EXPECT_EQ(index[i].size, spec_index[i].size);
    }
    EXPECT_EQ(index[1].offset, 12u);
    const PfsArchive archive(bytes, "default.s3d");
    EXPECT_EQ(archive.read("a.txt"), bytes_of("hi"));
    EXPECT_EQ(archive.footer_timestamp(), std::nullopt);
    EXPECT_EQ(write_pfs(members), bytes) << "deterministic";
}

TEST(PfsSpecArchive, NameListOfTwoFilesIsTheSpecs54Bytes)
{
    const std::vector<uint8_t> expected = {0x02, 0x00, 0x00, 0x00, 0x0d, 0x00, 0x00, 0x00, 0x67, 0x66, 0x61, 0x79,
                                           0x64, 0x61, 0x72, 0x6b, 0x2e, 0x77, 0x6c, 0x64, 0x00, 0x0b, 0x00, 0x00,
                                           0x00, 0x73, 0x67, 0x72, 0x61, 0x73, 0x73, 0x2e, 0x62, 0x6d, 0x70, 0x00};
    // §1.10 calls this "54 bytes", but the sequence it lists (4 + 4 + 13 + 4 + 11) is 36 bytes,
    // 0x24; 54 is 0x36, so the count was probably written in hex. The bytes are what we check.
    ASSERT_EQ(expected.size(), 36u);
    const std::vector<uint8_t> bytes = write_pfs({{"gfaydark.wld", bytes_of("wld")}, {"sgrass.bmp", bytes_of("bmp")}});
    for (const RawEntry& e : raw_index(bytes))
        if (e.crc == eq::kPfsNameListCrc) {
            size_t end = 0;
            EXPECT_EQ(raw_run(bytes, e.offset, e.size, end), expected);
        }
}

// ---------------------------------------------------------------------------------------------
// Round trips

std::vector<uint8_t> random_bytes(size_t size, uint32_t seed)
{
    std::mt19937 rng(seed);
    std::vector<uint8_t> out(size);
    for (uint8_t& b : out)
        b = static_cast<uint8_t>(rng());
    return out;
}

// Text-like data that deflates well, with a little noise so blocks differ.
std::vector<uint8_t> compressible_bytes(size_t size, uint32_t seed)
{
    std::mt19937 rng(seed);
    std::vector<uint8_t> out;
    out.reserve(size + 64);
    while (out.size() < size) {
        const std::string line = "region " + std::to_string(rng() % 977) + " sees regions 1-200 except " +
                                 std::to_string(rng() % 53) + "\n";
        out.insert(out.end(), line.begin(), line.end());
    }
    out.resize(size);
    return out;
}

std::vector<PfsMember> sample_members()
{
    return {
        {"Empty.TXT", {}},
        {"one.BIN", {0x42}},
        {"Random.bin", random_bytes(100 * 1024, 1)},
        {"GFayDark.WLD", compressible_bytes(300 * 1024, 2)},
        {"lights.wld", bytes_of("light 1 2 3\n")},
        {"exact.bmp", random_bytes(2 * 8192, 3)}, // ends on a block boundary
    };
}

TEST(PfsRoundTrip, RandomMembersReadBackAndRewriteIdentically)
{
    const std::vector<PfsMember> members = sample_members();
    const std::vector<uint8_t> bytes = write_pfs(members);
    expect_section_1_9_layout(bytes, members);
    EXPECT_EQ(write_pfs(members), bytes) << "same input, same bytes";

    const PfsArchive archive(bytes, "round.s3d");
    const std::vector<std::string> expected_names = {"empty.txt", "one.bin", "random.bin",
                                                     "gfaydark.wld", "lights.wld", "exact.bmp"};
    EXPECT_EQ(archive.members(), expected_names);
    EXPECT_EQ(archive.footer_timestamp(), std::nullopt);
    std::vector<PfsMember> read_back;
    for (const PfsMember& member : members) {
        EXPECT_TRUE(archive.contains(member.name));
        EXPECT_EQ(archive.read(member.name), member.data) << member.name;
    }
    for (const std::string& name : archive.members())
        read_back.push_back({name, archive.read(name)});
    EXPECT_EQ(write_pfs(read_back), bytes) << "write -> read -> write";

    const auto& entries = archive.entries();
    EXPECT_EQ(entries[0].block_count, 0u); // the empty member: no blocks
    EXPECT_EQ(entries[0].data_offset, entries[1].data_offset);
    EXPECT_EQ(entries[2].block_count, 13u); // 100 KiB in 8 KiB blocks
    EXPECT_EQ(entries[5].block_count, 2u);
}

TEST(PfsRoundTrip, EmptyArchiveHoldsOnlyTheNameList)
{
    const std::vector<uint8_t> bytes = write_pfs({});
    expect_section_1_9_layout(bytes, {});
    const PfsArchive archive(bytes, "empty.s3d");
    EXPECT_TRUE(archive.members().empty());
    EXPECT_FALSE(archive.contains("a.txt"));
}

TEST(PfsRoundTrip, FooterTimestampIsWrittenBigEndianAndReadBack)
{
    eq::PfsWriteOptions options;
    options.footer_timestamp = 0x12345678;
    const std::vector<uint8_t> bytes = write_pfs({{"a.txt", bytes_of("hi")}}, options);
    const std::vector<uint8_t> tail(bytes.end() - 9, bytes.end());
    EXPECT_EQ(tail, (std::vector<uint8_t>{'S', 'T', 'E', 'V', 'E', 0x12, 0x34, 0x56, 0x78}));
    EXPECT_EQ(PfsArchive(bytes, "footer.s3d").footer_timestamp(), 0x12345678u);
}

TEST(PfsWriter, RefusesMembersNoReaderCouldUse)
{
    const auto refuses = [](const std::vector<PfsMember>& members) {
        EXPECT_THROW(write_pfs(members), std::invalid_argument);
    };
    refuses({{"", bytes_of("x")}});
    refuses({{"maps/a.wld", bytes_of("x")}});
    refuses({{"a\\b.wld", bytes_of("x")}});
    refuses({{std::string("a\0b", 3), bytes_of("x")}});
    refuses({{"caf\xc3\xa9.txt", bytes_of("x")}});
    refuses({{std::string(1024, 'a'), bytes_of("x")}});
    refuses({{"a.txt", bytes_of("x")}, {"A.TXT", bytes_of("y")}});
    eq::PfsWriteOptions bad_level;
    bad_level.zlib_level = 10;
    EXPECT_THROW(write_pfs({{"a.txt", bytes_of("x")}}, bad_level), std::invalid_argument);
    EXPECT_NO_THROW(write_pfs({{std::string(1023, 'a'), bytes_of("x")}}));
}

// ---------------------------------------------------------------------------------------------
// Bad input

// Any FileError must name the archive; a problem inside a member must also name the member.
std::string open_error(const std::vector<uint8_t>& bytes, const std::string& file = "zone.s3d")
{
    try {
        const PfsArchive archive(bytes, file);
        for (const std::string& name : archive.members())
            archive.read(name);
    } catch (const FileError& e) {
        EXPECT_EQ(e.file().rfind(file, 0), 0u) << e.what();
        return e.what();
    }
    return "(read)";
}

#define EXPECT_MESSAGE(message, part) EXPECT_NE((message).find(part), std::string::npos) << (message)

// An archive assembled from raw parts, for corruptions the writer would never produce: each
// {crc, payload} becomes a run from offset 12 on, in order, then the index in the same order.
struct RawPart {
    uint32_t crc;
    std::vector<uint8_t> payload;
};

std::vector<uint8_t> assemble(const std::vector<RawPart>& parts)
{
    std::vector<uint8_t> out(12, 0);
    std::vector<RawEntry> index;
    for (const RawPart& part : parts) {
        index.push_back({part.crc, static_cast<uint32_t>(out.size()), static_cast<uint32_t>(part.payload.size())});
        for (size_t at = 0; at < part.payload.size(); at += 8192) {
            const size_t length = std::min<size_t>(8192, part.payload.size() - at);
            std::vector<uint8_t> z(compressBound(8192));
            uLongf z_length = z.size();
            EXPECT_EQ(compress2(z.data(), &z_length, part.payload.data() + at, length, 9), Z_OK);
            append32(out, static_cast<uint32_t>(z_length));
            append32(out, static_cast<uint32_t>(length));
            out.insert(out.end(), z.begin(), z.begin() + static_cast<std::ptrdiff_t>(z_length));
        }
    }
    put32(out, 0, static_cast<uint32_t>(out.size()));
    std::memcpy(out.data() + 4, "PFS ", 4);
    put32(out, 8, 0x00020000);
    append32(out, static_cast<uint32_t>(index.size()));
    for (const RawEntry& e : index) {
        append32(out, e.crc);
        append32(out, e.offset);
        append32(out, e.size);
    }
    return out;
}

// gfaydark.wld (three blocks) then a.txt ("hi", one block), as write_pfs makes them.
class PfsBadInput : public ::testing::Test {
protected:
    void SetUp() override
    {
        bytes_ = write_pfs({{"gfaydark.wld", compressible_bytes(20000, 4)}, {"a.txt", bytes_of("hi")}});
        ASSERT_EQ(open_error(bytes_), "(read)");
    }
    // The index entry (its offset in the file) with this CRC.
    size_t entry_at(uint32_t crc) const
    {
        const uint32_t index = get32(bytes_, 0);
        for (uint32_t i = 0; i < get32(bytes_, index); ++i)
            if (get32(bytes_, index + 4 + 12 * i) == crc)
                return index + 4 + 12 * i;
        ADD_FAILURE() << "no entry with CRC " << crc;
        return 0;
    }
    size_t a_txt() const { return entry_at(eq::pfs_filename_crc("a.txt")); }
    size_t gfaydark() const { return entry_at(eq::pfs_filename_crc("gfaydark.wld")); }
    std::vector<uint8_t> bytes_;
};

TEST_F(PfsBadInput, TruncatedHeader)
{
    bytes_.resize(8);
    EXPECT_MESSAGE(open_error(bytes_), "zone.s3d: offset 0 (0x0): truncated header: the file has 8 bytes");
}

TEST_F(PfsBadInput, WrongMagic)
{
    std::memcpy(bytes_.data() + 4, "PKZ\x03", 4);
    EXPECT_MESSAGE(open_error(bytes_), "offset 4 (0x4): not a PFS archive: the magic is 'PKZ\\x03'");
}

TEST_F(PfsBadInput, WrongVersion)
{
    put32(bytes_, 8, 0x00010000);
    EXPECT_MESSAGE(open_error(bytes_), "unsupported PFS version 0x00010000");
}

TEST_F(PfsBadInput, IndexOffsetPastTheEnd)
{
    put32(bytes_, 0, static_cast<uint32_t>(bytes_.size() + 100));
    EXPECT_MESSAGE(open_error(bytes_), "the index offset " + std::to_string(bytes_.size() + 100));
    EXPECT_MESSAGE(open_error(bytes_), "is past the end of the file");
}

TEST_F(PfsBadInput, IndexCountPastTheEnd)
{
    put32(bytes_, get32(bytes_, 0), 1000000);
    EXPECT_MESSAGE(open_error(bytes_), "the index declares 1000000 entries, but only 3 fit");
}

TEST_F(PfsBadInput, EntryPointingPastTheEnd)
{
    put32(bytes_, a_txt() + 4, static_cast<uint32_t>(bytes_.size() + 10));
    EXPECT_MESSAGE(open_error(bytes_), "outside the file's data");
    EXPECT_MESSAGE(open_error(bytes_), "offset " + std::to_string(a_txt() + 4));
}

TEST_F(PfsBadInput, EntryWhoseBlockHeaderRunsPastTheEnd)
{
    put32(bytes_, a_txt() + 4, static_cast<uint32_t>(bytes_.size() - 4));
    EXPECT_MESSAGE(open_error(bytes_), "zone.s3d: member 'a.txt': offset");
    EXPECT_MESSAGE(open_error(bytes_), "block 0 header runs past the end of the data");
}

TEST_F(PfsBadInput, BlockWhoseZlibDataRunsPastTheEnd)
{
    const uint32_t block = get32(bytes_, gfaydark() + 4);
    put32(bytes_, block, 0x7FFFFFFF);
    EXPECT_MESSAGE(open_error(bytes_), "zone.s3d: member 'gfaydark.wld': offset " + std::to_string(block + 8));
    EXPECT_MESSAGE(open_error(bytes_), "block 0 zlib data runs past the end of the data");
}

TEST_F(PfsBadInput, BlockInflatingToMoreThanDeclared)
{
    // a.txt's block holds "hi"; declare 1 byte in both the block header and the index.
    put32(bytes_, get32(bytes_, a_txt() + 4) + 4, 1);
    put32(bytes_, a_txt() + 8, 1);
    EXPECT_MESSAGE(open_error(bytes_), "zone.s3d: member 'a.txt'");
    EXPECT_MESSAGE(open_error(bytes_), "block 0 inflates to more than the 1 bytes its header declares");
}

TEST_F(PfsBadInput, BlockInflatingToLessThanDeclared)
{
    put32(bytes_, get32(bytes_, a_txt() + 4) + 4, 3);
    put32(bytes_, a_txt() + 8, 3);
    EXPECT_MESSAGE(open_error(bytes_), "block 0 inflates to 2 bytes, but its header declares 3");
}

TEST_F(PfsBadInput, BlocksNotAddingUpToTheEntrysSize)
{
    put32(bytes_, a_txt() + 8, 1); // the block declares 2
    EXPECT_MESSAGE(open_error(bytes_), "block 0 declares 2 inflated bytes, but only 1 of the entry's 1 bytes remain");
    put32(bytes_, get32(bytes_, a_txt() + 4) + 4, 9000);
    put32(bytes_, a_txt() + 8, 9000);
    EXPECT_MESSAGE(open_error(bytes_), "block 0 declares 9000 inflated bytes; a block holds 1 to 8192");
}

TEST_F(PfsBadInput, BlockDeclaringMoreThanZlibCanProduce)
{
    // 2 zlib bytes cannot inflate to 8192: refused before anything is allocated or inflated.
    const uint32_t block = get32(bytes_, gfaydark() + 4);
    put32(bytes_, block, 2);
    EXPECT_MESSAGE(open_error(bytes_),
                   "block 0 declares 8192 inflated bytes from 2 zlib bytes, more than zlib can produce");
}

TEST_F(PfsBadInput, CorruptZlibData)
{
    const uint32_t block = get32(bytes_, gfaydark() + 4);
    std::vector<uint8_t> bad_header = bytes_;
    bad_header[block + 8] ^= 0x01; // 0x78 0xDA no longer a valid zlib header
    EXPECT_MESSAGE(open_error(bad_header), "zone.s3d: member 'gfaydark.wld': offset " + std::to_string(block + 8));
    EXPECT_MESSAGE(open_error(bad_header), "block 0 has corrupt zlib data (incorrect header check)");

    std::vector<uint8_t> bad_adler = bytes_;
    bad_adler[block + 8 + get32(bytes_, block) - 1] ^= 0xFF; // the last byte of the Adler-32
    EXPECT_MESSAGE(open_error(bad_adler), "block 0 has corrupt zlib data (incorrect data check)");

    // a.txt's only block, so that no later block header moves with the shorter size.
    std::vector<uint8_t> cut = bytes_;
    const uint32_t a_block = get32(bytes_, a_txt() + 4);
    put32(cut, a_block, get32(bytes_, a_block) - 5); // drops the Adler-32 and a byte of deflate data
    EXPECT_MESSAGE(open_error(cut), "block 0's zlib stream is cut short");
}

TEST_F(PfsBadInput, DuplicateCrcs)
{
    put32(bytes_, a_txt(), eq::pfs_filename_crc("gfaydark.wld"));
    char crc[16];
    std::snprintf(crc, sizeof crc, "0x%08X", eq::pfs_filename_crc("gfaydark.wld"));
    EXPECT_MESSAGE(open_error(bytes_), std::string("both have CRC ") + crc);
}

TEST_F(PfsBadInput, OverlappingEntries)
{
    // a.txt claims gfaydark.wld's first block.
    put32(bytes_, a_txt() + 4, get32(bytes_, gfaydark() + 4));
    put32(bytes_, a_txt() + 8, 8192);
    EXPECT_MESSAGE(open_error(bytes_), "overlaps");
    EXPECT_MESSAGE(open_error(bytes_), "member 'gfaydark.wld'");
}

TEST_F(PfsBadInput, MissingMemberLookup)
{
    const PfsArchive archive(bytes_, "zone.s3d");
    try {
        archive.read("nothere.wld");
        FAIL() << "read a missing member";
    } catch (const FileError& e) {
        EXPECT_EQ(e.file(), "zone.s3d");
        EXPECT_MESSAGE(std::string(e.what()), "no member named 'nothere.wld'");
    }
}

TEST(PfsBadNameList, CountMismatch)
{
    const auto bytes = assemble({{eq::pfs_filename_crc("a.txt"), bytes_of("hi")},
                                 {eq::pfs_filename_crc("b.txt"), bytes_of("ho")},
                                 {eq::kPfsNameListCrc, name_list_of({"a.txt"})}});
    const std::string message = open_error(bytes);
    EXPECT_MESSAGE(message, "zone.s3d: name list: offset 48 (0x30)"); // 12 + two runs of 8 + 10 bytes
    EXPECT_MESSAGE(message, "the name list has 1 names, but the index has 2 entries besides the name list");
}

TEST(PfsBadNameList, NameWithoutEntry)
{
    const auto bytes = assemble({{eq::pfs_filename_crc("a.txt"), bytes_of("hi")},
                                 {eq::kPfsNameListCrc, name_list_of({"b.txt"})}});
    EXPECT_MESSAGE(open_error(bytes), "name 'b.txt' pairs with no index entry: no entry has its CRC 0x");
}

TEST(PfsBadNameList, NamesEqualIgnoringCase)
{
    // LQ-style: each name hashed as given, so both pair, but a lookup could not tell them apart.
    const auto bytes = assemble({{eq::pfs_filename_crc("A.TXT"), bytes_of("hi")},
                                 {eq::pfs_filename_crc("a.txt"), bytes_of("ho")},
                                 {eq::kPfsNameListCrc, name_list_of({"A.TXT", "a.txt"})}});
    EXPECT_MESSAGE(open_error(bytes), "names 'A.TXT' and 'a.txt' are the same ignoring case");
}

TEST(PfsBadNameList, BadNameEncodings)
{
    const auto with_list = [](const std::vector<uint8_t>& list) {
        return open_error(assemble({{eq::pfs_filename_crc("a.txt"), bytes_of("hi")}, {eq::kPfsNameListCrc, list}}));
    };
    std::vector<uint8_t> no_nul = name_list_of({"a.txt"});
    no_nul.back() = 'x';
    EXPECT_MESSAGE(with_list(no_nul), "name 0 'a.txtx' does not end with a NUL");
    std::vector<uint8_t> too_long = name_list_of({"a.txt"});
    put32(too_long, 4, 1000);
    EXPECT_MESSAGE(with_list(too_long), "name 0 is 1000 bytes long, but only 6 remain");
    std::vector<uint8_t> empty_name = name_list_of({""});
    EXPECT_MESSAGE(with_list(empty_name), "name 0 is empty");
    std::vector<uint8_t> huge = name_list_of({"a.txt"});
    huge.resize(4 + 1028 + 1); // one byte more than one name can use
    EXPECT_MESSAGE(with_list(huge), "the name list declares 1033 bytes, more than 1 names of at most 1024 bytes");
    EXPECT_MESSAGE(open_error(assemble({{eq::pfs_filename_crc("a.txt"), bytes_of("hi")}})),
                   "no name list: no index entry has CRC 0x61580AC9");
}

// ---------------------------------------------------------------------------------------------
// What other writers produce, read the way §1.7 decides.

TEST(PfsReaderChoices, MixedCaseNamesHashedAsGivenStillPair)
{
    // LQ hashes the name as given; WQ/ZU/QL would not find GFAYDARK.WLD here, pvscope does.
    const auto bytes = assemble({{eq::pfs_filename_crc("GFAYDARK.WLD"), bytes_of("wld")},
                                 {eq::kPfsNameListCrc, name_list_of({"GFAYDARK.WLD"})}});
    const PfsArchive archive(bytes, "lq.s3d");
    EXPECT_EQ(archive.members(), std::vector<std::string>{"GFAYDARK.WLD"});
    EXPECT_EQ(archive.read("gfaydark.wld"), bytes_of("wld"));
}

TEST(PfsReaderChoices, EqZipNameListCrcIsAccepted)
{
    // Index in offset order (not sorted), name list under 0xFFFFFFFF, runs with a gap: all accepted.
    auto bytes = assemble({{eq::pfs_filename_crc("b.txt"), bytes_of("bee")},
                           {eq::pfs_filename_crc("a.txt"), bytes_of("hi")},
                           {0xFFFFFFFF, name_list_of({"a.txt", "b.txt"})}});
    const PfsArchive archive(bytes, "eqzip.s3d");
    EXPECT_EQ(archive.members(), (std::vector<std::string>{"a.txt", "b.txt"}));
    EXPECT_EQ(archive.read("b.txt"), bytes_of("bee"));
    EXPECT_EQ(archive.read("a.txt"), bytes_of("hi"));
}

TEST(PfsReaderChoices, TrailingBytesThatAreNotAFooterAreIgnored)
{
    std::vector<uint8_t> bytes = write_pfs({{"a.txt", bytes_of("hi")}});
    bytes.insert(bytes.end(), {'J', 'U', 'N', 'K'});
    const PfsArchive archive(bytes, "trailing.s3d");
    EXPECT_EQ(archive.footer_timestamp(), std::nullopt);
    EXPECT_EQ(archive.read("a.txt"), bytes_of("hi"));
}

// ---------------------------------------------------------------------------------------------
// The sweep: never anything but a read or a FileError.

bool reads_or_file_error(const std::vector<uint8_t>& bytes)
{
    try {
        const PfsArchive archive(bytes, "sweep.s3d");
        for (const std::string& name : archive.members()) {
            const std::vector<uint8_t> data = archive.read(name);
            EXPECT_LE(data.size(), bytes.size() * 1032);
        }
        return true;
    } catch (const FileError& e) {
        EXPECT_EQ(e.file().rfind("sweep.s3d", 0), 0u) << e.what();
        return false;
    }
}

std::vector<uint8_t> sweep_archive()
{
    return write_pfs({{"gfaydark.wld", compressible_bytes(30000, 5)},
                      {"empty.txt", {}},
                      {"random.bin", random_bytes(9000, 6)},
                      {"a.txt", bytes_of("hi")}});
}

TEST(PfsSweep, TruncatedAt200CutPointsReadsOrThrowsFileError)
{
    const std::vector<uint8_t> original = sweep_archive();
    std::mt19937 rng(13);
    std::uniform_int_distribution<size_t> cut(0, original.size() - 1);
    size_t errors = 0;
    for (int i = 0; i < 200; ++i) {
        const size_t length = i < 100 ? original.size() * size_t(i) / 100 : cut(rng);
        const std::vector<uint8_t> bytes(original.begin(), original.begin() + static_cast<std::ptrdiff_t>(length));
        errors += !reads_or_file_error(bytes);
    }
    EXPECT_EQ(errors, 200u); // the index is at the end: every cut loses some of it
}

TEST(PfsSweep, With200RandomByteChangesReadsOrThrowsFileError)
{
    const std::vector<uint8_t> original = sweep_archive();
    const size_t index_offset = get32(original, 0);
    std::mt19937 rng(17);
    std::uniform_int_distribution<size_t> where(0, original.size() - 1);
    std::uniform_int_distribution<int> value(0, 255);
    size_t errors = 0;
    for (int i = 0; i < 200; ++i) {
        std::vector<uint8_t> bytes = original;
        // A quarter of the changes hit the header, a quarter the index, where a change matters most.
        size_t at = where(rng);
        if (i % 4 == 0)
            at %= 12;
        else if (i % 4 == 1)
            at = index_offset + at % (original.size() - index_offset);
        bytes[at] = static_cast<uint8_t>(value(rng));
        errors += !reads_or_file_error(bytes);
    }
    EXPECT_GT(errors, 50u);
}

} // namespace
} // namespace pvs
