#include "visibility/pvs.h"

#include "visibility/bit_row.h"
#include "visibility/codec/bit_runs.h"
#include "visibility/codec/quake_rle.h"

#include <cassert>
#include <string_view>
#include <unordered_map>

namespace pvs {

namespace {
constexpr size_t kDenseAlwaysBytes = 256 * 1024;
// The first byte of each compressed row: which codec follows.
constexpr uint8_t kTagQuakeRle = 0;
constexpr uint8_t kTagBitRuns = 1;
}

Pvs Pvs::build(uint32_t region_count, const RowSource& source, StoragePolicy policy)
{
    return build_rows(region_count, region_count, source, policy);
}

Pvs Pvs::build_rows(uint32_t row_count, uint32_t region_count, const RowSource& source, StoragePolicy policy)
{
    Pvs pvs;
    pvs.region_count_ = region_count;
    pvs.row_count_ = row_count;
    pvs.words_per_row_ = bits::words_for(region_count);
    pvs.missing_.assign(bits::words_for(row_count), 0);
    pvs.row_offsets_.assign(row_count, kMissingRow);

    // Compress every row first: the compressed size decides the storage, and identical rows
    // (Quake clusters, EverQuest zones with shared lists) are stored once. They are found by a
    // hash of the encoded bytes and confirmed against the stored copy: keying a map by a copy of
    // every row doubled the rows at the end of a bake (34 MB of a 5000-room bake's 400 MB peak).
    std::vector<uint64_t> row(pvs.words_per_row_);
    std::vector<uint8_t> encoded, runs;
    struct Stored {
        uint32_t offset, size;
    };
    std::unordered_multimap<size_t, Stored> seen;
    const auto bytes_of = [](const uint8_t* data, size_t size) {
        return std::string_view(reinterpret_cast<const char*>(data), size);
    };
    for (uint32_t r = 0; r < row_count; ++r) {
        std::fill(row.begin(), row.end(), 0);
        if (!source(r, row)) {
            bits::set(pvs.missing_, r);
            ++pvs.missing_count_;
            continue;
        }
        // A tag byte, then the row in the shorter codec: Quake RLE for sparse rows, bit runs for
        // dense rows in long stretches (open zones), which Quake RLE cannot shorten.
        encoded.assign(1, kTagQuakeRle);
        encode_quake_rle(row, region_count, encoded);
        runs.assign(1, kTagBitRuns);
        encode_bit_runs(row, region_count, runs);
        if (runs.size() < encoded.size())
            encoded.swap(runs);
        const std::string_view bytes = bytes_of(encoded.data(), encoded.size());
        const size_t hash = std::hash<std::string_view>{}(bytes);
        uint32_t offset = static_cast<uint32_t>(pvs.compressed_.size());
        bool stored = false;
        for (auto [it, end] = seen.equal_range(hash); it != end && !stored; ++it)
            if (bytes_of(pvs.compressed_.data() + it->second.offset, it->second.size) == bytes) {
                offset = it->second.offset;
                stored = true;
            }
        if (!stored) {
            seen.emplace(hash, Stored{offset, static_cast<uint32_t>(encoded.size())});
            pvs.compressed_.insert(pvs.compressed_.end(), encoded.begin(), encoded.end());
        }
        pvs.row_offsets_[r] = offset;
    }

    const size_t dense_bytes = size_t{row_count} * pvs.words_per_row_ * sizeof(uint64_t);
    const size_t compressed_bytes = pvs.compressed_.size() + pvs.row_offsets_.size() * sizeof(uint32_t);
    bool dense = dense_bytes <= kDenseAlwaysBytes || dense_bytes <= 2 * compressed_bytes;
    if (policy != StoragePolicy::Auto)
        dense = policy == StoragePolicy::Dense;
    if (!dense) {
        pvs.storage_ = Storage::Compressed;
        pvs.compressed_.shrink_to_fit();
        return pvs;
    }

    pvs.storage_ = Storage::Dense;
    pvs.dense_.resize(size_t{row_count} * pvs.words_per_row_);
    for (uint32_t r = 0; r < row_count; ++r)
        pvs.decode_compressed(r, std::span<uint64_t>(pvs.dense_).subspan(size_t{r} * pvs.words_per_row_,
                                                                        pvs.words_per_row_));
    // Released, not just emptied (`= {}` keeps the capacity: a dense PVS held its compressed
    // copy's memory too, doubling it).
    std::vector<uint8_t>().swap(pvs.compressed_);
    std::vector<uint32_t>().swap(pvs.row_offsets_);
    return pvs;
}

bool Pvs::row_missing(uint32_t region) const { return bits::test(missing_, region); }

void Pvs::decode_row(uint32_t region, std::span<uint64_t> out) const
{
    assert(region < row_count_ && out.size() >= words_per_row_);
    out = out.first(words_per_row_);
    if (storage_ == Storage::Dense) {
        const uint64_t* src = dense_.data() + size_t{region} * words_per_row_;
        std::copy(src, src + words_per_row_, out.begin());
        return;
    }
    decode_compressed(region, out);
}

void Pvs::decode_compressed(uint32_t region, std::span<uint64_t> out) const
{
    if (bits::test(missing_, region)) {
        bits::fill(out, region_count_);
        return;
    }
    // Rows were produced by our own encoder, so they are always complete.
    const std::span<const uint8_t> row = std::span<const uint8_t>(compressed_).subspan(row_offsets_[region]);
    if (row[0] == kTagBitRuns)
        decode_bit_runs(row.subspan(1), region_count_, out);
    else
        decode_quake_rle(row.subspan(1), region_count_, out);
}

std::span<const uint64_t> Pvs::dense_row(uint32_t region) const
{
    if (storage_ != Storage::Dense)
        return {};
    return std::span<const uint64_t>(dense_).subspan(size_t{region} * words_per_row_, words_per_row_);
}

bool Pvs::visible(uint32_t from, uint32_t to) const
{
    assert(from < row_count_);
    if (to >= region_count_)
        return false; // a padding bit
    if (storage_ == Storage::Dense)
        return bits::test(dense_row(from), to);
    if (bits::test(missing_, from))
        return true;
    // One bit without decoding the row: a column (every row's bit `to`) costs a walk per row.
    const std::span<const uint8_t> row = std::span<const uint8_t>(compressed_).subspan(row_offsets_[from]);
    return row[0] == kTagBitRuns ? bit_runs_test(row.subspan(1), region_count_, to)
                                 : quake_rle_test(row.subspan(1), region_count_, to);
}

size_t Pvs::memory_bytes() const
{
    return sizeof(Pvs) + dense_.capacity() * sizeof(uint64_t) + compressed_.capacity() +
           row_offsets_.capacity() * sizeof(uint32_t) + missing_.capacity() * sizeof(uint64_t);
}

PvsRowCursor::PvsRowCursor(const Pvs& pvs) : pvs_(&pvs), row_(pvs.words_per_row()) {}

std::span<const uint64_t> PvsRowCursor::row(uint32_t region)
{
    if (pvs_->storage() == Pvs::Storage::Dense)
        return pvs_->dense_row(region);
    if (region_ != region) {
        pvs_->decode_row(region, row_);
        region_ = region;
    }
    return row_;
}

} // namespace pvs
