#include "wld/eq/pfs_archive.h"

#include "visibility/file_error.h"
#include "visibility/worker_pool.h"
#include "wld/common/byte_reader.h"
#include "wld/common/quote.h"
#include "wld/common/read_file.h"
#include "wld/eq/pfs_crc.h"

#define ZLIB_CONST // next_in is a pointer to const, so the archive's bytes need no cast
#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <limits>
#include <new>
#include <stdexcept>

namespace pvs::eq {

namespace {

constexpr uint32_t kHeaderSize = 12;
constexpr uint32_t kIndexEntrySize = 12;
constexpr uint32_t kBlockHeaderSize = 8;
constexpr uint32_t kFooterSize = 9;              // "STEVE" + u32
constexpr uint32_t kEqZipNameListCrc = 0xFFFFFFFF; // what EQZip writes instead of 0x61580AC9 (§1.4)
// Deflate's largest expansion: a 258-byte match coded in 2 bits. A block declaring more inflated
// bytes than this allows from its zlib bytes is lying, whatever its data.
constexpr uint64_t kMaxZlibRatio = 1032;
// A member's output starts with at most this much reserved and then grows as its blocks inflate.
constexpr size_t kMaxInitialReserve = size_t{16} << 20;
constexpr size_t kMaxNameLength = 1023;  // bytes before the NUL; LQ rejects longer (§1.5)
constexpr size_t kMaxMembers = 99'999;   // LQ caps entry_count at 100 000 (§1.5)

char ascii_lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

std::string lowercase(std::string_view text)
{
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(), ascii_lower);
    return out;
}

std::string hex32(uint32_t value)
{
    char text[16];
    std::snprintf(text, sizeof text, "0x%08X", value);
    return text;
}

std::string quoted(std::string_view name) { return quote_for_message(name, 64); }

std::string member_file(const std::string& archive, std::string_view name)
{
    return archive + ": member " + quoted(name);
}

// ---------------------------------------------------------------------------------------------
// Reading

struct IndexEntry {
    uint32_t crc = 0;
    uint32_t data_offset = 0;
    uint32_t size = 0;
    uint64_t at = 0; // where the entry sits in the index
};

struct Block {
    uint64_t offset = 0; // of its 8-byte header
    uint32_t compressed = 0;
    uint32_t inflated = 0;
};

uint32_t read_header(const ByteReader& in)
{
    if (in.size() < kHeaderSize)
        in.fail(0, "truncated header: the file has " + std::to_string(in.size()) +
                       " bytes, a PFS header needs 12");
    const std::span<const uint8_t> magic = in.bytes(4, 4, "magic");
    if (std::memcmp(magic.data(), "PFS ", 4) != 0)
        in.fail(4, "not a PFS archive: the magic is " +
                       quoted(std::string_view(reinterpret_cast<const char*>(magic.data()), 4)) +
                       ", expected 'PFS '");
    const auto version = in.read<uint32_t>(8, "version");
    if (version != kPfsVersion)
        in.fail(8, "unsupported PFS version " + hex32(version) + "; every known archive has 0x00020000");
    const auto index_offset = in.read<uint32_t>(0, "index offset");
    if (index_offset < kHeaderSize)
        in.fail(0, "the index offset " + std::to_string(index_offset) + " points into the header");
    if (index_offset > in.size() || in.size() - index_offset < 4)
        in.fail(0, "the index offset " + std::to_string(index_offset) + " (" + hex32(index_offset) +
                       ") is past the end of the file (" + std::to_string(in.size()) + " bytes)");
    return index_offset;
}

std::vector<IndexEntry> read_index(const ByteReader& in, uint32_t index_offset)
{
    const auto count = in.read<uint32_t>(index_offset, "index entry count");
    const uint64_t room = (in.size() - index_offset - 4) / kIndexEntrySize;
    if (count > room)
        in.fail(index_offset, "the index declares " + std::to_string(count) + " entries, but only " +
                                  std::to_string(room) + " fit between it and the end of the file");
    if (count == 0)
        in.fail(index_offset, "the index is empty: not even the name list has an entry");

    std::vector<IndexEntry> entries(count);
    for (uint32_t i = 0; i < count; ++i) {
        IndexEntry& e = entries[i];
        e.at = index_offset + 4 + uint64_t{kIndexEntrySize} * i;
        e.crc = in.read<uint32_t>(e.at, "index entry CRC");
        e.data_offset = in.read<uint32_t>(e.at + 4, "index entry data offset");
        e.size = in.read<uint32_t>(e.at + 8, "index entry size");
        if (e.data_offset < kHeaderSize || e.data_offset > in.size())
            in.fail(e.at + 4, "index entry " + std::to_string(i) + " (CRC " + hex32(e.crc) + ") has data offset " +
                                  std::to_string(e.data_offset) + " (" + hex32(e.data_offset) +
                                  "), outside the file's data (12 to " + std::to_string(in.size()) + ")");
    }

    // Two entries with one CRC would make a name pair with either (§1.9 rule 2).
    std::vector<uint32_t> order(count);
    for (uint32_t i = 0; i < count; ++i)
        order[i] = i;
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return entries[a].crc != entries[b].crc ? entries[a].crc < entries[b].crc : a < b;
    });
    for (size_t k = 1; k < order.size(); ++k)
        if (entries[order[k]].crc == entries[order[k - 1]].crc)
            in.fail(entries[order[k]].at, "index entries " + std::to_string(order[k - 1]) + " and " +
                                              std::to_string(order[k]) + " both have CRC " +
                                              hex32(entries[order[k]].crc));
    return entries;
}

