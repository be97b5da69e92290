// libFuzzer target: PVS edit lists, JSON (wld/pvs_edit_list.h). The first two bytes choose the
// zone's rows and regions (the list must match them), the rest is the text. An accepted list
// names only rows and regions of that zone, and writes back to a list that reads the same.
#include "tests/fuzz/fuzz_support.h"
#include "wld/pvs_edit_list.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    if (size < 2)
        return 0;
    const uint32_t rows = data[0], regions = data[1];
    const std::string text(fuzz::as_text(data + 2, size - 2));
    fuzz::accepts([&] {
        const std::vector<PvsEdit> edits = parse_edit_list(text, "fuzz.json", rows, regions);
        const std::vector<PvsEdit> again = parse_edit_list(edit_list_json(edits, rows, regions), "again.json", rows, regions);
        fuzz::fuzz_check(again.size() == edits.size(), "edit list round-trips: count");
        for (size_t i = 0; i < edits.size(); ++i) {
            const PvsEdit &a = edits[i], &b = again[i];
            fuzz::fuzz_check(a.op == b.op && a.from == b.from && a.row_visible == b.row_visible && a.note == b.note,
                             "edit list round-trips: row edits");
            if (a.op == PvsEdit::Op::Pair)
                fuzz::fuzz_check(a.to == b.to && a.visible == b.visible && a.both == b.both,
                                 "edit list round-trips: pair edits");
        }
    });
    return 0;
}
