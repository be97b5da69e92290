// `pvscope bake` through its command function (app/cmd_bake.h), no subprocess:
//  - visdemo's example.bsp (made elsewhere) baked portal-full -> OUT.bsp: the PVS read back from
//    OUT equals bake_portal_vis on the portals built from the same tree; the report's numbers
//    agree with an independent count over OUT's and the original file's rows; the PRT written
//    reads back as the portals used; --prt example.prt bakes from qbsp's portals;
//  - an EverQuest .s3d (a small generated zone written by write_eq_zone) -> OUT.s3d with the
//    baked VISLISTs;
//  - bad arguments, a portal file of another map and a cancelled bake: a clear message, the
//    documented exit code, and no output file.
#include "app/cmd_bake.h"

#include "tests/app/bake_command_fixture.h"

#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/portal/portal_vis.h"
#include "visibility/portal/portalize.h"
#include "wld/common/read_file.h"
#include "wld/convert.h"
#include "wld/pvs_edit_list.h"
#include "wld/quake/ambient_sounds.h"
#include "wld/quake/bsp29_reader.h"
#include "wld/quake/prt_file.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <bit>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <utility>

namespace pvs {
namespace {

namespace fs = std::filesystem;
using test::Rows;

using test::rows_of;

using test::read_text;

class Bake : public test::BakeCommand {
protected:
    // Bakes `input` twice with two threads and a report: as given ("with.bsp", "with.json") and
    // with `switch_off` applied ("without.bsp", "without.json"). Returns the two option sets.
    std::pair<app::BakeOptions, app::BakeOptions> bake_with_and_without(const std::string& input,
                                                                        void (*switch_off)(app::BakeOptions&))
    {
        app::BakeOptions with;
        with.input = input;
        with.threads = 2;
        with.output = path("with.bsp");
        with.report = path("with.json");
        EXPECT_EQ(run(with), 0) << err_;
        app::BakeOptions without = with;
        switch_off(without);
        without.output = path("without.bsp");
        without.report = path("without.json");
        EXPECT_EQ(run(without), 0) << err_;
        return {with, without};
    }
};

Pvs bake_directly(const PortalSet& portals, uint32_t regions, VisParams::Method method)
{
    VisParams params;
    params.method = method;
    params.threads = 2;
    return bake_portal_vis(portals, regions, params);
}

TEST_F(Bake, VisdemoEndToEndGivesTheBakersPvsAndAConsistentReport)
{
    SHARED_DATA_OR_SKIP(input, "visdemo/example.bsp");
    app::BakeOptions o;
    o.input = input;
    o.output = path("out.bsp");
    o.method = "portal-full";
    o.threads = 2;
    o.report = path("report.json");
    o.prt_out = path("used.prt");
    ASSERT_EQ(run(o), 0) << err_;

    const std::vector<uint8_t> original_bytes = test::read_bytes(input);
    const Zone original = quake::load_bsp29(original_bytes, input);
    const Zone out = quake::load_bsp29(test::read_bytes(o.output), o.output);
    ASSERT_TRUE(out.baked_pvs.has_value());
    const PortalSet portals = build_zone_portals(original);
    const Pvs expected = bake_directly(portals, uint32_t(original.region_count()), VisParams::Method::Full);
    EXPECT_EQ(rows_of(*out.baked_pvs), rows_of(expected));
    EXPECT_NE(err_.find("bake: 100%"), std::string::npos) << err_; // not a terminal: percentage lines

    // The report, against counts made here from the two files' rows.
    const nlohmann::json report = nlohmann::json::parse(read_text(o.report));
    for (const char* field : {"time_seconds", "base_seconds", "peak_memory_estimate_bytes", "peak_rss_bytes", "portals",
                              "portals_skipped", "regions", "mean_visible", "file_pvs", "method", "threads"})
        EXPECT_TRUE(report.contains(field)) << field;
    EXPECT_EQ(report["regions"], original.region_count());
    EXPECT_EQ(report["portals"], portals.portals.size());
    EXPECT_EQ(report["portals_skipped"], 0);
    EXPECT_EQ(report["method"], "portal-full");
    EXPECT_EQ(report["level"], 4);
    EXPECT_EQ(report["portal_source"], "tree");
    EXPECT_GE(report["time_seconds"].get<double>(), report["base_seconds"].get<double>());
    EXPECT_GT(report["peak_rss_bytes"].get<size_t>(), 1000000u);
    EXPECT_GT(report["peak_memory_estimate_bytes"].get<size_t>(), 0u);
    const Rows ours = rows_of(*out.baked_pvs), file = rows_of(*original.baked_pvs);
    size_t ours_total = 0, file_total = 0, only_ours = 0, only_file = 0;
    for (size_t r = 0; r < ours.size(); ++r) {
        ours_total += bits::count(ours[r]);
        file_total += bits::count(file[r]);
        for (size_t w = 0; w < ours[r].size(); ++w) {
            only_ours += size_t(std::popcount(ours[r][w] & ~file[r][w]));
            only_file += size_t(std::popcount(file[r][w] & ~ours[r][w]));
        }
    }
    const double n = double(ours.size());
    EXPECT_DOUBLE_EQ(report["mean_visible"].get<double>(), double(ours_total) / n);
    EXPECT_DOUBLE_EQ(report["file_pvs"]["mean_visible_baked"].get<double>(), double(ours_total) / n);
    EXPECT_DOUBLE_EQ(report["file_pvs"]["mean_visible_file"].get<double>(), double(file_total) / n);
    EXPECT_EQ(report["file_pvs"]["bits_only_baked"], only_ours);
    EXPECT_EQ(report["file_pvs"]["bits_only_file"], only_file);

    // The portals written are the ones used, in PRT1 numbering (leaf k = region k).
    const quake::PrtFile written = quake::load_prt(o.prt_out);
    EXPECT_EQ(written.leaf_count, original.region_count());
    EXPECT_EQ(written.portals.portals.size(), portals.portals.size());
    EXPECT_EQ(written.portals.points, portals.points);
}

TEST_F(Bake, PortalsFromAPrtFileAreTheOnesBaked)
{
    SHARED_DATA_OR_SKIP(input, "visdemo/example.bsp");
    SHARED_DATA_OR_SKIP(prt, "visdemo/example.prt");
    app::BakeOptions o;
    o.input = input;
    o.output = path("out.bsp");
    o.method = "portal-fast";
    o.prt_in = prt;
    o.report = path("report.json");
    ASSERT_EQ(run(o), 0) << err_;
    const Zone out = quake::load_bsp29(test::read_bytes(o.output), o.output);
    const quake::PrtFile file = quake::load_prt(prt);
    const Pvs expected = bake_directly(file.portals, file.leaf_count, VisParams::Method::Fast);
    ASSERT_TRUE(out.baked_pvs.has_value());
    EXPECT_EQ(rows_of(*out.baked_pvs), rows_of(expected));
    const nlohmann::json report = nlohmann::json::parse(read_text(o.report));
    EXPECT_EQ(report["portal_source"], prt);
    EXPECT_EQ(report["portals"], file.portals.portals.size());
    EXPECT_TRUE(report["level"].is_null()); // portal-fast has no level
    EXPECT_FALSE(report.contains("leaks"));
}

// --passages false runs the flow without passages: the report says none were built, and the
// rows hold every bit of the rows with them (passages only cut walks; with the symmetry prune
// riding on other portals' rows, a few bits may differ, always as bits the passages removed).
TEST_F(Bake, PassagesOffOnlyEverAddsBits)
{
    SHARED_DATA_OR_SKIP(input, "quake/end.bsp");
    const auto [o, off] = bake_with_and_without(input, [](app::BakeOptions& b) { b.passages = false; });
    EXPECT_GT(nlohmann::json::parse(read_text(o.report))["passage_pairs"].get<size_t>(), 0u);
    EXPECT_EQ(nlohmann::json::parse(read_text(off.report))["passage_pairs"].get<size_t>(), 0u);
    const Zone with = quake::load_bsp29(test::read_bytes(o.output), o.output);
    const Zone without = quake::load_bsp29(test::read_bytes(off.output), off.output);
    ASSERT_TRUE(with.baked_pvs.has_value() && without.baked_pvs.has_value());
    const Rows a = rows_of(*with.baked_pvs), b = rows_of(*without.baked_pvs);
    ASSERT_EQ(a.size(), b.size());
    size_t differing = 0, total = 0;
    for (size_t r = 0; r < a.size(); ++r)
        for (size_t w = 0; w < a[r].size(); ++w) {
            EXPECT_EQ(a[r][w] & ~b[r][w], 0u) << "leaf " << r << " sees more with passages";
            differing += size_t(std::popcount(a[r][w] ^ b[r][w]));
            total += size_t(std::popcount(a[r][w]));
        }
    EXPECT_LE(differing * 1000, total) << "at most 0.1 % of the bits";
}

TEST_F(Bake, TargetChecksCanBeSwitchedOffAndOnlyEverRemoveBits)
{
    SHARED_DATA_OR_SKIP(input, "quake/end.bsp");
    const auto [o, off] = bake_with_and_without(input, [](app::BakeOptions& b) { b.target_checks = false; });
    EXPECT_GT(nlohmann::json::parse(read_text(o.report))["target_checks"].get<size_t>(), 0u);
    EXPECT_EQ(nlohmann::json::parse(read_text(off.report))["target_checks"].get<size_t>(), 0u);
    const Zone with = quake::load_bsp29(test::read_bytes(o.output), o.output);
    const Zone without = quake::load_bsp29(test::read_bytes(off.output), off.output);
    ASSERT_TRUE(with.baked_pvs.has_value() && without.baked_pvs.has_value());
    const Rows a = rows_of(*with.baked_pvs), b = rows_of(*without.baked_pvs);
    ASSERT_EQ(a.size(), b.size());
    for (size_t r = 0; r < a.size(); ++r)
        for (size_t w = 0; w < a[r].size(); ++w)
            EXPECT_EQ(a[r][w] & ~b[r][w], 0u) << "leaf " << r << " sees more with target checks";
}

TEST_F(Bake, AnEverQuestZoneGetsTheBakedRowsAsVislists)
{
    app::BakeOptions o = bake_generated({8, 5, 32.0f}, "baked.s3d");
    o.method = "portal-full";
    ASSERT_EQ(run(o), 0) << err_;

    const Zone in = test::load_s3d(o.input);
    const Zone out = test::load_s3d(o.output);
    ASSERT_TRUE(out.baked_pvs.has_value());
    const Pvs expected = bake_directly(build_zone_portals(in), uint32_t(in.region_count()), VisParams::Method::Full);
    // The writer stores each row with the region's own bit set (the baker's rows already have it).
    EXPECT_EQ(rows_of(*out.baked_pvs), rows_of(expected));
    EXPECT_EQ(out.region_count(), in.region_count());
}

TEST_F(Bake, BadArgumentsAreRefusedWithAMessageAndNothingIsWritten)
{
    SHARED_DATA_OR_SKIP(input, "visdemo/example.bsp");
    app::BakeOptions o;
    o.input = input;
    o.output = path("out.s3d"); // a .bsp is written back as a .bsp
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find("must end in .bsp"), std::string::npos) << err_;
    EXPECT_FALSE(fs::exists(o.output));

