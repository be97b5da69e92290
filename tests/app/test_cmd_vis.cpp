// `pvscope vis` as a build script calls it, on copies of ericw's lqdm2 (../shared/data/modern-quake):
// in place with the .prt beside the map, ericw's one-dash spellings, --ambient-only restoring
// ericw's own bytes, the -noambient* switches, an interrupted run and bad options leaving the map
// untouched, and BSP2 kept BSP2. Quake 2 maps (modern-quake/q2): PVS and PHS over clusters from
// the PRT1 beside the map, every other lump unchanged, --phs-only with ericw's rule rebuilding
// ericw's own PHS, and the errors that leave the map as it was.
#include "app/cmd_bake.h"
#include "app/cmd_vis.h"

#include "tests/app/bake_command_fixture.h"
#include "wld/common/read_file.h"
#include "wld/quake/ambient_sounds.h"
#include "wld/quake2/ibsp38_file.h"
#include "wld/quake2/phs.h"
#include "wld/zone_file.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <filesystem>
#include <fstream>

namespace pvs::test {
namespace {

namespace fs = std::filesystem;

class VisCommand : public BakeCommand {
protected:
    // Copies shared files into the scratch folder; returns the copy of the first.
    std::string copy(std::initializer_list<const char*> relatives)
    {
        std::string first;
        for (const char* relative : relatives) {
            const auto found = find_shared_data(relative);
            if (!found)
                return {};
            const std::string to = path(fs::path(relative).filename().string());
            fs::copy_file(*found, to, fs::copy_options::overwrite_existing);
            fs::permissions(to, fs::perms::owner_write, fs::perm_options::add);
            if (first.empty())
                first = to;
        }
        return first;
    }
    // Runs `pvscope ARGS` through the same parser and spellings as the binary.
    int vis_cli(const std::vector<std::string>& args)
    {
        CLI::App app;
        int code = -1;
        app::register_vis_command(app, code);
        std::vector<std::string> a = app::normalize_vis_arguments(args);
        std::reverse(a.begin(), a.end());
        try {
            app.parse(a);
        } catch (const CLI::ParseError&) {
            return -2;
        }
        return code;
    }
    size_t files_in_scratch() const
    {
        return size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}));
    }
};

TEST(VisArguments, OneDashLongOptionsBecomeTwoAfterVis)
{
    EXPECT_EQ(app::normalize_vis_arguments({"vis", "-threads", "2", "-noambientsky", "-v", "--fast", "map"}),
              (std::vector<std::string>{"vis", "--threads", "2", "--noambientsky", "-v", "--fast", "map"}));
    EXPECT_EQ(app::normalize_vis_arguments({"bake", "-o", "x.bsp", "-threads"}),
              (std::vector<std::string>{"bake", "-o", "x.bsp", "-threads"}))
        << "only vis's arguments";
}

TEST_F(VisCommand, WritesThePvsAndAmbientInPlaceAsBakeWould)
{
    SHARED_DATA_OR_SKIP(source, "modern-quake/q1/lqdm2.bsp");
    const std::string map = copy({"modern-quake/q1/lqdm2.bsp", "modern-quake/q1/lqdm2.prt"});
    ASSERT_FALSE(map.empty());
    app::BakeOptions bake;
    bake.input = map;
    bake.prt_in = path("lqdm2.prt");
    bake.output = path("baked.bsp");
    bake.threads = 2;
    ASSERT_EQ(run(bake), 0) << err_;
    const size_t files = files_in_scratch();
    ASSERT_EQ(vis_cli({"vis", "-threads", "2", "-level", "4", "-nostate", path("lqdm2")}), 0);
    EXPECT_EQ(read_bytes(map), read_bytes(bake.output)) << "vis in place writes what bake -o writes";
    EXPECT_EQ(files_in_scratch(), files) << "no temporary file left";
    size_t with_sound = 0;
    for (const quake::AmbientLevels& l : quake::read_ambient_levels(read_bytes(map), map))
        with_sound += l != quake::AmbientLevels{0, 0, 0, 0};
    EXPECT_EQ(with_sound, 452u) << "the leaves ericw's vis gives a level to (the shared README)";
}

