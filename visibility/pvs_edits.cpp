#include "visibility/pvs_edits.h"

#include "visibility/bit_row.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace pvs {

PvsEdit pair_edit(uint32_t from, uint32_t to, bool visible, bool both)
{
    PvsEdit e;
    e.op = PvsEdit::Op::Pair;
    e.from = from;
    e.to = to;
    e.visible = visible;
    e.both = both;
    return e;
}

PvsEdit row_edit_from(const Pvs& source, uint32_t row, std::string note)
{
    if (row >= source.row_count())
        throw std::invalid_argument("row " + std::to_string(row) + " out of range");
    PvsEdit e;
    e.op = PvsEdit::Op::Row;
    e.from = row;
    e.note = std::move(note);
    std::vector<uint64_t> words(source.words_per_row());
    source.decode_row(row, words);
    bits::for_each_set(words, [&](size_t region) {
        if (region < source.region_count())
            e.row_visible.push_back(uint32_t(region));
    });
    return e;
}

PvsEdit cleared_row_edit(uint32_t row)
{
    PvsEdit e;
    e.op = PvsEdit::Op::Row;
    e.from = row;
    e.note = "cleared";
    return e;
}

EditablePvs::EditablePvs(const Pvs& base)
    : rows_(base.row_count()), regions_(base.region_count()), words_(bits::words_for(base.region_count())),
      bits_(size_t(rows_) * words_, 0)
{
    for (uint32_t r = 0; r < rows_; ++r)
        base.decode_row(r, std::span<uint64_t>(bits_.data() + size_t(r) * words_, words_));
}

bool EditablePvs::visible(uint32_t row, uint32_t region) const
{
    return row < rows_ && region < regions_ &&
           bits::test(std::span<const uint64_t>(bits_.data() + size_t(row) * words_, words_), region);
}

bool EditablePvs::edited(uint32_t row, uint32_t region) const
{
    for (const Done& d : done_)
        for (const BitChange& c : d.changes)
            if (c.row == row && c.region == region)
                return true;
    return false;
}

void EditablePvs::set(uint32_t row, uint32_t region, bool value)
{
    const std::span<uint64_t> words(bits_.data() + size_t(row) * words_, words_);
    value ? bits::set(words, region) : bits::clear(words, region);
}

void EditablePvs::change(uint32_t row, uint32_t region, bool value, std::vector<BitChange>& changes)
{
    if (visible(row, region) == value)
        return;
    set(row, region, value);
    changes.push_back({row, region, value});
}

std::vector<EditablePvs::BitChange> EditablePvs::perform(const PvsEdit& edit)
{
    const auto check = [&](uint32_t row, uint32_t region) {
        if (row >= rows_ || region >= regions_)
            throw std::invalid_argument("edit of row " + std::to_string(row) + ", region " + std::to_string(region) +
                                        ": out of range (" + std::to_string(rows_) + " rows, " +
                                        std::to_string(regions_) + " regions)");
    };
    std::vector<BitChange> changes;
    if (edit.op == PvsEdit::Op::Pair) {
        check(edit.from, edit.to);
        if (edit.both)
            check(edit.to, edit.from);
        // A square PVS keeps each region seeing itself.
        const bool self = rows_ == regions_ && edit.from == edit.to;
        change(edit.from, edit.to, edit.visible || self, changes);
        if (edit.both)
            change(edit.to, edit.from, edit.visible || self, changes);
        return changes;
    }
    check(edit.from, 0);
    for (uint32_t region : edit.row_visible)
        check(edit.from, region);
    std::vector<uint8_t> wanted(regions_, 0);
    for (uint32_t region : edit.row_visible)
        wanted[region] = 1;
    if (rows_ == regions_)
        wanted[edit.from] = 1;
    for (uint32_t region = 0; region < regions_; ++region)
        change(edit.from, region, wanted[region] != 0, changes);
    return changes;
}

void EditablePvs::apply(const PvsEdit& edit)
{
    std::vector<BitChange> changes = perform(edit);
    done_.push_back({edit, std::move(changes)});
    undone_.clear();
}

void EditablePvs::undo()
{
    if (done_.empty())
        return;
    Done d = std::move(done_.back());
    done_.pop_back();
    for (auto it = d.changes.rbegin(); it != d.changes.rend(); ++it)
        set(it->row, it->region, !it->after);
    undone_.push_back(std::move(d));
}

void EditablePvs::redo()
{
    if (undone_.empty())
        return;
    Done d = std::move(undone_.back());
    undone_.pop_back();
    for (const BitChange& c : d.changes)
        set(c.row, c.region, c.after);
    done_.push_back(std::move(d));
}

std::vector<PvsEdit> EditablePvs::edits() const
{
    std::vector<PvsEdit> out;
    for (const Done& d : done_)
        out.push_back(d.edit);
    return out;
}

size_t EditablePvs::popping_risk(const Pvs& reference) const
{
    if (reference.row_count() != rows_ || reference.region_count() != regions_)
        return 0;
    std::vector<std::pair<uint32_t, uint32_t>> hidden; // edited bits that are clear now
    for (const Done& d : done_)
        for (const BitChange& c : d.changes)
            if (!visible(c.row, c.region))
                hidden.emplace_back(c.row, c.region);
    std::sort(hidden.begin(), hidden.end());
    hidden.erase(std::unique(hidden.begin(), hidden.end()), hidden.end());
    size_t risk = 0;
    for (const auto& [row, region] : hidden)
        risk += reference.visible(row, region);
    return risk;
}

Pvs EditablePvs::to_pvs() const
{
    return Pvs::build_rows(rows_, regions_, [&](uint32_t row, std::span<uint64_t> out) {
        std::copy_n(bits_.data() + size_t(row) * words_, words_, out.data());
        return true;
    });
}

Pvs apply_edits(const Pvs& base, const std::vector<PvsEdit>& edits)
{
    EditablePvs editable(base);
    for (const PvsEdit& edit : edits)
        editable.apply(edit);
    return editable.to_pvs();
}

} // namespace pvs