// The blocks of the run at `data_offset` that inflates to `size` bytes. Checks every block header
// lies in the file, declares 1..8192 bytes, no more than its zlib bytes could produce and no more
// than the entry still needs, and that its zlib bytes lie in the file. Inflates nothing.
std::vector<Block> blocks_of(const ByteReader& in, uint64_t data_offset, uint32_t size)
{
    std::vector<Block> blocks;
    uint64_t at = data_offset;
    uint64_t remaining = size;
    while (remaining > 0) {
        const std::string which = "block " + std::to_string(blocks.size());
        const auto compressed = in.read<uint32_t>(at, (which + " header").c_str());
        const auto inflated = in.read<uint32_t>(at + 4, (which + " header").c_str());
        if (inflated == 0 || inflated > kPfsMaxBlockSize)
            in.fail(at + 4, which + " declares " + std::to_string(inflated) +
                                " inflated bytes; a block holds 1 to 8192");
        if (inflated > remaining)
            in.fail(at + 4, which + " declares " + std::to_string(inflated) + " inflated bytes, but only " +
                                std::to_string(remaining) + " of the entry's " + std::to_string(size) +
                                " bytes remain");
        if (inflated > uint64_t{compressed} * kMaxZlibRatio)
            in.fail(at, which + " declares " + std::to_string(inflated) + " inflated bytes from " +
                            std::to_string(compressed) + " zlib bytes, more than zlib can produce");
        in.require(at + kBlockHeaderSize, compressed, (which + " zlib data").c_str());
        blocks.push_back({at, compressed, inflated});
        at += kBlockHeaderSize + uint64_t{compressed};
        remaining -= inflated;
    }
    return blocks;
}

uint64_t run_end(const std::vector<Block>& blocks, uint64_t data_offset)
{
    return blocks.empty() ? data_offset : blocks.back().offset + kBlockHeaderSize + blocks.back().compressed;
}

// Ends the zlib stream when it goes out of scope, on every path.
struct InflateStream {
    z_stream zs{};
    InflateStream()
    {
        if (inflateInit(&zs) != Z_OK)
            throw std::bad_alloc();
    }
    ~InflateStream() { inflateEnd(&zs); }
    InflateStream(const InflateStream&) = delete;
    InflateStream& operator=(const InflateStream&) = delete;
};