TEST_F(VisCommand, AmbientOnlyRestoresEricwsBytesAndTheSwitchesClearTheirClass)
{
    SHARED_DATA_OR_SKIP(source, "modern-quake/q1/lqdm5.ericw-vis.bsp");
    const std::string map = copy({"modern-quake/q1/lqdm5.ericw-vis.bsp"});
    ASSERT_FALSE(map.empty());
    const std::vector<uint8_t> ericw = read_bytes(map);
    const auto silent = std::vector<quake::AmbientLevels>(quake::read_ambient_levels(ericw, map).size(),
                                                          quake::AmbientLevels{0, 0, 0, 0});
    write_whole_file(map, quake::with_ambient_levels(ericw, silent, map));
    ASSERT_NE(read_bytes(map), ericw);
    ASSERT_EQ(vis_cli({"vis", "--ambient-only", map}), 0);
    EXPECT_EQ(read_bytes(map), ericw) << "every byte of ericw's file back";

    const auto count = [&](uint32_t channel) {
        size_t n = 0;
        for (const quake::AmbientLevels& l : quake::read_ambient_levels(read_bytes(map), map))
            n += l[channel] != 0;
        return n;
    };
    const size_t water = count(quake::kAmbientWater), sky = count(quake::kAmbientSky);
    ASSERT_GT(water, 0u);
    ASSERT_GT(sky, 0u);
    ASSERT_EQ(vis_cli({"vis", "-ambient-only", "-noambientsky", map}), 0);
    EXPECT_EQ(count(quake::kAmbientSky), 0u);
    EXPECT_EQ(count(quake::kAmbientWater), water);
    ASSERT_EQ(vis_cli({"vis", "-ambient-only", "-noambientwater", "-noambientslime", map}), 0);
    EXPECT_EQ(count(quake::kAmbientWater), 0u);
    EXPECT_EQ(count(quake::kAmbientSky), sky);
    ASSERT_EQ(vis_cli({"vis", "-ambient-only", "-noambient", map}), 0);
    EXPECT_EQ(count(quake::kAmbientWater) + count(quake::kAmbientSky), 0u);
}

TEST_F(VisCommand, AnInterruptedRunOrABadOptionLeavesTheMapAsItWas)
{
    SHARED_DATA_OR_SKIP(source, "modern-quake/q1/lqdm2.bsp");
    const std::string map = copy({"modern-quake/q1/lqdm2.bsp", "modern-quake/q1/lqdm2.prt"});
    ASSERT_FALSE(map.empty());
    const std::vector<uint8_t> before = read_bytes(map);
    const size_t files = files_in_scratch();
    app::VisCommandOptions o;
    o.map = map;
    o.threads = 1;
    const std::atomic<bool> interrupted{true}; // Ctrl-C as the bake starts
    std::FILE* err = std::tmpfile();
    EXPECT_EQ(app::run_vis_command(o, err, &interrupted), 130);
    const std::string said = read_and_close(err);
    EXPECT_NE(said.find("left as it was"), std::string::npos) << said;
    EXPECT_EQ(read_bytes(map), before);
    EXPECT_EQ(files_in_scratch(), files) << "no temporary file left";

    EXPECT_EQ(vis_cli({"vis", "-notanoption", map}), -2);
    EXPECT_EQ(vis_cli({"vis", "-visdist", "512", map}), 2);
    fs::remove(path("lqdm2.prt"));
    EXPECT_EQ(vis_cli({"vis", map}), 1) << "no .prt beside the map";
    EXPECT_EQ(read_bytes(map), before);
}

// Without a .prt, --portals tree builds the portals from the BSP tree (the visdemo map: its rows
// are the hand-derived ones the portal-vis tests check).
TEST_F(VisCommand, PortalsFromTheTreeWithoutAPrt)
{
    SHARED_DATA_OR_SKIP(source, "visdemo/example.bsp");
    const std::string map = copy({"visdemo/example.bsp"});
    const Zone before = load_zone(map);
    const std::vector<uint8_t> original = read_bytes(map);
    EXPECT_EQ(vis_cli({"vis", map}), 1) << "no .prt beside it";
    EXPECT_EQ(read_bytes(map), original);
    ASSERT_EQ(vis_cli({"vis", "--portals", "tree", "-threads", "1", map}), 0);
    const Zone after = load_zone(map);
    ASSERT_TRUE(after.baked_pvs.has_value());
    ASSERT_EQ(after.region_count(), before.region_count());
    size_t bits = 0;
    for (uint32_t r = 0; r < after.region_count(); ++r)
        for (uint32_t c = 0; c < after.region_count(); ++c)
            bits += after.baked_pvs->visible(r, c);
    EXPECT_GT(bits, after.region_count()) << "regions see more than themselves";
    EXPECT_LT(bits, after.region_count() * after.region_count()) << "and not everything";
}

