#include "wld/pvs_part_file.h"

#include "visibility/file_error.h"

#include <zlib.h>

#include <cstring>
#include <stdexcept>

namespace pvs {

namespace {

constexpr char kMagic[8] = {'P', 'V', 'S', 'P', 'A', 'R', 'T', '1'};
constexpr uint32_t kVersion = 1;
constexpr uint32_t kMaxSettings = 1u << 20;

void put_u32(std::vector<uint8_t>& out, uint32_t v)
{
    for (int i = 0; i < 4; ++i)
        out.push_back(uint8_t(v >> (8 * i)));
}

void put_u64(std::vector<uint8_t>& out, uint64_t v)
{
    for (int i = 0; i < 8; ++i)
        out.push_back(uint8_t(v >> (8 * i)));
}

// Reads little-endian fields in order; every read past the end throws, naming the field.
class Reader {
public:
    Reader(std::span<const uint8_t> bytes, const std::string& name) : bytes_(bytes), name_(name) {}

    uint64_t offset() const { return offset_; }
    size_t left() const { return bytes_.size() - offset_; }
    [[noreturn]] void fail(const std::string& problem) const { throw FileError(name_, offset_, problem); }

    std::span<const uint8_t> take(size_t n, const char* what)
    {
        if (n > left())
            fail(std::string("truncated: ") + what + " needs " + std::to_string(n) + " bytes, " +
                 std::to_string(left()) + " left");
        const std::span<const uint8_t> s = bytes_.subspan(offset_, n);
        offset_ += n;
        return s;
    }
    uint32_t u32(const char* what)
    {
        const std::span<const uint8_t> s = take(4, what);
        return uint32_t(s[0]) | uint32_t(s[1]) << 8 | uint32_t(s[2]) << 16 | uint32_t(s[3]) << 24;
    }
    uint64_t u64(const char* what)
    {
        const uint64_t lo = u32(what);
        return lo | uint64_t(u32(what)) << 32;
    }

private:
    std::span<const uint8_t> bytes_;
    const std::string& name_;
    uint64_t offset_ = 0;
};

} // namespace

uint64_t fnv1a64(std::span<const uint8_t> bytes, uint64_t hash)
{
    for (uint8_t b : bytes) {
        hash ^= b;
        hash *= 0x100000001b3ull;
    }
    return hash;
}

std::vector<uint8_t> encode_pvs_part(const PvsPart& part)
{
    std::vector<uint8_t> out(std::begin(kMagic), std::end(kMagic));
    put_u32(out, kVersion);
    put_u64(out, part.zone_hash);
    put_u32(out, part.shard);
    put_u32(out, part.shards);
    put_u32(out, part.row_count);
    put_u32(out, part.region_count);
    put_u32(out, uint32_t(part.join));
    put_u32(out, uint32_t(part.settings.size()));
    out.insert(out.end(), part.settings.begin(), part.settings.end());
    put_u32(out, uint32_t(part.sources.size()));
    for (uint32_t s : part.sources)
        put_u32(out, s);
    std::vector<uint8_t> raw;
    raw.reserve(part.rows.size() * 8);
    for (uint64_t w : part.rows)
        put_u64(raw, w);
    uLongf packed_size = compressBound(uLong(raw.size()));
    std::vector<uint8_t> packed(packed_size);
    if (compress2(packed.data(), &packed_size, raw.data(), uLong(raw.size()), Z_BEST_SPEED) != Z_OK)
        throw std::runtime_error("part file: zlib could not compress the rows");
    put_u64(out, packed_size);
    out.insert(out.end(), packed.begin(), packed.begin() + std::ptrdiff_t(packed_size));
    return out;
}

PvsPart decode_pvs_part(std::span<const uint8_t> bytes, const std::string& name)
{
    Reader in(bytes, name);
    const std::span<const uint8_t> magic = in.take(8, "the magic");
    if (std::memcmp(magic.data(), kMagic, 8) != 0)
        throw FileError(name, 0, "not a pvscope part file (no PVSPART1 magic)");
    if (const uint32_t version = in.u32("the version"); version != kVersion)
        throw FileError(name, 8,
                        "part file version " + std::to_string(version) + ", this pvscope reads " +
                            std::to_string(kVersion));
    PvsPart part;
    part.zone_hash = in.u64("the zone hash");
    part.shard = in.u32("the shard");
    part.shards = in.u32("the shard count");
    if (part.shards == 0 || part.shard >= part.shards)
        throw FileError(name, 20, "shard " + std::to_string(part.shard) + " of " + std::to_string(part.shards));
    part.row_count = in.u32("the row count");
    part.region_count = in.u32("the region count");
    const uint32_t join = in.u32("the rows' join");
    if (join > uint32_t(PartRows::Union))
        throw FileError(name, 36, "rows joined by rule " + std::to_string(join) + " (0 or 1)");
    part.join = PartRows(join);
    const uint64_t settings_at = in.offset();
    const uint32_t settings_size = in.u32("the settings' length");
    if (settings_size > kMaxSettings)
        throw FileError(name, settings_at, "settings of " + std::to_string(settings_size) + " bytes (at most 1 MiB)");
    const std::span<const uint8_t> settings = in.take(settings_size, "the settings");
    part.settings.assign(settings.begin(), settings.end());
    const uint64_t count_at = in.offset();
    const uint32_t source_count = in.u32("the source count");
    if (source_count > part.row_count)
        throw FileError(name, count_at,
                        std::to_string(source_count) + " sources of a zone of " + std::to_string(part.row_count) +
                            " rows");
    if (uint64_t(source_count) * 4 > in.left())
        in.fail("truncated: " + std::to_string(source_count) + " sources need " + std::to_string(4ull * source_count) +
                " bytes");
    const uint64_t sources_at = in.offset();
    part.sources.resize(source_count);
    for (uint32_t& s : part.sources)
        s = in.u32("a source");
    for (size_t i = 0; i < part.sources.size(); ++i)
        if (part.sources[i] >= part.row_count || (i > 0 && part.sources[i] <= part.sources[i - 1]))
            throw FileError(name, sources_at + 4 * i,
                            "source " + std::to_string(part.sources[i]) + " is " +
                                (part.sources[i] >= part.row_count ? "past the last row"
                                                                   : "not after the one before (sources ascend)"));
    const uint64_t packed_at = in.offset();
    const uint64_t packed_size = in.u64("the rows' length");
    if (packed_size != in.left())
        throw FileError(name, packed_at,
                        "the rows take " + std::to_string(packed_size) + " bytes but " + std::to_string(in.left()) +
                            " follow");
    const std::span<const uint8_t> packed = in.take(size_t(packed_size), "the rows");
    const uint64_t raw_size = uint64_t(source_count) * part.words_per_row() * 8;
    // zlib packs at best about 1000:1; a claim beyond that is a corrupt header, not a big zone.
    if (raw_size > 1032 * packed_size + 64)
        throw FileError(name, packed_at,
                        std::to_string(source_count) + " rows of " + std::to_string(part.region_count) +
                            " bits cannot be packed in " + std::to_string(packed_size) + " bytes");
    std::vector<uint8_t> raw(raw_size);
    uLongf got = uLongf(raw_size);
    if (uncompress(raw.data(), &got, packed.data(), uLong(packed.size())) != Z_OK || got != raw_size)
        throw FileError(name, packed_at + 8, "the rows do not unpack (corrupt zlib data)");
    part.rows.resize(raw_size / 8);
    for (size_t i = 0; i < part.rows.size(); ++i) {
        uint64_t w = 0;
        for (int b = 7; b >= 0; --b)
            w = w << 8 | raw[8 * i + size_t(b)];
        part.rows[i] = w;
    }
    // A bit past the last region would name a region the zone has not: refused, not written.
    const size_t words = part.words_per_row();
    const unsigned used = part.region_count % 64;
    if (used != 0)
        for (size_t r = 0; r < source_count; ++r)
            if (part.rows[r * words + words - 1] >> used)
                throw FileError(name, packed_at + 8,
                                "row " + std::to_string(part.sources[r]) + " sets a bit past region " +
                                    std::to_string(part.region_count - 1));
    return part;
}

} // namespace pvs