// Inflates one block into out[0, block.inflated). Anything but a complete zlib stream (Adler-32
// included) of exactly that many bytes throws.
void inflate_block(const ByteReader& in, const Block& block, size_t index, uint8_t* out)
{
    const uint64_t data_at = block.offset + kBlockHeaderSize;
    const std::span<const uint8_t> data = in.bytes(data_at, block.compressed, "block zlib data");
    const std::string which = "block " + std::to_string(index);
    const std::string declared = std::to_string(block.inflated);

    InflateStream stream;
    z_stream& zs = stream.zs;
    zs.next_in = data.data();
    zs.avail_in = block.compressed;
    zs.next_out = out;
    zs.avail_out = block.inflated;
    int result = inflate(&zs, Z_FINISH);
    if (result == Z_BUF_ERROR && zs.avail_out == 0) {
        // The output is full and the stream goes on: it holds either more data or only its end.
        uint8_t scratch[64];
        zs.next_out = scratch;
        zs.avail_out = sizeof scratch;
        result = inflate(&zs, Z_FINISH);
        if (zs.total_out > block.inflated)
            in.fail(data_at, which + " inflates to more than the " + declared + " bytes its header declares");
    }
    switch (result) {
    case Z_STREAM_END:
        if (zs.total_out != block.inflated)
            in.fail(data_at, which + " inflates to " + std::to_string(zs.total_out) +
                                 " bytes, but its header declares " + declared);
        return; // bytes after the end of the stream, inside the block, are ignored as zlib readers do
    case Z_MEM_ERROR:
        throw std::bad_alloc();
    case Z_DATA_ERROR:
    case Z_NEED_DICT:
        in.fail(data_at, which + " has corrupt zlib data (" + (zs.msg ? zs.msg : "preset dictionary required") + ")");
    default:
        in.fail(data_at, which + "'s zlib stream is cut short: its " + std::to_string(block.compressed) +
                             " bytes end after " + std::to_string(zs.total_out) + " of the " + declared +
                             " bytes its header declares");
    }
}

std::vector<uint8_t> inflate_blocks(const ByteReader& in, const std::vector<Block>& blocks, uint32_t size)
{
    std::vector<uint8_t> out;
    out.reserve(std::min<size_t>(size, kMaxInitialReserve));
    for (size_t i = 0; i < blocks.size(); ++i) {
        const size_t at = out.size();
        out.resize(at + blocks[i].inflated);
        inflate_block(in, blocks[i], i, out.data() + at);
    }
    return out;
}

uint32_t le32(const std::vector<uint8_t>& bytes, size_t at)
{
    uint32_t value;
    std::memcpy(&value, bytes.data() + at, sizeof value);
    return value;
}

// The names of the inflated name list (§1.5). Errors name the list's run, whose absolute offset is
// the best there is for bytes that exist only after inflation, and give the byte within the list.
std::vector<std::string> parse_name_list(const std::vector<uint8_t>& list, const std::string& file,
                                         uint64_t list_offset, uint32_t expected_count)
{
    const auto fail = [&](size_t at, const std::string& reason) {
        throw FileError(file, list_offset, reason + " (byte " + std::to_string(at) + " of the inflated name list)");
    };
    if (list.size() < 4)
        fail(0, "the name list is " + std::to_string(list.size()) + " bytes, too short for its name count");
    const uint32_t count = le32(list, 0);
    if (count != expected_count)
        fail(0, "the name list has " + std::to_string(count) + " names, but the index has " +
                    std::to_string(expected_count) + " entries besides the name list");

    std::vector<std::string> names;
    names.reserve(count); // the index, which lies in the file, has as many entries
    size_t at = 4;
    for (uint32_t i = 0; i < count; ++i) {
        const std::string which = "name " + std::to_string(i);
        if (list.size() - at < 4)
            fail(at, "the name list ends before the length of " + which);
        const uint32_t length = le32(list, at);
        if (length == 0)
            fail(at, which + " has length 0; a name ends with a NUL");
        if (length > kMaxNameLength + 1)
            fail(at, which + " is " + std::to_string(length) + " bytes long; a name takes at most 1024 with its NUL");
        if (length > list.size() - at - 4)
            fail(at, which + " is " + std::to_string(length) + " bytes long, but only " +
                         std::to_string(list.size() - at - 4) + " remain in the name list");
        at += 4;
        const std::string_view text(reinterpret_cast<const char*>(list.data() + at), length);
        if (text.back() != '\0')
            fail(at, which + " " + quoted(text) + " does not end with a NUL");
        const std::string_view name = text.substr(0, length - 1);
        if (name.empty())
            fail(at, which + " is empty");
        if (name.find('\0') != std::string_view::npos)
            fail(at, which + " " + quoted(name) + " has a NUL inside it");
        names.emplace_back(name);
        at += length;
    }
    return names; // bytes after the last name are ignored
}

} // namespace

