// The file browser's listing (a temporary directory of known files), the recent-files store
// (order, duplicates, limit, persistence, corrupt and oversized files, the XDG path), and the
// File menu's open: success remembered, failure in the error modal, never thrown.
#include "tests/gui/headless_imgui.h"
#include "ui/gui/file_browser.h"
#include "ui/gui/panels.h"
#include "ui/gui/recent_files.h"

#include <gtest/gtest.h>

#include <imgui_internal.h>

#include <cstdlib>
#include <fstream>
#include <random>
#include <unistd.h>

namespace pvs {
namespace {

namespace fs = std::filesystem;

struct TempDir : ::testing::Test {
    void SetUp() override
    {
        dir = fs::temp_directory_path() /
              ("pvscope-gui-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    void touch(const fs::path& path, const std::string& content = "x")
    {
        std::ofstream(path, std::ios::binary) << content;
    }
    fs::path dir;
};

std::vector<std::string> names(const gui::DirectoryListing& listing)
{
    std::vector<std::string> out;
    for (const auto& e : listing.entries)
        out.push_back((e.directory ? "/" : "") + e.name);
    return out;
}

TEST_F(TempDir, ListingHasDirectoriesFirstThenZoneFiles)
{
    for (const char* name : {"a.bsp", "B.S3D", "c.txt", ".hidden.bsp", "d.obj", "e.WAD", "f.bsp.bak"})
        touch(dir / name, std::string(10, 'z'));
    fs::create_directories(dir / "sub");
    fs::create_directories(dir / ".git");
    const gui::DirectoryListing listing = gui::list_directory(dir);
    EXPECT_TRUE(listing.error.empty()) << listing.error;
    EXPECT_EQ(names(listing), (std::vector<std::string>{"/sub", "B.S3D", "a.bsp", "d.obj", "e.WAD"}));
    EXPECT_EQ(listing.entries[1].size, 10u);
    const gui::DirectoryListing all = gui::list_directory(dir, true);
    EXPECT_EQ(names(all), (std::vector<std::string>{"/sub", "B.S3D", "a.bsp", "c.txt", "d.obj", "e.WAD", "f.bsp.bak"}));
}

TEST_F(TempDir, MissingDirectoryIsAnErrorNotAnException)
{
    const gui::DirectoryListing listing = gui::list_directory(dir / "nope");
    EXPECT_TRUE(listing.entries.empty());
    EXPECT_NE(listing.error.find("nope"), std::string::npos) << listing.error;
    touch(dir / "file.bsp");
    EXPECT_FALSE(gui::list_directory(dir / "file.bsp").error.empty()); // a file, not a directory
}

TEST_F(TempDir, RecentFilesKeepOrderLimitAndPersist)
{
    const fs::path store = dir / "config" / "pvscope" / "recent.txt";
    gui::RecentFiles recent(store);
    recent.load(); // no file yet
    EXPECT_TRUE(recent.paths().empty());
    for (int i = 0; i < 12; ++i)
        recent.add("/zones/" + std::to_string(i) + ".bsp");
    recent.add("/zones/5.bsp"); // again: moves to the front, once
    recent.add("bad\npath");    // control characters: not remembered
    recent.add(std::string(gui::kMaxRecentPathLength + 1, 'a'));
    EXPECT_TRUE(recent.error().empty()) << recent.error();
    ASSERT_EQ(recent.paths().size(), gui::kMaxRecentFiles);
    EXPECT_EQ(recent.paths()[0], "/zones/5.bsp");
    EXPECT_EQ(recent.paths()[1], "/zones/11.bsp");
    EXPECT_EQ(std::count(recent.paths().begin(), recent.paths().end(), "/zones/5.bsp"), 1);

    gui::RecentFiles again(store);
    again.load();
    EXPECT_EQ(again.paths(), recent.paths());
    again.remove("/zones/5.bsp");
    gui::RecentFiles third(store);
    third.load();
    EXPECT_EQ(third.paths().front(), "/zones/11.bsp");
    EXPECT_EQ(third.paths().size(), gui::kMaxRecentFiles - 1);
}

TEST_F(TempDir, CorruptRecentFilesAreIgnoredAndReplaced)
{
    const fs::path store = dir / "recent.txt";
    // Binary junk (no header): nothing read, nothing thrown.
    std::string junk(4096, '\0');
    std::mt19937 random(5);
    for (char& c : junk)
        c = char(random() & 0xFF);
    touch(store, junk);
    gui::RecentFiles recent(store);
    recent.load();
    EXPECT_TRUE(recent.paths().empty());
    // The right header with bad lines among good ones: the good ones only.
    touch(store, std::string(gui::kRecentFilesHeader) + "\n/a.bsp\n\n/b\x01.bsp\n/a.bsp\n" +
                     std::string(gui::kMaxRecentPathLength + 10, 'x') + "\n/c.s3d");
    recent.load();
    EXPECT_EQ(recent.paths(), (std::vector<std::string>{"/a.bsp", "/c.s3d"}));
    // Too large to be ours: ignored.
    touch(store, std::string(gui::kRecentFilesHeader) + "\n" + std::string(gui::kMaxRecentBytes, 'y'));
    recent.load();
    EXPECT_TRUE(recent.paths().empty());
    // Adding rewrites a clean file.
    recent.add("/d.wad");
    gui::RecentFiles reread(store);
    reread.load();
    EXPECT_EQ(reread.paths(), (std::vector<std::string>{"/d.wad"}));
    // A store that cannot be written says so.
    gui::RecentFiles unwritable(dir / "recent.txt" / "inside-a-file.txt");
    unwritable.add("/e.bsp");
    EXPECT_FALSE(unwritable.error().empty());
    EXPECT_EQ(unwritable.paths().size(), 1u);
}

TEST_F(TempDir, DefaultStoreFollowsXdgConfigHome)
{
    const char* old_xdg = std::getenv("XDG_CONFIG_HOME");
    const std::string saved = old_xdg ? old_xdg : "";
    ::setenv("XDG_CONFIG_HOME", dir.c_str(), 1);
    EXPECT_EQ(gui::default_recent_files_path(), dir / "pvscope" / "recent.txt");
    ::setenv("XDG_CONFIG_HOME", "relative/ignored", 1); // the spec wants an absolute path
    if (const char* home = std::getenv("HOME"); home && home[0]) {
        EXPECT_EQ(gui::default_recent_files_path(), fs::path(home) / ".config" / "pvscope" / "recent.txt");
    }
    if (old_xdg)
        ::setenv("XDG_CONFIG_HOME", saved.c_str(), 1);
    else
        ::unsetenv("XDG_CONFIG_HOME");
}

struct FileMenuHeadless : TempDir {
    void SetUp() override
    {
        TempDir::SetUp();
        test::create_headless_imgui_context();
        panels.file.recent = gui::RecentFiles(dir / "recent.txt");
        state.set_viewport_size(64, 48);
        state.open_demo();
    }
    void TearDown() override
    {
        ImGui::DestroyContext();
        TempDir::TearDown();
    }
    void frame()
    {
        ImGui::NewFrame();
        gui::draw_inspector(state, panels, 0.0f);
        ImGui::Render();
    }
    gui::InspectorState state;
    gui::InspectorPanels panels;
};

TEST_F(FileMenuHeadless, BadFileOpensTheErrorModalAndKeepsTheZone)
{
    touch(dir / "broken.bsp", "not a bsp at all");
    const uint64_t generation = state.zone_generation();
    EXPECT_FALSE(gui::open_zone_file(state, panels.file, (dir / "broken.bsp").string()));
    EXPECT_EQ(state.zone_generation(), generation);
    EXPECT_NE(panels.file.error.find("broken.bsp"), std::string::npos) << panels.file.error;
    EXPECT_TRUE(panels.file.recent.paths().empty());
    frame();
    frame();
    const ImGuiWindow* modal = ImGui::FindWindowByName("Cannot open");
    ASSERT_NE(modal, nullptr);
    EXPECT_TRUE(modal->Active);
}

TEST_F(FileMenuHeadless, BrowserListsTheDirectoryAndEveryPanelDraws)
{
    touch(dir / "zone.bsp");
    gui::browse_to(panels.file, dir);
    panels.file.browser_open = true;
    for (int i = 0; i < 3; ++i)
        frame();
    const ImGuiWindow* browser = ImGui::FindWindowByName("Open zone");
    ASSERT_NE(browser, nullptr);
    EXPECT_TRUE(browser->Active);
    EXPECT_EQ(names(panels.file.listing), (std::vector<std::string>{"zone.bsp"}));
    for (const char* name : {"Viewport", "Zone", "Culling", "Region", "BSP", "Bake", "##MainMenuBar"}) {
        const ImGuiWindow* window = ImGui::FindWindowByName(name);
        ASSERT_NE(window, nullptr) << name;
        EXPECT_TRUE(window->WasActive) << name;
    }
    panels.file.browser_open = false;
    frame();
}

} // namespace
} // namespace pvs