    o.output = path("out.bsp");
    o.method = "portal-medium";
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find("--method must be portal-fast, portal-full, clustered, reference or raster"), std::string::npos) << err_;

    o.method = "portal-full";
    o.level = 7;
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find("--level must be 0..4"), std::string::npos) << err_;

    o.level = 4;
    o.output.clear();
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find("no output file"), std::string::npos) << err_;

    o.output = path("out.bsp");
    o.input = path("missing.bsp");
    EXPECT_EQ(run(o), 1);
    EXPECT_NE(err_.find("missing.bsp"), std::string::npos) << err_;

    o.input = input; // a text file is no zone
    const std::string text = path("notes.txt");
    std::ofstream(text) << "hello";
    o.input = text;
    EXPECT_EQ(run(o), 1);
    EXPECT_NE(err_.find("unknown file format"), std::string::npos) << err_;
    EXPECT_FALSE(fs::exists(o.output));

    // A file to be written into a folder that is not there, or an edit list that is not there:
    // refused before the bake (they once failed after it, the map already written).
    o.input = input;
    o.report = path("no-such-folder/report.json");
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find("no folder"), std::string::npos) << err_;
    o.report.clear();
    o.prt_out = path("no-such-folder/out.prt");
    EXPECT_EQ(run(o), 2);
    o.prt_out.clear();
    o.apply_edits = path("no-such-edits.json");
    EXPECT_EQ(run(o), 2);
    EXPECT_NE(err_.find("no such file"), std::string::npos) << err_;
    EXPECT_FALSE(fs::exists(o.output));
}