PfsArchive::PfsArchive(std::span<const uint8_t> bytes, std::string file_name)
    : bytes_(bytes.begin(), bytes.end()), file_name_(std::move(file_name))
{
    const ByteReader in(bytes_, file_name_);
    index_offset_ = read_header(in);
    const std::vector<IndexEntry> index = read_index(in, index_offset_);

    // The name list: 0x61580AC9, or EQZip's 0xFFFFFFFF when no entry has 0x61580AC9.
    const auto with_crc = [&](uint32_t crc) {
        return std::find_if(index.begin(), index.end(), [crc](const IndexEntry& e) { return e.crc == crc; });
    };
    auto list_entry = with_crc(kPfsNameListCrc);
    if (list_entry == index.end())
        list_entry = with_crc(kEqZipNameListCrc);
    if (list_entry == index.end())
        in.fail(index_offset_, "no name list: no index entry has CRC 0x61580AC9");
    const std::string list_file = file_name_ + ": name list";
    const ByteReader list_in(bytes_, list_file);
    // Each name takes at most 4 + 1024 bytes, so a longer list is refused before it is inflated.
    const uint64_t max_list_size = 4 + (index.size() - 1) * (4 + uint64_t{kMaxNameLength} + 1);
    if (list_entry->size > max_list_size)
        in.fail(list_entry->at + 8, "the name list declares " + std::to_string(list_entry->size) +
                                        " bytes, more than " + std::to_string(index.size() - 1) +
                                        " names of at most 1024 bytes can take (" + std::to_string(max_list_size) +
                                        ")");
    const std::vector<Block> list_blocks = blocks_of(list_in, list_entry->data_offset, list_entry->size);
    const std::vector<uint8_t> list = inflate_blocks(list_in, list_blocks, list_entry->size);
    names_ = parse_name_list(list, list_file, list_entry->data_offset, static_cast<uint32_t>(index.size() - 1));

    // Pair each name with the entry holding its CRC: lowercased first, then as stored.
    std::unordered_map<uint32_t, size_t> by_crc;
    for (size_t i = 0; i < index.size(); ++i)
        if (&index[i] != &*list_entry)
            by_crc.emplace(index[i].crc, i);
    std::vector<size_t> paired_name(index.size(), names_.size()); // index entry -> name, or none
    entries_.reserve(names_.size());
    for (size_t n = 0; n < names_.size(); ++n) {
        const std::string& name = names_[n];
        const std::string lower = lowercase(name);
        uint32_t crc = pfs_filename_crc(lower);
        auto found = by_crc.find(crc);
        if (found == by_crc.end() && lower != name) {
            crc = pfs_filename_crc(name);
            found = by_crc.find(crc);
        }
        const uint64_t list_at = list_entry->data_offset;
        if (found == by_crc.end())
            list_in.fail(list_at, "name " + quoted(name) + " pairs with no index entry: no entry has its CRC " +
                                      hex32(pfs_filename_crc(lower)));
        const auto [same, inserted] = by_lowercase_name_.emplace(lower, n);
        if (!inserted)
            list_in.fail(list_at, "names " + quoted(names_[same->second]) + " and " + quoted(name) +
                                      " are the same ignoring case, so a lookup cannot tell them apart");
        if (paired_name[found->second] != names_.size())
            list_in.fail(list_at, "names " + quoted(names_[paired_name[found->second]]) + " and " + quoted(name) +
                                      " both pair with the index entry of CRC " + hex32(crc));
        paired_name[found->second] = n;
        const IndexEntry& e = index[found->second];
        entries_.push_back({name, e.crc, e.data_offset, e.size, 0, 0});
    }

    // Every run, with the index, must have bytes of its own.
    struct Extent {
        uint64_t begin, end;
        std::string what;
    };
    std::vector<Extent> extents;
    extents.push_back({index_offset_, index_offset_ + 4 + uint64_t{kIndexEntrySize} * index.size(), "the index"});
    extents.push_back({list_entry->data_offset, run_end(list_blocks, list_entry->data_offset), "the name list"});
    for (PfsEntry& entry : entries_) {
        const ByteReader member_in(bytes_, member_file(file_name_, entry.name));
        const std::vector<Block> blocks = blocks_of(member_in, entry.data_offset, entry.size);
        const uint64_t end = run_end(blocks, entry.data_offset);
        entry.stored_size = end - entry.data_offset;
        entry.block_count = static_cast<uint32_t>(blocks.size());
        extents.push_back({entry.data_offset, end, "member " + quoted(entry.name)});
    }
    std::erase_if(extents, [](const Extent& e) { return e.begin == e.end; });
    std::sort(extents.begin(), extents.end(), [](const Extent& a, const Extent& b) { return a.begin < b.begin; });
    for (size_t k = 1; k < extents.size(); ++k) {
        // Sorted by start and disjoint so far, so the previous extent is the one that ends last.
        const Extent& a = extents[k - 1];
        const Extent& b = extents[k];
        if (b.begin < a.end)
            in.fail(b.begin, "the data of " + b.what + " (bytes " + std::to_string(b.begin) + " to " +
                                 std::to_string(b.end) + ") overlaps " + a.what + " (bytes " + std::to_string(a.begin) +
                                 " to " + std::to_string(a.end) + ")");
    }

    const uint64_t index_end = index_offset_ + 4 + uint64_t{kIndexEntrySize} * index.size();
    if (in.size() - index_end >= kFooterSize && std::memcmp(bytes_.data() + index_end, "STEVE", 5) == 0) {
        const uint8_t* t = bytes_.data() + index_end + 5;
        footer_timestamp_ = uint32_t{t[0]} << 24 | uint32_t{t[1]} << 16 | uint32_t{t[2]} << 8 | uint32_t{t[3]};
    }
}

