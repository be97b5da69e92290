// Generated zones baked when made (wld/gen/generate_zone.h, GenParams::bake) and the cached
// demo zone (wld/gen/demo_zone.h):
//  - the baked PVS is conservative, checked independently of the portals: random pairs of
//    points in two regions whose straight segment stays in open space — found by an exact walk
//    of the segment down the BSP tree, every leaf it passes through a region — must have the
//    second region in the first's row;
//  - the notes name the method; bake off gives no PVS;
//  - the demo cache: made once then read back (the same rows), a corrupt file is made again,
//    a cache directory that cannot be made still gives the zone.
#include "gen/demo_zone.h"
#include "gen/generate_zone.h"

#include "visibility/region_lookup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <random>
#include <unistd.h>

namespace pvs {
namespace {

namespace fs = std::filesystem;

bool has_note(const Zone& zone, const std::string& text)
{
    return std::any_of(zone.source.notes.begin(), zone.source.notes.end(),
                       [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

// True when every leaf the segment a-b passes through is a region: the segment is split at
// each node plane it crosses (in double precision), as a trace walks a BSP; a piece on the
// plane goes front (the generated zones' EverQuest tie rule).
bool segment_in_open_space(const BspTree& tree, int32_t child, glm::dvec3 a, glm::dvec3 b)
{
    while (!BspTree::is_leaf(child)) {
        const BspNode& node = tree.nodes[size_t(child)];
        const glm::dvec3 n(node.normal);
        const double da = glm::dot(n, a) - double(node.dist), db = glm::dot(n, b) - double(node.dist);
        if (da >= 0.0 && db >= 0.0) {
            child = node.children[0];
        } else if (da < 0.0 && db < 0.0) {
            child = node.children[1];
        } else {
            const glm::dvec3 mid = a + (b - a) * (da / (da - db));
            const int near_side = da >= 0.0 ? 0 : 1;
            if (!segment_in_open_space(tree, node.children[near_side], a, mid))
                return false;
            child = node.children[1 - near_side];
            a = mid;
        }
    }
    return tree.leaf_region[size_t(BspTree::leaf_index(child))] >= 0;
}

glm::vec3 random_point_in(const Aabb& box, std::mt19937& rng)
{
    std::uniform_real_distribution<float> u(0.02f, 0.98f); // strictly inside the region's box
    return box.min + (box.max - box.min) * glm::vec3(u(rng), u(rng), u(rng));
}

TEST(GenBake, TheBakedPvsHoldsEveryClearSightLine)
{
    gen::GenParams params{40, 11, 32.0f, true};
    const Zone zone = gen::generate_zone(params);
    ASSERT_TRUE(zone.baked_pvs.has_value());
    ASSERT_EQ(zone.baked_pvs->region_count(), zone.region_count());
    EXPECT_TRUE(has_note(zone, "PVS baked with portal-full"));

    std::mt19937 rng(5);
    std::uniform_int_distribution<size_t> pick(0, zone.region_count() - 1);
    size_t checked = 0, missing = 0;
    for (int attempt = 0; attempt < 40000; ++attempt) {
        const size_t ra = pick(rng), rb = pick(rng);
        if (ra == rb)
            continue;
        const glm::vec3 a = random_point_in(zone.regions[ra].bounds, rng);
        const glm::vec3 b = random_point_in(zone.regions[rb].bounds, rng);
        ASSERT_EQ(locate_point(zone.tree, a).region, int32_t(ra));
        ASSERT_EQ(locate_point(zone.tree, b).region, int32_t(rb));
        if (!segment_in_open_space(zone.tree, zone.tree.root, a, b))
            continue;
        ++checked;
        if (!zone.baked_pvs->visible(uint32_t(ra), uint32_t(rb))) {
            ++missing;
            ADD_FAILURE() << "region " << ra << " sees " << rb << " along a clear line but its row lacks it";
        }
    }
    EXPECT_EQ(missing, 0u);
    EXPECT_GT(checked, 300u) << "too few clear lines to say anything";
    // The PVS culls something: a room does not see the whole zone.
    size_t total = 0;
    for (uint32_t r = 0; r < zone.region_count(); ++r)
        for (uint32_t s = 0; s < zone.region_count(); ++s)
            total += zone.baked_pvs->visible(r, s) ? 1 : 0;
    EXPECT_LT(double(total) / double(zone.region_count()), 0.5 * double(zone.region_count()));
}

TEST(GenBake, BakeOffGivesNoPvsAndSaysSo)
{
    const Zone zone = gen::generate_zone({12, 3, 32.0f});
    EXPECT_FALSE(zone.baked_pvs.has_value());
    EXPECT_TRUE(has_note(zone, "no PVS"));
    EXPECT_TRUE(gen::demo_zone_params().bake);
}

std::vector<std::vector<uint64_t>> rows_of(const Pvs& pvs)
{
    std::vector<std::vector<uint64_t>> rows(pvs.region_count(), std::vector<uint64_t>(pvs.words_per_row()));
    for (uint32_t r = 0; r < pvs.region_count(); ++r)
        pvs.decode_row(r, rows[r]);
    return rows;
}

class DemoCache : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = fs::temp_directory_path() / ("pvscope_demo_cache_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
    gen::GenParams params_{10, 77, 32.0f, true};
};

TEST_F(DemoCache, MadeOnceThenReadBackWithTheSameRows)
{
    gen::DemoZoneSource first, second;
    const Zone a = gen::load_or_make_demo_zone(params_, dir_.string(), &first);
    EXPECT_FALSE(first.from_cache);
    EXPECT_TRUE(first.cached) << first.problem;
    EXPECT_EQ(fs::path(first.cache_path).filename(), "demo-10-77-v" + std::to_string(gen::kDemoCacheVersion) + ".s3d");
    EXPECT_TRUE(fs::is_regular_file(first.cache_path));

    const Zone b = gen::load_or_make_demo_zone(params_, dir_.string(), &second);
    EXPECT_TRUE(second.from_cache) << second.problem;
    EXPECT_TRUE(has_note(b, "read from the cache"));
    EXPECT_TRUE(has_note(b, "portal-full"));
    ASSERT_TRUE(a.baked_pvs && b.baked_pvs);
    EXPECT_EQ(rows_of(*a.baked_pvs), rows_of(*b.baked_pvs));
    // The same as baking the generated zone directly.
    const Zone made = gen::generate_zone(params_);
    ASSERT_TRUE(made.baked_pvs.has_value());
    EXPECT_EQ(rows_of(*b.baked_pvs), rows_of(*made.baked_pvs));
    EXPECT_EQ(b.region_count(), made.region_count());
}

TEST_F(DemoCache, ACorruptCacheFileIsMadeAgain)
{
    gen::DemoZoneSource first, again;
    gen::load_or_make_demo_zone(params_, dir_.string(), &first);
    ASSERT_TRUE(first.cached);
    fs::resize_file(first.cache_path, fs::file_size(first.cache_path) / 2); // an interrupted copy
    const Zone zone = gen::load_or_make_demo_zone(params_, dir_.string(), &again);
    EXPECT_FALSE(again.from_cache);
    EXPECT_TRUE(again.cached);
    EXPECT_NE(again.problem.find(first.cache_path), std::string::npos) << again.problem; // names the file
    ASSERT_TRUE(zone.baked_pvs.has_value());
    gen::DemoZoneSource third;
    gen::load_or_make_demo_zone(params_, dir_.string(), &third);
    EXPECT_TRUE(third.from_cache) << third.problem;

    std::ofstream(first.cache_path, std::ios::binary | std::ios::trunc) << "not an archive";
    gen::DemoZoneSource garbage;
    gen::load_or_make_demo_zone(params_, dir_.string(), &garbage);
    EXPECT_FALSE(garbage.from_cache);
    EXPECT_TRUE(garbage.cached);
}

TEST_F(DemoCache, ACacheDirectoryThatCannotBeMadeStillGivesTheZone)
{
    fs::create_directories(dir_);
    std::ofstream(dir_ / "a_file") << "x"; // a directory cannot be made below a file, even as root
    gen::DemoZoneSource source;
    const Zone zone = gen::load_or_make_demo_zone(params_, (dir_ / "a_file" / "pvscope").string(), &source);
    EXPECT_FALSE(source.cached);
    EXPECT_FALSE(source.problem.empty());
    EXPECT_TRUE(zone.baked_pvs.has_value());
    EXPECT_TRUE(has_note(zone, "not cached"));

    gen::DemoZoneSource none;
    const Zone uncached = gen::load_or_make_demo_zone(params_, "", &none);
    EXPECT_TRUE(none.cache_path.empty());
    EXPECT_TRUE(uncached.baked_pvs.has_value());
}

TEST(DemoCacheDir, FollowsXdgCacheHomeThenHome)
{
    const char* old_xdg = std::getenv("XDG_CACHE_HOME");
    const std::string saved_xdg = old_xdg ? old_xdg : "";
    setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
    EXPECT_EQ(gen::default_demo_cache_dir(), "/tmp/xdg/pvscope");
    unsetenv("XDG_CACHE_HOME");
    if (const char* home = std::getenv("HOME")) {
        EXPECT_EQ(gen::default_demo_cache_dir(), (fs::path(home) / ".cache" / "pvscope").string());
    }
    if (old_xdg)
        setenv("XDG_CACHE_HOME", saved_xdg.c_str(), 1);
}

} // namespace
} // namespace pvs