TEST_F(Bake, AZoneWithNoPortalsIsBakedWithWarnings)
{
    // One region, one leaf, no node: no portal, and the leaf reaches the world box (a leak).
    Zone zone;
    zone.regions.resize(1);
    zone.regions[0].bounds = {{0, 0, 0}, {64, 64, 64}};
    zone.tree.leaf_region = {0};
    zone.tree.root = ~0;
    zone.tree.tie_rule = TieRule::OnPlaneGoesFront;
    zone.region_face_offsets = {0, 0};
    const std::string input = path("one.s3d");
    write_zone(zone, input, ZoneOutput::S3d);
    app::BakeOptions o;
    o.input = input;
    o.output = path("one-baked.s3d");
    ASSERT_EQ(run(o), 0) << err_;
    EXPECT_NE(err_.find("has no portals: every region will see only itself"), std::string::npos) << err_;
    EXPECT_NE(err_.find("leaks: 1 open leaves touch the world box"), std::string::npos) << err_;
    const Zone out = test::load_s3d(o.output);
    ASSERT_TRUE(out.baked_pvs.has_value());
    ASSERT_EQ(out.baked_pvs->region_count(), 1u);
    EXPECT_TRUE(out.baked_pvs->visible(0, 0));
}

TEST_F(Bake, APortalFileOfAnotherMapIsRefused)
{
    SHARED_DATA_OR_SKIP(input, "visdemo/example.bsp");
    const std::string prt = path("other.prt");
    std::ofstream(prt) << "PRT1\n3\n1\n4 0 1 (0 0 0 ) (0 1 0 ) (0 1 1 ) (0 0 1 )\n";
    app::BakeOptions o;
    o.input = input;
    o.output = path("out.bsp");
    o.prt_in = prt;
    EXPECT_EQ(run(o), 1);
    EXPECT_NE(err_.find("portal file names 3 leaves"), std::string::npos) << err_;
    EXPECT_FALSE(fs::exists(o.output));
}

