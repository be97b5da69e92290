// PVS editing in the inspector (InspectorState, "PVS editing"), headless on the demo zone: a
// hidden pair stops being drawn, undo and redo restore and replay it, a row filled from
// portal-fast equals portal-fast's row, the edit list saved and loaded again into a fresh
// session gives the same PVS, and a zone change drops the edits.
#include "ui/gui/inspector_state.h"

#include "visibility/methods/vis_method.h"

#include <gtest/gtest.h>
#include <iterator>
#include <cstring>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace pvs::gui {
namespace {

struct EditingInspector : ::testing::Test {
    void SetUp() override
    {
        state.set_viewport_size(160, 120);
        state.open_demo();
        ASSERT_TRUE(state.has_zone());
        ASSERT_TRUE(state.active_pvs()) << "the demo zone is baked";
        camera = state.frame().region;
        ASSERT_GE(camera, 0);
    }
    // A region the camera's row holds, other than its own.
    uint32_t seen_region() const
    {
        const Pvs& pvs = *state.active_pvs();
        for (uint32_t r = 0; r < pvs.region_count(); ++r)
            if (r != uint32_t(camera) && pvs.visible(uint32_t(camera), r))
                return r;
        return UINT32_MAX;
    }
    InspectorState state;
    int32_t camera = -1;
};

TEST_F(EditingInspector, HideUndoRedo)
{
    const uint32_t target = seen_region();
    ASSERT_NE(target, UINT32_MAX);
    ASSERT_TRUE(state.edit_pvs(pair_edit(uint32_t(camera), target, false, true)));
    EXPECT_EQ(state.pvs_source(), PvsSource::Edited);
    EXPECT_FALSE(state.active_pvs()->visible(uint32_t(camera), target));
    EXPECT_FALSE(state.active_pvs()->visible(target, uint32_t(camera)));
    state.frame(); // the culler uses the edited PVS
    EXPECT_TRUE(state.undo_pvs_edit());
    EXPECT_TRUE(state.active_pvs()->visible(uint32_t(camera), target));
    EXPECT_FALSE(state.undo_pvs_edit()) << "nothing more to undo";
    EXPECT_TRUE(state.redo_pvs_edit());
    EXPECT_FALSE(state.active_pvs()->visible(uint32_t(camera), target));
    EXPECT_EQ(state.pvs_editor()->edit_count(), 1u);
    EXPECT_FALSE(state.edit_pvs(pair_edit(uint32_t(camera), 1u << 30, true, false))) << "out of range";
}

TEST_F(EditingInspector, RowFromPortalFastAndTheListRoundTrip)
{
    ASSERT_TRUE(state.fill_pvs_row(uint32_t(camera), "portal-fast"));
    const Pvs fast = *find_vis_method("portal-fast")->run(state.zone(), MethodSettings{}).pvs;
    for (uint32_t r = 0; r < fast.region_count(); ++r)
        EXPECT_EQ(state.active_pvs()->visible(uint32_t(camera), r), fast.visible(uint32_t(camera), r)) << r;
    const uint32_t target = seen_region();
    ASSERT_TRUE(state.edit_pvs(pair_edit(uint32_t(camera), target, false, false)));
    const Pvs edited = *state.active_pvs();

    const std::string path = (std::filesystem::temp_directory_path() /
                              ("pvscope-edits-" + std::to_string(getpid()) + ".json"))
                                 .string();
    std::ofstream(path) << state.pvs_edit_list_json();
    InspectorState again;
    again.set_viewport_size(160, 120);
    again.open_demo();
    ASSERT_TRUE(again.load_pvs_edit_list(path)) << again.error();
    EXPECT_EQ(again.pvs_editor()->edit_count(), 2u);
    for (uint32_t r = 0; r < edited.row_count(); ++r)
        for (uint32_t c = 0; c < edited.region_count(); ++c)
            ASSERT_EQ(again.active_pvs()->visible(r, c), edited.visible(r, c)) << r << " " << c;
    std::filesystem::remove(path);

    state.open_demo();
    EXPECT_EQ(state.pvs_editor(), nullptr) << "a new zone drops the edits";
    EXPECT_NE(state.pvs_source(), PvsSource::Edited);
}

} // namespace
} // namespace pvs::gui

#include "tests/support/test_data.h"
#include "visibility/file_error.h"
#include "gen/generate_zone.h"
#include "wld/pvs_writeback.h"
#include "wld/zone_file.h"

