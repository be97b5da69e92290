// Hand edits of a PVS with undo and redo: force a pair visible or hidden, in one
// direction or both, or replace a whole row (filled from another PVS, or cleared to the region
// itself). Map authors fix what a bake got wrong; the edits survive a re-bake as an edit list.
//
// Model. EditablePvs holds the rows densely (row_count x words_for(region_count) words; grid
// zones' cell rows too). An edit is kept twice: as what the user asked (PvsEdit: the intent,
// what an edit list stores and re-applies to another bake of the same zone) and as the bits it
// changed (before and after), which is what undo and redo replay, so undoing restores exactly
// the bits that were there whatever the intent was. An edit that changes no bit is still an
// edit (it is on the stack, it is in the list: re-applied after a re-bake it may change bits).
// A new edit clears the redo stack. Rows keep their own region visible in every edit (a camera
// always sees where it is); set_row lists may omit it.
// Edit lists are saved and read as JSON by wld/pvs_edit_list.h.
#pragma once

#include "visibility/pvs.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pvs {

struct PvsEdit {
    enum class Op : uint8_t { Pair, Row };
    Op op = Op::Pair;
    // Pair: the bit (row `from`, region `to`) and, when `both`, (to, from).
    uint32_t from = 0, to = 0;
    bool visible = true;
    bool both = false;
    // Row: row `from` becomes exactly `row_visible` (plus its own region).
    std::vector<uint32_t> row_visible;
    std::string note; // where a row came from ("reference", "portal-fast", "cleared")
};

PvsEdit pair_edit(uint32_t from, uint32_t to, bool visible, bool both);
// Row `row` := row `row` of `source` (same row and region counts).
PvsEdit row_edit_from(const Pvs& source, uint32_t row, std::string note);
// Row `row` := its own region only.
PvsEdit cleared_row_edit(uint32_t row);

class EditablePvs {
public:
    explicit EditablePvs(const Pvs& base);

    uint32_t row_count() const { return rows_; }
    uint32_t region_count() const { return regions_; }
    bool visible(uint32_t row, uint32_t region) const;
    // Whether an edit on the undo stack set this bit (for marking edited pairs).
    bool edited(uint32_t row, uint32_t region) const;

    // Applies an edit; throws std::invalid_argument for an index out of range.
    void apply(const PvsEdit& edit);
    bool can_undo() const { return !done_.empty(); }
    bool can_redo() const { return !undone_.empty(); }
    void undo();
    void redo();
    size_t edit_count() const { return done_.size(); }
    // The intents on the undo stack, oldest first: the edit list to save.
    std::vector<PvsEdit> edits() const;
    // Pairs the edits hid that `reference` sees: what culling with the edited PVS could pop.
    size_t popping_risk(const Pvs& reference) const;

    Pvs to_pvs() const;

private:
    struct BitChange {
        uint32_t row, region;
        bool after;
    };
    struct Done {
        PvsEdit edit;
        std::vector<BitChange> changes; // bits that flipped; undo flips them back
    };
    uint32_t rows_ = 0, regions_ = 0;
    size_t words_ = 0;
    std::vector<uint64_t> bits_;
    std::vector<Done> done_, undone_;

    void set(uint32_t row, uint32_t region, bool value);
    void change(uint32_t row, uint32_t region, bool value, std::vector<BitChange>& changes);
    std::vector<BitChange> perform(const PvsEdit& edit);
};

// `base` with `edits` applied in order; throws std::invalid_argument for an index out of range.
Pvs apply_edits(const Pvs& base, const std::vector<PvsEdit>& edits);

} // namespace pvs
