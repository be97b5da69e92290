// Inputs the libFuzzer targets (tests/fuzz/, docs/fuzzing.md) found, kept as regression tests
// so that they run under gcc with ASan + UBSan in CI: each must now be refused with a FileError
// naming the problem, not crash, abort or allocate without bound. One TEST per finding, named
// after the target that found it; the bytes are the fuzzer's input (or a minimal equivalent).
#include "visibility/file_error.h"
#include "wld/hepvs/hepvs_file.h"
#include "wld/pvs_edit_list.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pvs {
namespace {

// Runs `parse`, which must throw FileError; returns it.
template <class F>
FileError file_error_of(F&& parse)
{
    try {
        parse();
    } catch (const FileError& e) {
        return e;
    }
    ADD_FAILURE() << "no FileError";
    return FileError("", 0, "");
}

// fuzz_hepvs: a header declaring 2304 x 2560 x 2816 cells (16.6 G) over 97 bytes of cells made
// the reader reserve 66 GB of cell offsets before reading the first cell.
TEST(FuzzRegressions, HepvsCellCountLargerThanTheFile)
{
    const std::vector<uint8_t> bytes = {
    0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x10, 0x41, 0x00, 0x00, 0x00, 0xbf, 0x00, 0x00, 0xe0, 0x40,
    0x00, 0x00, 0x00, 0x41, 0x00, 0x09, 0x00, 0x0a, 0x00, 0x0b, 0x00, 0x00, 0x00, 0x01, 0x00, 0x02,
    0x00, 0x03, 0x00, 0x04, 0x00, 0x5d, 0x00, 0x06, 0x00, 0x07, 0x00, 0x08, 0x00, 0x09, 0x00, 0x0a,
    0x00, 0x0b, 0x00, 0x00, 0x00, 0x01, 0x00, 0x02, 0x00, 0x03, 0x00, 0x04, 0x00, 0x05, 0x00, 0x06,
    0x00, 0x07, 0x00, 0x08, 0x00, 0x09, 0x00, 0x0a, 0x00, 0x0b, 0x00, 0x00, 0x00, 0x01, 0x00, 0x02,
    0x00, 0x03, 0x00, 0x04, 0x00, 0x05, 0x00, 0x06, 0x00, 0x07, 0x00, 0x08, 0x00, 0x09, 0x00, 0x0a,
    0x00, 0x0a, 0x00, 0x00, 0x00, 0x01, 0x00, 0x02, 0x00, 0x03, 0x00, 0x04, 0x00, 0x01, 0x00, 0x02,
    0x00, 0x03, 0x00, 0x04, 0x00, 0x05, 0x00, 0x06, 0x00, 0x07, 0x00, 0x0a, 0x00,
    };
    const FileError e = file_error_of([&] { read_hepvs(bytes, "crash.hepvs"); });
    EXPECT_EQ(e.file(), "crash.hepvs");
    EXPECT_EQ(e.offset(), 20u);
    EXPECT_NE(e.reason().find("cells need at least"), std::string::npos) << e.reason();
}

// The same with the largest counts a header can hold (65535^3 cells, 2^48 bytes of offsets).
TEST(FuzzRegressions, HepvsLargestCellCounts)
{
    std::vector<uint8_t> bytes = {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x80, 0x3f,
                                  0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0, 0};
    bytes.resize(bytes.size() + 64, 0);
    EXPECT_EQ(file_error_of([&] { read_hepvs(bytes, "big.hepvs"); }).offset(), 20u);
}

// fuzz_edit_list: a number too large for a double made nlohmann::json throw out_of_range, which
// escaped parse_edit_list (only parse_error was caught).
TEST(FuzzRegressions, EditListNumberOverflow)
{
    const FileError e = file_error_of([] { parse_edit_list("\n1e400", "crash.json", 79, 79); });
    EXPECT_EQ(e.file(), "crash.json");
    EXPECT_NE(e.reason().find("not JSON"), std::string::npos) << e.reason();
}

// The same family: fields of the wrong JSON type made value() throw type_error.
TEST(FuzzRegressions, EditListFieldsOfTheWrongType)
{
    for (const char* text : {R"({"format": 1})", R"({"format": "pvscope-pvs-edits", "version": "1"})",
                              R"({"format": "pvscope-pvs-edits", "version": 1, "rows": "8", "regions": 8})",
                              R"({"format": "pvscope-pvs-edits", "version": 1, "rows": 8, "regions": -8})"})
        EXPECT_EQ(file_error_of([&] { parse_edit_list(text, "wrong.json", 8, 8); }).file(), "wrong.json") << text;
}

} // namespace
} // namespace pvs