TEST_F(VisCommand, Bsp2StaysBsp2)
{
    SHARED_DATA_OR_SKIP(source, "modern-quake/q1/lqdm2-bsp2.bsp");
    const std::string map = copy({"modern-quake/q1/lqdm2-bsp2.bsp", "modern-quake/q1/lqdm2-bsp2.prt"});
    ASSERT_FALSE(map.empty());
    const std::string report = path("report.json");
    ASSERT_EQ(vis_cli({"vis", "-threads", "2", "--report", report, map}), 0);
    const std::vector<uint8_t> bytes = read_bytes(map);
    EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 4), "BSP2");
    const Zone zone = load_zone(map);
    ASSERT_TRUE(zone.baked_pvs.has_value());
    EXPECT_EQ(zone.source.version, "BSP2");
    // The report names the variant and the map written, not the temporary file beside it.
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(report));
    EXPECT_EQ(j["format"], "Quake BSP2");
    EXPECT_EQ(j["output"], map);
}

// Quake 2: the unvised maps vised from their .prt beside them get ericw's cluster counts and a PVS
// the same as ericw vis's on the two maps without t-junction noise; the PHS is Quake 2's rule of
// that PVS (recomputed here); every lump but the visibility lump is byte for byte the input's.
// Every lump of a Quake 2 map but the visibility lump has the same bytes after as before.
void expect_other_lumps_kept(const std::vector<uint8_t>& before, const quake2::Ibsp38File& in,
                             const std::vector<uint8_t>& after, const quake2::Ibsp38File& out, const char* name)
{
    for (int lump = 0; lump < quake2::kIbsp38LumpCount; ++lump) {
        if (lump == quake2::kQ2LumpVisibility)
            continue;
        const auto a = std::span(before).subspan(in.lumps[lump].offset, in.lumps[lump].length);
        const auto b = std::span(after).subspan(out.lumps[lump].offset, out.lumps[lump].length);
        EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end())) << name << " lump " << lump;
    }
}

TEST_F(VisCommand, Quake2MapsGetPvsAndPhsOverClusters)
{
    SHARED_DATA_OR_SKIP(source, "modern-quake/q2/q2_liquids.bsp");
    for (const char* name : {"q2_areaportals", "q2_liquids", "q2_tjunc_matrix"}) {
        const std::string base = std::string("modern-quake/q2/") + name;
        const std::string map = copy({(base + ".bsp").c_str(), (base + ".prt").c_str()});
        ASSERT_FALSE(map.empty());
        const std::vector<uint8_t> before = read_bytes(map);
        ASSERT_EQ(vis_cli({"vis", "-threads", "2", path(name)}), 0) << name;
        const std::vector<uint8_t> after = read_bytes(map);
        const quake2::Ibsp38File in = quake2::read_ibsp38(before, map), out = quake2::read_ibsp38(after, map);
        const std::vector<uint8_t> ericw_bytes = read_bytes(*find_shared_data(base + ".ericw-vis.bsp"));
        const quake2::Ibsp38File ericw = quake2::read_ibsp38(ericw_bytes, name);
        EXPECT_EQ(out.clusters, ericw.clusters) << name;
        EXPECT_EQ(out.phs_rows, quake2::compute_phs(out.pvs_rows, out.clusters, quake2::PhsRule::Quake2)) << name;
        if (std::string(name) != "q2_tjunc_matrix") {
            EXPECT_EQ(out.pvs_rows, ericw.pvs_rows) << name;
        }
        expect_other_lumps_kept(before, in, after, out, name);
    }
}