PfsArchive PfsArchive::load(const std::string& path)
{
    const std::vector<uint8_t> bytes = read_whole_file(path);
    return PfsArchive(bytes, path);
}

bool PfsArchive::contains(std::string_view name) const { return by_lowercase_name_.contains(lowercase(name)); }

std::vector<uint8_t> PfsArchive::read(std::string_view name) const
{
    const auto found = by_lowercase_name_.find(lowercase(name));
    if (found == by_lowercase_name_.end())
        throw FileError(file_name_, index_offset_, "no member named " + quoted(name));
    const PfsEntry& entry = entries_[found->second];
    return inflate_run(entry.data_offset, entry.size, member_file(file_name_, entry.name));
}

std::vector<uint8_t> PfsArchive::inflate_run(uint32_t data_offset, uint32_t size, const std::string& what) const
{
    const ByteReader in(bytes_, what);
    return inflate_blocks(in, blocks_of(in, data_offset, size), size);
}

// ---------------------------------------------------------------------------------------------
// Writing

namespace {

void put32(std::vector<uint8_t>& out, uint32_t value)
{
    for (int shift = 0; shift < 32; shift += 8)
        out.push_back(static_cast<uint8_t>(value >> shift));
}

void check_size(const std::vector<uint8_t>& out)
{
    if (out.size() > std::numeric_limits<uint32_t>::max())
        throw std::invalid_argument("write_pfs: the archive would exceed 4 GiB, beyond PFS's 32-bit offsets");
}

// Appends `data` as blocks of 8192 bytes (the last one shorter), each its own zlib stream. The
// streams are independent, so a long run is compressed on every core and appended in order: the
// same bytes as one thread writes (a 33 000-region zone's 12 MB: about half the write's time).
void write_run(std::vector<uint8_t>& out, std::span<const uint8_t> data, int level)
{
    const size_t blocks = (data.size() + kPfsMaxBlockSize - 1) / kPfsMaxBlockSize;
    std::vector<std::vector<uint8_t>> packed(blocks);
    std::atomic<bool> stop{false};
    constexpr size_t kBlocksPerThread = 64; // below this a thread costs more than it saves
    parallel_items(
        blocks, blocks >= 2 * kBlocksPerThread ? 0u : 1u, {}, [] { return 0.0; }, stop,
        [] { return std::vector<uint8_t>(compressBound(kPfsMaxBlockSize)); },
        [&](size_t block, std::vector<uint8_t>& compressed) {
            const size_t at = block * kPfsMaxBlockSize;
            const size_t length = std::min<size_t>(kPfsMaxBlockSize, data.size() - at);
            uLongf compressed_length = static_cast<uLongf>(compressed.size());
            const int result =
                compress2(compressed.data(), &compressed_length, data.data() + at, static_cast<uLong>(length), level);
            if (result == Z_MEM_ERROR)
                throw std::bad_alloc();
            if (result != Z_OK)
                throw std::logic_error("write_pfs: compress2 failed with " + std::to_string(result));
            packed[block].assign(compressed.begin(),
                                 compressed.begin() + static_cast<std::ptrdiff_t>(compressed_length));
        });
    for (size_t block = 0; block < blocks; ++block) {
        const size_t length = std::min<size_t>(kPfsMaxBlockSize, data.size() - block * kPfsMaxBlockSize);
        put32(out, static_cast<uint32_t>(packed[block].size()));
        put32(out, static_cast<uint32_t>(length));
        out.insert(out.end(), packed[block].begin(), packed[block].end());
        std::vector<uint8_t>().swap(packed[block]);
        check_size(out);
    }
}

// The name as stored: lowercased, after checking every reader can take it (§1.9 rule 2).
std::string stored_name(const std::string& name)
{
    if (name.empty())
        throw std::invalid_argument("write_pfs: a member has an empty name");
    if (name.size() > kMaxNameLength)
        throw std::invalid_argument("write_pfs: member name " + quoted(name) + " is longer than 1023 bytes");
    for (const char ch : name) {
        const auto c = static_cast<unsigned char>(ch);
        if (c < 0x20 || c >= 0x7F || c == '/' || c == '\\')
            throw std::invalid_argument("write_pfs: member name " + quoted(name) +
                                        " is not a bare file name in printable ASCII");
    }
    return lowercase(name);
}

} // namespace

