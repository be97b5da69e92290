// Potentially visible sets: one row of region_count bits per region ("from region r, these
// regions may be visible"). Grid zones (Zone::view_grid: OBJ levels with a .hepvs) have one row
// per view cell instead, still of region_count bits: row_count() is then the cell count; for
// every other zone rows and regions are the same set (row_count() == region_count()).
//
// Memory scales with what the scene needs: rows are kept either as a dense bit matrix or
// compressed (each row in the shorter of Quake RLE and bit runs, codec/bit_runs.h: sparse rows
// and dense rows in long stretches both shrink; identical rows stored once), chosen when the PVS
// is built:
//   dense when the matrix takes at most 256 KiB, or at most twice the compressed size;
//   compressed otherwise.
// A row marked missing (the file had no row for that region: Quake visofs -1, an empty
// EverQuest VISLIST) decodes as all visible, which is what engines do with it.
//
// PvsRowCursor gives O(1) access to the current row: it decodes only when the region changes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace pvs {

class Pvs {
public:
    enum class Storage : uint8_t { Dense, Compressed };
    enum class StoragePolicy : uint8_t { Auto, Dense, Compressed };

    // Fills one decoded row (words_for(region_count) words, zeroed on entry). Returns false
    // when the source has no row for that region (the row is then "missing": all visible).
    using RowSource = std::function<bool(uint32_t region, std::span<uint64_t> row)>;

    Pvs() = default;
    static Pvs build(uint32_t region_count, const RowSource& source, StoragePolicy policy = StoragePolicy::Auto);
    // row_count rows of region_count bits each (grid zones: one row per view cell).
    static Pvs build_rows(uint32_t row_count, uint32_t region_count, const RowSource& source,
                          StoragePolicy policy = StoragePolicy::Auto);

    uint32_t region_count() const { return region_count_; } // bits per row
    uint32_t row_count() const { return row_count_; }
    bool square() const { return row_count_ == region_count_; }
    size_t words_per_row() const { return words_per_row_; }
    Storage storage() const { return storage_; }
    bool row_missing(uint32_t region) const;
    uint32_t missing_row_count() const { return missing_count_; }

    // Writes the row of `region` (a row index: a view cell in a grid zone) into `out` (words_per_row() words). Never allocates.
    void decode_row(uint32_t region, std::span<uint64_t> out) const;
    // Dense storage only: the row in place, with no copy. Empty span for compressed storage.
    std::span<const uint64_t> dense_row(uint32_t region) const;
    // Does `from` see `to` (false for `to` past the last region)? One bit, read in place from a
    // compressed row (no decode of the rest, no allocation).
    bool visible(uint32_t from, uint32_t to) const;

    size_t memory_bytes() const;

private:
    void decode_compressed(uint32_t region, std::span<uint64_t> out) const;

    static constexpr uint32_t kMissingRow = 0xFFFFFFFFu;

    uint32_t region_count_ = 0;
    uint32_t row_count_ = 0;
    size_t words_per_row_ = 0;
    Storage storage_ = Storage::Dense;
    uint32_t missing_count_ = 0;
    std::vector<uint64_t> dense_;          // region_count * words_per_row, row-major
    std::vector<uint8_t> compressed_;      // Quake RLE rows, each identical row once
    std::vector<uint32_t> row_offsets_;    // compressed: byte offset of each region's row, or kMissingRow
    std::vector<uint64_t> missing_;        // bit set of regions whose row is missing
};

// The current row of a moving camera. Holding one per culler keeps the decode off the
// per-frame path: row() costs a compare when the region has not changed.
class PvsRowCursor {
public:
    explicit PvsRowCursor(const Pvs& pvs);
    std::span<const uint64_t> row(uint32_t region);

private:
    const Pvs* pvs_;
    int64_t region_ = -1;
    std::vector<uint64_t> row_;
};

} // namespace pvs