// --report on a Quake 2 map: the clusters and portals of the files (qbsp's .prt header, ericw's
// map), the mean of the rows written, counted here.
TEST_F(VisCommand, Quake2ReportNamesWhatWasWritten)
{
    SHARED_DATA_OR_SKIP(source, "modern-quake/q2/q2_tjunc_matrix.bsp");
    const std::string base = "modern-quake/q2/q2_tjunc_matrix";
    const std::string map = copy({(base + ".bsp").c_str(), (base + ".prt").c_str()});
    ASSERT_FALSE(map.empty());
    const std::string report = path("report.json");
    ASSERT_EQ(vis_cli({"vis", "-threads", "2", "--report", report, path("q2_tjunc_matrix")}), 0);
    const std::vector<uint8_t> text = read_bytes(report);
    const nlohmann::json j = nlohmann::json::parse(text.begin(), text.end());
    const quake2::Ibsp38File out = quake2::read_ibsp38(read_bytes(map), map);
    uint64_t bits = 0;
    for (uint64_t w : out.pvs_rows)
        bits += uint64_t(std::popcount(w));
    std::ifstream prt(*find_shared_data(base + ".prt"));
    std::string magic;
    uint64_t clusters = 0, portals = 0;
    prt >> magic >> clusters >> portals;
    EXPECT_EQ(magic, "PRT1");
    EXPECT_EQ(j.at("format"), "Quake 2 BSP (IBSP 38)");
    EXPECT_EQ(j.at("clusters"), out.clusters);
    EXPECT_EQ(j.at("clusters").get<uint64_t>(), clusters);
    EXPECT_EQ(j.at("portals").get<uint64_t>(), portals);
    EXPECT_DOUBLE_EQ(j.at("mean_visible").get<double>(), double(bits) / out.clusters);
    EXPECT_GT(j.at("time_seconds").get<double>(), 0.0);
    EXPECT_EQ(j.at("threads"), 2);
}

// --portals tree goes through bake, and its report says what the map now holds as the portal
// file's report does: the map's clusters and the clusters per cluster row of the PVS and the PHS
// written (counted here in the rows read back), and the PHS rule.
TEST_F(VisCommand, Quake2TreeReportGivesTheClustersWritten)
{
    SHARED_DATA_OR_SKIP(source, "modern-quake/q2/q2_tjunc_matrix.bsp");
    const std::string map = copy({"modern-quake/q2/q2_tjunc_matrix.bsp"});
    ASSERT_FALSE(map.empty());
    const std::string report = path("tree-report.json");
    ASSERT_EQ(vis_cli({"vis", "--portals", "tree", "-threads", "2", "--report", report, map}), 0) << err_;
    const std::vector<uint8_t> text = read_bytes(report);
    const nlohmann::json j = nlohmann::json::parse(text.begin(), text.end());
    const quake2::Ibsp38File out = quake2::read_ibsp38(read_bytes(map), map);
    ASSERT_GT(out.clusters, 0u);
    const auto bits = [](const std::vector<uint64_t>& rows) {
        uint64_t n = 0;
        for (uint64_t w : rows)
            n += uint64_t(std::popcount(w));
        return n;
    };
    EXPECT_EQ(j.at("clusters"), out.clusters);
    EXPECT_DOUBLE_EQ(j.at("mean_visible").get<double>(), double(bits(out.pvs_rows)) / out.clusters);
    EXPECT_DOUBLE_EQ(j.at("mean_hearable").get<double>(), double(bits(out.phs_rows)) / out.clusters);
    EXPECT_EQ(j.at("phs_rule"), "quake2");
    EXPECT_EQ(j.at("portal_source"), "tree");
}

// `bake` on a Quake 2 map: portals from the tree per leaf (Quake 2's content rule), the leaves'
// rows ORed per cluster. Every cluster row holds no cluster ericw's lacks (ericw's clusters see
// through detail brushes; the tree's leaves do not), the two maps without detail get ericw's rows
// exactly, the PHS is Quake 2's rule of them, and every other lump is the map's own.
TEST_F(VisCommand, Quake2BakeFromTheTreeWithinEricwsRows)
{
    SHARED_DATA_OR_SKIP(source, "modern-quake/q2/q2_liquids.bsp");
    for (const char* name : {"q2_areaportals", "q2_liquids", "q2_tjunc_matrix"}) {
        const std::string base = std::string("modern-quake/q2/") + name;
        const std::string map = copy({(base + ".bsp").c_str()});
        ASSERT_FALSE(map.empty());
        app::BakeOptions options;
        options.input = map;
        options.output = path(std::string(name) + ".baked.bsp");
        options.threads = 2;
        ASSERT_EQ(run(options), 0) << name;
        const std::vector<uint8_t> before = read_bytes(map), after = read_bytes(options.output);
        const quake2::Ibsp38File in = quake2::read_ibsp38(before, map), out = quake2::read_ibsp38(after, map);
        const quake2::Ibsp38File ericw = quake2::read_ibsp38(read_bytes(*find_shared_data(base + ".ericw-vis.bsp")), name);
        ASSERT_EQ(out.clusters, ericw.clusters) << name;
        size_t fewer = 0;
        for (size_t w = 0; w < out.pvs_rows.size(); ++w) {
            EXPECT_EQ(out.pvs_rows[w] & ~ericw.pvs_rows[w], 0u) << name << " word " << w;
            fewer += std::popcount(ericw.pvs_rows[w] & ~out.pvs_rows[w]);
        }
        if (std::string(name) == "q2_tjunc_matrix") {
            EXPECT_GT(fewer, 500u) << "per-leaf portals through its detail brushes";
        } else {
            EXPECT_EQ(out.pvs_rows, ericw.pvs_rows) << name;
        }
        EXPECT_EQ(out.phs_rows, quake2::compute_phs(out.pvs_rows, out.clusters, quake2::PhsRule::Quake2)) << name;
        expect_other_lumps_kept(before, in, after, out, name);
    }
}