std::vector<uint8_t> write_pfs(const std::vector<PfsMember>& members, const PfsWriteOptions& options)
{
    if (options.zlib_level < 0 || options.zlib_level > 9)
        throw std::invalid_argument("write_pfs: zlib level " + std::to_string(options.zlib_level) + " is not 0..9");
    if (members.size() > kMaxMembers)
        throw std::invalid_argument("write_pfs: " + std::to_string(members.size()) +
                                    " members; readers accept at most 99999");

    std::vector<IndexEntry> index;
    index.reserve(members.size() + 1);
    std::vector<std::string> names;
    names.reserve(members.size());
    std::unordered_map<uint32_t, size_t> by_crc;
    for (const PfsMember& member : members) {
        names.push_back(stored_name(member.name));
        const uint32_t crc = pfs_filename_crc(names.back());
        if (crc == kPfsNameListCrc)
            throw std::invalid_argument("write_pfs: member name " + quoted(member.name) +
                                        " hashes to the name list's CRC 0x61580AC9");
        const auto [other, inserted] = by_crc.emplace(crc, names.size() - 1);
        if (!inserted)
            throw std::invalid_argument(names[other->second] == names.back()
                                            ? "write_pfs: member names " + quoted(members[other->second].name) +
                                                  " and " + quoted(member.name) + " are the same after lowercasing"
                                            : "write_pfs: member names " + quoted(members[other->second].name) +
                                                  " and " + quoted(member.name) + " have the same CRC " + hex32(crc));
        if (member.data.size() > std::numeric_limits<uint32_t>::max())
            throw std::invalid_argument("write_pfs: member " + quoted(member.name) + " is larger than 4 GiB");
        index.push_back({crc, 0, static_cast<uint32_t>(member.data.size()), 0});
    }

    std::vector<uint8_t> out(kHeaderSize, 0);
    // Data in name-list order (§1.9 rule 4); an empty member's offset is where the next run starts.
    for (size_t i = 0; i < members.size(); ++i) {
        index[i].data_offset = static_cast<uint32_t>(out.size());
        write_run(out, members[i].data, options.zlib_level);
    }

    std::vector<uint8_t> list;
    put32(list, static_cast<uint32_t>(names.size()));
    for (const std::string& name : names) {
        put32(list, static_cast<uint32_t>(name.size() + 1));
        list.insert(list.end(), name.begin(), name.end());
        list.push_back(0);
    }
    check_size(list);
    index.push_back({kPfsNameListCrc, static_cast<uint32_t>(out.size()), static_cast<uint32_t>(list.size()), 0});
    write_run(out, list, options.zlib_level);

    // The index right after the name list, sorted by unsigned CRC (§1.9 rule 6). CRCs are unique.
    const auto index_offset = static_cast<uint32_t>(out.size());
    std::sort(index.begin(), index.end(), [](const IndexEntry& a, const IndexEntry& b) { return a.crc < b.crc; });
    put32(out, static_cast<uint32_t>(index.size()));
    for (const IndexEntry& e : index) {
        put32(out, e.crc);
        put32(out, e.data_offset);
        put32(out, e.size);
    }
    if (options.footer_timestamp) {
        const uint32_t t = *options.footer_timestamp;
        out.insert(out.end(), {'S', 'T', 'E', 'V', 'E'});
        for (int shift = 24; shift >= 0; shift -= 8) // big-endian, as LQ reads the originals (§1.8)
            out.push_back(static_cast<uint8_t>(t >> shift));
    }
    check_size(out);

    std::vector<uint8_t> header;
    put32(header, index_offset);
    header.insert(header.end(), {'P', 'F', 'S', ' '});
    put32(header, kPfsVersion);
    std::copy(header.begin(), header.end(), out.begin());
    return out;
}

} // namespace pvs::eq