TEST_F(Bake, ACancelledBakeWritesNothing)
{
    SHARED_DATA_OR_SKIP(input, "visdemo/example.bsp");
    app::BakeOptions o;
    o.input = input;
    o.output = path("out.bsp");
    o.report = path("report.json");
    o.prt_out = path("out.prt");
    const std::atomic<bool> cancel{true}; // as if Ctrl-C came before the first progress call
    EXPECT_EQ(run(o, &cancel), 130);
    EXPECT_NE(err_.find("cancelled: nothing was written"), std::string::npos) << err_;
    EXPECT_FALSE(fs::exists(o.output));
    EXPECT_FALSE(fs::exists(o.report));
    EXPECT_FALSE(fs::exists(o.prt_out));
}

} // namespace
} // namespace pvs

namespace pvs::test {
namespace {

// `bake --method reference`: a lower bound within the portal-full bake of the same zone, and it
// says that it can pop.
TEST_F(BakeCommand, ReferenceIsALowerBoundOfPortalFullAndWarns)
{
    app::BakeOptions full = bake_generated({15, 4}, "full.s3d");
    ASSERT_EQ(run(full), 0) << err_;
    app::BakeOptions reference = full;
    reference.output = path("reference.s3d");
    reference.method = "reference";
    reference.samples = 128;
    ASSERT_EQ(run(reference), 0) << err_;
    EXPECT_NE(err_.find("lower bound"), std::string::npos) << err_;
    EXPECT_NE(err_.find(" eyes per region"), std::string::npos) << "the rounds are reported: " << err_;
    const Rows full_rows = rows_of(*load_s3d(full.output).baked_pvs);
    const Rows reference_rows = rows_of(*load_s3d(reference.output).baked_pvs);
    ASSERT_EQ(full_rows.size(), reference_rows.size());
    size_t reference_bits = 0;
    for (size_t r = 0; r < full_rows.size(); ++r)
        for (size_t w = 0; w < full_rows[r].size(); ++w) {
            EXPECT_EQ(reference_rows[r][w] & ~full_rows[r][w], 0u) << "row " << r;
            reference_bits += size_t(std::popcount(reference_rows[r][w]));
        }
    EXPECT_GT(reference_bits, full_rows.size()) << "more than each region seeing itself";

    reference.prt_in = path("none.prt");
    EXPECT_EQ(run(reference), 2) << "--prt does not apply to the reference";
}

} // namespace
} // namespace pvs::test