// `bake --prt` on a Quake 2 map: the PRT1 names the map's clusters, not its leaves, so the bake
// runs over the clusters (each leaf in its own) and writes the file `pvscope vis` writes in place,
// byte for byte - one path expands cluster rows to leaves and ORs them back, the other writes the
// cluster rows. Another map's portal file is refused and nothing is written.
TEST_F(VisCommand, Quake2BakeWithThePortalFileWritesWhatVisWrites)
{
    SHARED_DATA_OR_SKIP(source, "modern-quake/q2/q2_liquids.bsp");
    for (const char* name : {"q2_areaportals", "q2_liquids", "q2_tjunc_matrix"}) {
        const std::string base = std::string("modern-quake/q2/") + name;
        const std::string map = copy({(base + ".bsp").c_str(), (base + ".prt").c_str()});
        ASSERT_FALSE(map.empty());
        app::BakeOptions options;
        options.input = map;
        options.prt_in = path(std::string(name) + ".prt");
        options.output = path(std::string(name) + ".baked.bsp");
        options.threads = 2;
        ASSERT_EQ(run(options), 0) << name;
        ASSERT_EQ(vis_cli({"vis", "-threads", "2", map}), 0) << name;
        EXPECT_EQ(read_bytes(options.output), read_bytes(map)) << name;
    }
    const std::string map = copy({"modern-quake/q2/q2_liquids.bsp", "modern-quake/q2/q2_areaportals.prt"});
    app::BakeOptions options;
    options.input = map;
    options.prt_in = path("q2_areaportals.prt");
    options.output = path("wrong.bsp");
    EXPECT_EQ(run(options), 1) << "8 portal-file leaves for 18 clusters";
    EXPECT_FALSE(fs::exists(options.output));
    // What --write-prt writes of a bake per leaf (PRT1 over the map's leaves) reads back per leaf.
    app::BakeOptions per_leaf;
    per_leaf.input = map;
    per_leaf.output = path("per-leaf.bsp");
    per_leaf.prt_out = path("per-leaf.prt");
    per_leaf.threads = 2;
    ASSERT_EQ(run(per_leaf), 0) << err_;
    per_leaf.prt_in = per_leaf.prt_out;
    per_leaf.prt_out.clear();
    per_leaf.output = path("per-leaf-again.bsp");
    ASSERT_EQ(run(per_leaf), 0) << err_;
    EXPECT_EQ(read_bytes(per_leaf.output), read_bytes(path("per-leaf.bsp")));
}

// vis --portals tree on a Quake 2 map: bake's per-leaf PVS from the tree (checked against ericw's
// rows above) written in place, byte for byte bake's file, with the PHS by --phs-rule.
TEST_F(VisCommand, Quake2PortalsFromTheTreeAreBakesAndKeepThePhsRule)
{
    SHARED_DATA_OR_SKIP(source, "modern-quake/q2/q2_tjunc_matrix.bsp");
    const std::string map = copy({"modern-quake/q2/q2_tjunc_matrix.bsp"});
    ASSERT_FALSE(map.empty());
    const std::vector<uint8_t> before = read_bytes(map);
    std::vector<std::vector<uint64_t>> phs;
    for (const char* rule : {"quake2", "ericw"}) {
        write_whole_file(map, before);
        ASSERT_EQ(vis_cli({"vis", "--portals", "tree", "-threads", "2", "--phs-rule", rule, map}), 0) << rule;
        app::BakeOptions options;
        options.input = source;
        options.output = path(std::string("baked-") + rule + ".bsp");
        options.threads = 2;
        options.phs_rule = rule;
        ASSERT_EQ(run(options), 0) << err_;
        EXPECT_EQ(read_bytes(map), read_bytes(options.output)) << rule;
        const quake2::Ibsp38File out = quake2::read_ibsp38(read_bytes(map), map);
        EXPECT_EQ(out.phs_rows, quake2::compute_phs(out.pvs_rows, out.clusters,
                                                    std::string(rule) == "ericw" ? quake2::PhsRule::EricwTools
                                                                                 : quake2::PhsRule::Quake2))
            << rule;
        phs.push_back(out.phs_rows);
    }
    EXPECT_NE(phs[0], phs[1]) << "96 clusters: the two rules differ, so the rule reached the writer";
}

