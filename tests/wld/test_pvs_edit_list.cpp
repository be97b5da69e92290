// PVS edit lists on disk (wld/pvs_edit_list.h): a round trip, and bad lists refused with the
// file and the edit named.
#include "wld/pvs_edit_list.h"

#include "visibility/file_error.h"

#include <gtest/gtest.h>

namespace pvs {
namespace {

TEST(PvsEditList, RoundTrip)
{
    PvsEdit row;
    row.op = PvsEdit::Op::Row;
    row.from = 3;
    row.row_visible = {0, 3, 7};
    row.note = "reference";
    const std::vector<PvsEdit> edits = {pair_edit(1, 2, false, true), row};
    const std::vector<PvsEdit> back = parse_edit_list(edit_list_json(edits, 8, 8), "e.json", 8, 8);
    ASSERT_EQ(back.size(), 2u);
    EXPECT_EQ(back[0].op, PvsEdit::Op::Pair);
    EXPECT_EQ(back[0].from, 1u);
    EXPECT_EQ(back[0].to, 2u);
    EXPECT_FALSE(back[0].visible);
    EXPECT_TRUE(back[0].both);
    EXPECT_EQ(back[1].row_visible, (std::vector<uint32_t>{0, 3, 7}));
    EXPECT_EQ(back[1].note, "reference");
}

TEST(PvsEditList, BadListsNameTheFileAndTheEdit)
{
    const std::string good = edit_list_json({pair_edit(1, 2, true, false)}, 8, 8);
    const auto error = [](const std::string& text, uint32_t n = 8) {
        try {
            parse_edit_list(text, "e.json", n, n);
        } catch (const FileError& e) {
            EXPECT_EQ(e.file(), "e.json");
            return std::string(e.reason());
        }
        return std::string("(no error)");
    };
    EXPECT_NE(error(good, 9).find("another zone"), std::string::npos);
    EXPECT_NE(error("{").find("not JSON"), std::string::npos);
    EXPECT_NE(error(R"({"format":"x"})").find("not a PVS edit list"), std::string::npos);
    std::string bad_index = good;
    bad_index.replace(bad_index.find("\"to\": 2"), 7, "\"to\": 99");
    EXPECT_NE(error(bad_index).find("edit 0: \"to\" 99 out of range"), std::string::npos) << error(bad_index);
    std::string bad_op = good;
    bad_op.replace(bad_op.find("\"pair\""), 6, "\"swap\"");
    EXPECT_NE(error(bad_op).find("unknown op"), std::string::npos);
}

} // namespace
} // namespace pvs