namespace pvs::test {
namespace {

// --apply-edits: an edit list (as the inspector saves it) applied to a fresh bake before it is
// written: the hidden pair is hidden in the file, the forced one visible, the rest the bake's.
TEST_F(BakeCommand, ApplyEditsAfterTheBake)
{
    gen::GenParams generation;
    generation.rooms = 12;
    generation.seed = 5;
    app::BakeOptions o = bake_generated(generation, "plain.s3d");
    ASSERT_EQ(run(o), 0) << err_;
    const Zone plain = load_s3d(o.output);
    ASSERT_TRUE(plain.baked_pvs);
    const uint32_t n = uint32_t(plain.region_count());
    uint32_t seen = 1, unseen = 0;
    while (seen < n && !plain.baked_pvs->visible(0, seen))
        ++seen;
    while (unseen < n && plain.baked_pvs->visible(0, unseen))
        ++unseen;
    ASSERT_LT(seen, n);
    ASSERT_LT(unseen, n);
    const std::string list = path("edits.json");
    const std::string json = edit_list_json({pair_edit(0, seen, false, false), pair_edit(0, unseen, true, false)}, n, n);
    write_whole_file(list, std::vector<uint8_t>(json.begin(), json.end()));
    o.output = path("edited.s3d");
    o.apply_edits = list;
    ASSERT_EQ(run(o), 0) << err_;
    EXPECT_NE(err_.find("applied 2 edits"), std::string::npos) << err_;
    const Zone edited = load_s3d(o.output);
    EXPECT_FALSE(edited.baked_pvs->visible(0, seen));
    EXPECT_TRUE(edited.baked_pvs->visible(0, unseen));
    size_t other_differences = 0;
    for (uint32_t r = 0; r < n; ++r)
        for (uint32_t c = 0; c < n; ++c)
            if (!(r == 0 && (c == seen || c == unseen)))
                other_differences += edited.baked_pvs->visible(r, c) != plain.baked_pvs->visible(r, c);
    EXPECT_EQ(other_differences, 0u);
    // The summary and the report give what was written, not the bake before the edits.
    o.report = path("edited.json");
    o.output = path("edited-again.s3d");
    ASSERT_EQ(run(o), 0) << err_;
    const nlohmann::json report = nlohmann::json::parse(std::ifstream(o.report));
    EXPECT_EQ(report["edits_applied"], 2);
    size_t bits = 0;
    for (uint32_t r = 0; r < n; ++r)
        for (uint32_t c = 0; c < n; ++c)
            bits += edited.baked_pvs->visible(r, c);
    EXPECT_DOUBLE_EQ(report["mean_visible"].get<double>(), double(bits) / n);
}

} // namespace
} // namespace pvs::test

namespace pvs::test {
namespace {

// A Quake map baked as vis bakes it gets ambient sound levels from its new rows (the same code as
// `--ambient-only` would run: computed from the written file's own PVS they come out the same),
// and --no-ambient keeps what qbsp wrote (zeros).
TEST_F(BakeCommand, QuakeBakeWritesAmbientLevelsUnlessTold)
{
    SHARED_DATA_OR_SKIP(map, "modern-quake/q1/lqdm2.bsp");
    SHARED_DATA_OR_SKIP(prt, "modern-quake/q1/lqdm2.prt");
    app::BakeOptions o;
    o.input = map;
    o.prt_in = prt;
    o.output = path("vised.bsp");
    o.threads = 2;
    ASSERT_EQ(run(o), 0) << err_;
    EXPECT_NE(err_.find("ambient sounds on"), std::string::npos) << err_;
    const std::vector<uint8_t> written = read_bytes(o.output);
    const Zone vised = load_zone(o.output);
    const std::vector<quake::AmbientLevels> levels = quake::read_ambient_levels(written, o.output);
    EXPECT_EQ(levels, quake::compute_ambient_levels(written, *vised.baked_pvs, {}, o.output));
    size_t with_sky = 0;
    for (const quake::AmbientLevels& l : levels)
        with_sky += l[quake::kAmbientSky] == 255;
    EXPECT_GT(with_sky, levels.size() / 3) << "lqdm2 is open to the sky";

    o.ambient = false;
    o.output = path("kept.bsp");
    ASSERT_EQ(run(o), 0) << err_;
    for (const quake::AmbientLevels& l : quake::read_ambient_levels(read_bytes(o.output), o.output))
        ASSERT_EQ(l, (quake::AmbientLevels{0, 0, 0, 0})) << "qbsp writes no levels";
}

} // namespace
} // namespace pvs::test