// -phsonly with ericw's rule on ericw's own output: the PVS kept, the PHS ericw's byte for byte
// (decoded rows and their stored lengths); with Quake 2's rule the PHS holds ericw's.
TEST_F(VisCommand, Quake2PhsOnlyRebuildsEricwsPhs)
{
    SHARED_DATA_OR_SKIP(source, "modern-quake/q2/q2_tjunc_matrix.ericw-vis.bsp");
    const std::string map = copy({"modern-quake/q2/q2_tjunc_matrix.ericw-vis.bsp"});
    ASSERT_FALSE(map.empty());
    const std::vector<uint8_t> ericw_bytes = read_bytes(map);
    const quake2::Ibsp38File ericw = quake2::read_ibsp38(ericw_bytes, map);
    ASSERT_EQ(vis_cli({"vis", "-phsonly", "--phs-rule", "ericw", map}), 0);
    const quake2::Ibsp38File ours = quake2::read_ibsp38(read_bytes(map), map);
    EXPECT_EQ(ours.pvs_rows, ericw.pvs_rows);
    EXPECT_EQ(ours.phs_rows, ericw.phs_rows);
    EXPECT_EQ(ours.phs_lengths, ericw.phs_lengths);
    ASSERT_EQ(vis_cli({"vis", "--phs-only", map}), 0); // Quake 2's rule
    const quake2::Ibsp38File quake2_rule = quake2::read_ibsp38(read_bytes(map), map);
    size_t added = 0;
    for (size_t w = 0; w < ericw.phs_rows.size(); ++w) {
        EXPECT_EQ(quake2_rule.phs_rows[w] & ericw.phs_rows[w], ericw.phs_rows[w]);
        added += std::popcount(quake2_rule.phs_rows[w] & ~ericw.phs_rows[w]);
    }
    EXPECT_GT(added, 0u) << "96 clusters: the bits ericw's word loop leaves out";
}

// vis on a map that is not a Quake map (an EverQuest zone, whatever its extension): a clear error
// naming the map, nothing written beside it.
TEST_F(VisCommand, AMapThatIsNotQuakesIsRefused)
{
    const std::string zone = path("zone.bsp");
    const std::vector<uint8_t> not_quake = {'P', 'F', 'S', ' ', 0, 0, 0, 0, 1, 2, 3, 4};
    write_whole_file(zone, not_quake);
    const size_t files = files_in_scratch();
    EXPECT_EQ(vis_cli({"vis", "--portals", "tree", zone}), 1);
    EXPECT_EQ(read_bytes(zone), not_quake);
    EXPECT_EQ(files_in_scratch(), files);
}

TEST_F(VisCommand, Quake2ErrorsLeaveTheMapAsItWas)
{
    SHARED_DATA_OR_SKIP(source, "modern-quake/q2/q2_liquids.bsp");
    const std::string map = copy({"modern-quake/q2/q2_liquids.bsp", "modern-quake/q2/q2_areaportals.prt"});
    ASSERT_FALSE(map.empty());
    const std::vector<uint8_t> before = read_bytes(map);
    EXPECT_EQ(vis_cli({"vis", map}), 1) << "no q2_liquids.prt beside it";
    fs::rename(path("q2_areaportals.prt"), path("q2_liquids.prt"));
    EXPECT_EQ(vis_cli({"vis", map}), 1) << "another map's portals (8 leaves for 18 clusters)";
    EXPECT_EQ(vis_cli({"vis", "--phs-only", map}), 1) << "no PVS to make a PHS from";
    EXPECT_EQ(vis_cli({"vis", "--phs-rule", "q3", map}), -2);
    EXPECT_EQ(vis_cli({"vis", "--report", path("no-such-folder/r.json"), map}), 2) << "refused before the vis";
    EXPECT_EQ(read_bytes(map), before);
    SHARED_DATA_OR_SKIP(q1, "modern-quake/q1/lqdm2.bsp");
    const std::string quake1 = copy({"modern-quake/q1/lqdm2.bsp"});
    EXPECT_EQ(vis_cli({"vis", "--phs-only", quake1}), 2) << "a Quake map has no PHS";
}

} // namespace
} // namespace pvs::test