namespace pvs::gui {
namespace {

std::vector<uint8_t> file_bytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// BSP 29 (quake-doom-hepvs.md): a version word, then 15 lumps of (offset, length). Every lump
// but VISIBILITY (4) must be the original's byte for byte, leaves (10, 28 bytes each) apart from
// their visofs field (bytes 4..7), which points into the new visibility lump.
void expect_only_the_pvs_changed(const std::string& original_path, const std::string& saved_path)
{
    const std::vector<uint8_t> original = file_bytes(original_path), saved = file_bytes(saved_path);
    ASSERT_GE(original.size(), 124u);
    ASSERT_GE(saved.size(), 124u);
    auto lump = [](const std::vector<uint8_t>& bsp, int index) {
        int32_t offset = 0, length = 0;
        std::memcpy(&offset, bsp.data() + 4 + 8 * index, 4);
        std::memcpy(&length, bsp.data() + 8 + 8 * index, 4);
        EXPECT_GE(offset, 0);
        EXPECT_LE(size_t(offset) + size_t(length), bsp.size());
        return std::vector<uint8_t>(bsp.begin() + offset, bsp.begin() + offset + length);
    };
    EXPECT_EQ(std::memcmp(original.data(), saved.data(), 4), 0) << "version";
    for (int i = 0; i < 15; ++i) {
        if (i == 4)
            continue;
        std::vector<uint8_t> a = lump(original, i), b = lump(saved, i);
        ASSERT_EQ(a.size(), b.size()) << "lump " << i;
        if (i == 10)
            for (size_t leaf = 0; leaf < a.size() / 28; ++leaf) {
                std::memset(a.data() + 28 * leaf + 4, 0, 4);
                std::memset(b.data() + 28 * leaf + 4, 0, 4);
            }
        EXPECT_TRUE(a == b) << "lump " << i << " changed";
    }
}

// Save on a real map: the copy read back has the edited PVS and every other byte of the file
// (lump by lump); a generated zone (no file) says it cannot be saved.
TEST(EditingOnE1m1, SaveWritesTheEditedPvsIntoACopyOfTheBsp)
{
    SHARED_DATA_OR_SKIP(e1m1, "quake/e1m1.bsp");
    InspectorState state;
    state.set_viewport_size(160, 120);
    ASSERT_TRUE(state.open_zone(e1m1)) << state.error();
    const Pvs& file = *state.active_pvs();
    uint32_t target = 1;
    while (target < file.region_count() && !file.visible(0, target))
        ++target;
    ASSERT_LT(target, file.region_count());
    ASSERT_TRUE(state.edit_pvs(pair_edit(0, target, false, true)));
    const std::string out = (std::filesystem::temp_directory_path() /
                             ("pvscope-saved-" + std::to_string(getpid()) + ".bsp"))
                                .string();
    std::string message;
    ASSERT_TRUE(state.save_pvs(out, message)) << state.error();
    EXPECT_NE(message.find("rows"), std::string::npos) << message;
    const Zone saved = load_zone(out);
    ASSERT_TRUE(saved.baked_pvs);
    EXPECT_FALSE(saved.baked_pvs->visible(0, target));
    EXPECT_FALSE(saved.baked_pvs->visible(target, 0));
    size_t differences = 0;
    for (uint32_t r = 0; r < file.region_count(); r += 7)
        for (uint32_t c = 0; c < file.region_count(); ++c)
            differences += saved.baked_pvs->visible(r, c) != state.active_pvs()->visible(r, c);
    EXPECT_EQ(differences, 0u);
    expect_only_the_pvs_changed(e1m1, out);
    std::filesystem::remove(out);
}

TEST(EditingOnE1m1, AZoneWithoutAFileCannotBeSaved)
{
    gen::GenParams params;
    params.rooms = 6;
    params.bake = true;
    const Zone generated = gen::generate_zone(params);
    ASSERT_TRUE(generated.baked_pvs);
    try {
        write_pvs_in_zone_format(generated, {}, *generated.baked_pvs, "unused.s3d");
        FAIL() << "no error";
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("not read from a file"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace pvs::gui

namespace pvs::gui {
namespace {

// The membership overlay renders every region (the depth test decides what shows) and tints
// them; without it only the culled set is drawn.
TEST(MembershipTint, DrawsEveryRegionTinted)
{
    InspectorState state;
    state.set_viewport_size(160, 120);
    state.open_demo();
    state.frame();
    const uint32_t culled_faces = state.last_render().faces_drawn;
    state.overlays.pvs_membership = true;
    state.frame();
    EXPECT_GT(state.last_render().faces_drawn, culled_faces);
    EXPECT_EQ(state.after_pvs_regions().empty(), false) << "the PVS stage's set is computed for the classes";
}

} // namespace
} // namespace pvs::gui
