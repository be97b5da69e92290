// Writing GL_PVS and REJECT into Doom GL nodes (wld/doom/gl_pvs_writer.h), on Freedoom's
// freedoom2.wad with GL nodes made elsewhere: glbsp's .gwa (an empty GL_PVS placeholder at
// marker + 5: replaced) and zdbsp's WAD (GL lumps inside the WAD, no GL_PVS: inserted after
// GL_NODES). Each write reads back row for row with decode_glvis_row; every other lump is the
// original's, byte for byte, at the same index (one up after an insertion); the backup is the
// original file. REJECT is checked against a sector-pair computation made here; files that no
// longer match the MapSource and PVSs of the wrong size are refused before anything is written.
// MapSources are built by hand from the markers (read_doom_map is not used here).
#include "wld/doom/gl_pvs_writer.h"

#include "tests/support/freedoom.h"
#include "visibility/bit_row.h"
#include "visibility/codec/glvis_rows.h"
#include "visibility/file_error.h"
#include "wld/common/read_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <optional>
#include <set>
#include <stdexcept>
#include <unistd.h>

namespace pvs::doom {
namespace {

namespace fs = std::filesystem;

// A directory of its own for each test (the originals are never written), removed afterwards.
class ScratchDir {
public:
    ScratchDir()
    {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("pvscope-glpvs-" + std::to_string(::getpid()) + "-" + test->test_suite_name() + "-" + test->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    ~ScratchDir()
    {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    std::string copy(const std::string& from, const std::string& name) const
    {
        const fs::path to = dir_ / name;
        fs::copy_file(from, to, fs::copy_options::overwrite_existing);
        return to.string();
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    std::set<std::string> names() const
    {
        std::set<std::string> found;
        for (const auto& entry : fs::directory_iterator(dir_))
            found.insert(entry.path().filename().string());
        return found;
    }

private:
    fs::path dir_;
};

uint32_t mix(uint32_t a, uint32_t b, uint32_t seed)
{
    uint32_t h = a * 2654435761u ^ (b * 40503u + seed);
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    return h ^ (h >> 15);
}

// A PVS with no structure to lean on: every subsector sees itself and about a third of the rest.
Pvs pattern_pvs(uint32_t count, uint32_t seed)
{
    return Pvs::build(count, [&](uint32_t r, std::span<uint64_t> row) {
        bits::set(row, r);
        for (uint32_t j = 0; j < count; ++j)
            if (mix(r, j, seed) % 3 == 0)
                bits::set(row, j);
        return true;
    });
}

Pvs pvs_from_rows(const std::vector<std::vector<uint32_t>>& visible)
{
    return Pvs::build(uint32_t(visible.size()), [&](uint32_t r, std::span<uint64_t> row) {
        for (uint32_t j : visible[r])
            bits::set(row, j);
        return true;
    });
}

std::vector<uint64_t> row_of(const Pvs& pvs, uint32_t r)
{
    std::vector<uint64_t> row(pvs.words_per_row());
    pvs.decode_row(r, row);
    return row;
}

// The lump decodes, row for row, to `pvs`.
void expect_gl_pvs_rows(std::span<const uint8_t> lump, const Pvs& pvs)
{
    const uint32_t n = pvs.region_count();
    ASSERT_EQ(lump.size(), glvis_lump_size(n));
    std::vector<uint64_t> decoded(bits::words_for(n));
    for (uint32_t r = 0; r < n; ++r) {
        ASSERT_EQ(decode_glvis_row(lump, n, r, decoded), GlvisRowStatus::decoded) << "row " << r;
        ASSERT_EQ(decoded, row_of(pvs, r)) << "row " << r;
    }
}

bool same_bytes(std::span<const uint8_t> a, std::span<const uint8_t> b) { return std::ranges::equal(a, b); }

// Every lump of `original` is in `written` with its name and, unless listed in `changed`
// (original indices), its bytes; at the same index, or one up from `inserted_at` on.
void expect_lumps_kept(const WadFile& original, const WadFile& written, std::optional<size_t> inserted_at,
                       const std::set<size_t>& changed)
{
    ASSERT_EQ(written.lumps.size(), original.lumps.size() + (inserted_at ? 1 : 0));
    EXPECT_EQ(written.iwad, original.iwad);
    for (size_t i = 0; i < original.lumps.size(); ++i) {
        const size_t k = inserted_at && i >= *inserted_at ? i + 1 : i;
        ASSERT_EQ(written.lumps[k].name, original.lumps[i].name) << "lump " << i;
        if (!changed.contains(i)) {
            EXPECT_TRUE(same_bytes(written.data(k), original.data(i))) << "lump " << i << " " << original.lumps[i].name;
        }
    }
}

size_t lump_index(const WadFile& file, const std::string& name, size_t from = 0)
{
    const auto found = file.find_from(name, from);
    if (!found)
        throw std::runtime_error("no lump " + name + " in " + file.path);
    return *found;
}

MapSource source_for(const WadFile& wad, const WadFile& gl, const std::string& map)
{
    MapSource source;
    source.wad_path = wad.path;
    source.map_marker = lump_index(wad, map);
    source.gl_path = gl.path;
    source.gl_marker = lump_index(gl, "GL_" + map);
    source.gl_pvs_present = source.gl_marker + 5 < gl.lumps.size() && gl.lumps[source.gl_marker + 5].name == "GL_PVS";
    return source;
}

// GL V2: GL_SSECT is 4-byte records with no magic.
uint32_t v2_subsectors(const WadFile& gl, size_t gl_marker) { return gl.lumps[gl_marker + 3].size / 4; }

uint32_t sectors_of_map(const WadFile& wad, size_t map_marker)
{
    return wad.lumps[lump_index(wad, "SECTORS", map_marker)].size / 26;
}

std::vector<uint32_t> some_sectors(uint32_t subsectors, uint32_t sectors)
{
    std::vector<uint32_t> sector(subsectors);
    for (uint32_t i = 0; i < subsectors; ++i)
        sector[i] = (i * 7 + i / 3) % sectors;
    return sector;
}

// REJECT straight from its definition: pair (a, b) is clear when some subsector of sector b is
// visible from some subsector of sector a; every other bit (padding included) is set.
std::vector<uint8_t> reject_by_sector_pairs(const Pvs& pvs, const std::vector<uint32_t>& sector, uint32_t n)
{
    std::vector<uint8_t> reject((n * n + 7) / 8, 0xFF);
    for (uint32_t a = 0; a < n; ++a)
        for (uint32_t b = 0; b < n; ++b) {
            bool seen = false;
            for (uint32_t i = 0; i < sector.size() && !seen; ++i)
                for (uint32_t j = 0; j < sector.size() && !seen; ++j)
                    seen = sector[i] == a && sector[j] == b && pvs.visible(i, j);
            if (seen)
                reject[(a * n + b) / 8] &= uint8_t(~(1u << ((a * n + b) % 8)));
        }
    return reject;
}

// --- Freedoom with glbsp's .gwa: GL_PVS replaced ---------------------------------------------

TEST(GlPvsWriter, ReplacesGlbspsPlaceholderInTheGwa)
{
    FREEDOOM_OR_SKIP(iwad, "freedoom2.wad");
    GL_NODES_OR_SKIP(made, iwad, pvs::test::GlBuilder::glbsp_v2);
    ScratchDir dir;
    const std::string gwa = dir.copy(made, "freedoom2.gwa");
    const WadFile original = read_wad(gwa);
    const MapSource source = source_for(read_wad(iwad), original, "MAP02");
    ASSERT_TRUE(source.gl_pvs_present) << "glbsp writes an empty GL_PVS after GL_NODES";
    EXPECT_EQ(original.lumps[source.gl_marker + 5].size, 0u);
    const uint32_t n = v2_subsectors(original, source.gl_marker);
    ASSERT_GT(n, 100u);
    EXPECT_EQ(gl_subsector_count(original, source.gl_marker), n);

    const Pvs pvs = pattern_pvs(n, 1);
    const GlPvsWriteResult result = write_gl_pvs(source, pvs, {}, 0);
    EXPECT_EQ(result.gl_file, gwa);
    EXPECT_FALSE(result.inserted);
    EXPECT_FALSE(result.reject_written);
    EXPECT_EQ(result.backup_file, dir.path("freedoom2.~gw"));
    EXPECT_TRUE(result.wad_backup_file.empty());
    EXPECT_TRUE(std::ranges::equal(read_whole_file(result.backup_file), original.bytes)) << "the backup is the original file";
    EXPECT_EQ(dir.names(), (std::set<std::string>{"freedoom2.gwa", "freedoom2.~gw"})) << "no temporary left behind";

    const WadFile written = read_wad(gwa);
    expect_lumps_kept(original, written, std::nullopt, {source.gl_marker + 5});
    EXPECT_EQ(written.lumps[source.gl_marker + 5].name, "GL_PVS");
    expect_gl_pvs_rows(written.data(source.gl_marker + 5), pvs);

    // Again: the older backup is replaced by the file as it was before this write.
    const Pvs again = pattern_pvs(n, 2);
    write_gl_pvs(source, again, {}, 0);
    EXPECT_TRUE(std::ranges::equal(read_whole_file(result.backup_file), written.bytes));
    expect_gl_pvs_rows(read_wad(gwa).data(source.gl_marker + 5), again);
}

// --- Freedoom rebuilt by zdbsp: GL_PVS inserted into the WAD ----------------------------------

TEST(GlPvsWriter, InsertsAfterGlNodesInZdbspsWad)
{
    FREEDOOM_OR_SKIP(iwad, "freedoom2.wad");
    GL_NODES_OR_SKIP(made, iwad, pvs::test::GlBuilder::zdbsp_v2);
    ScratchDir dir;
    const std::string wad = dir.copy(made, "freedoom2.wad");
    const WadFile original = read_wad(wad);
    const MapSource source = source_for(original, original, "MAP02");
    ASSERT_FALSE(source.gl_pvs_present) << "zdbsp writes no GL_PVS";
    const uint32_t n = v2_subsectors(original, source.gl_marker);

    const Pvs pvs = pattern_pvs(n, 3);
    const GlPvsWriteResult result = write_gl_pvs(source, pvs, {}, 0);
    EXPECT_TRUE(result.inserted);
    EXPECT_EQ(result.backup_file, dir.path("freedoom2.~wa"));
    EXPECT_TRUE(std::ranges::equal(read_whole_file(result.backup_file), original.bytes));

    const WadFile written = read_wad(wad);
    expect_lumps_kept(original, written, source.gl_marker + 5, {});
    EXPECT_EQ(written.lumps[source.gl_marker + 4].name, "GL_NODES");
    EXPECT_EQ(written.lumps[source.gl_marker + 5].name, "GL_PVS");
    expect_gl_pvs_rows(written.data(source.gl_marker + 5), pvs);

    // The same MapSource still holds (the insertion is after the group): now it is a replacement.
    const Pvs again = pattern_pvs(n, 4);
    EXPECT_FALSE(write_gl_pvs(source, again, {}, 0).inserted);
    const WadFile rewritten = read_wad(wad);
    expect_lumps_kept(written, rewritten, std::nullopt, {source.gl_marker + 5});
    expect_gl_pvs_rows(rewritten.data(source.gl_marker + 5), again);
}

TEST(GlPvsWriter, OneFileGetsBothGlPvsAndRejectInOneRewrite)
{
    FREEDOOM_OR_SKIP(iwad, "freedoom2.wad");
    GL_NODES_OR_SKIP(made, iwad, pvs::test::GlBuilder::zdbsp_v2);
    ScratchDir dir;
    const std::string wad = dir.copy(made, "freedoom2.wad");
    const WadFile original = read_wad(wad);
    const MapSource source = source_for(original, original, "MAP03");
    const uint32_t n = v2_subsectors(original, source.gl_marker);
    const uint32_t sectors = sectors_of_map(original, source.map_marker);
    const size_t reject = lump_index(original, "REJECT", source.map_marker);
    ASSERT_LT(reject, source.gl_marker);
    const std::vector<uint32_t> sector = some_sectors(n, sectors);
    const Pvs pvs = pattern_pvs(n, 5);

    GlPvsWriteOptions options;
    options.rebuild_reject = true;
    options.backup = false;
    const GlPvsWriteResult result = write_gl_pvs(source, pvs, sector, sectors, options);
    EXPECT_TRUE(result.inserted);
    EXPECT_TRUE(result.reject_written);
    EXPECT_TRUE(result.backup_file.empty());
    EXPECT_EQ(dir.names(), (std::set<std::string>{"freedoom2.wad"}));

    const WadFile written = read_wad(wad);
    expect_lumps_kept(original, written, source.gl_marker + 5, {reject});
    expect_gl_pvs_rows(written.data(source.gl_marker + 5), pvs);
    const std::vector<uint8_t> expected = reject_from_pvs(pvs, sector, sectors);
    EXPECT_EQ(expected.size(), (size_t(sectors) * sectors + 7) / 8);
    EXPECT_TRUE(same_bytes(written.data(reject), expected));
}

TEST(GlPvsWriter, RejectGoesToTheWadBesideTheGwa)
{
    FREEDOOM_OR_SKIP(iwad, "freedoom2.wad");
    GL_NODES_OR_SKIP(made, iwad, pvs::test::GlBuilder::glbsp_v2);
    ScratchDir dir;
    const std::string gwa = dir.copy(made, "freedoom2.gwa");
    const std::string wad = dir.copy(iwad, "freedoom2.wad");
    const WadFile original_gwa = read_wad(gwa);
    const WadFile original_wad = read_wad(wad);
    const MapSource source = source_for(original_wad, original_gwa, "MAP01");
    const uint32_t n = v2_subsectors(original_gwa, source.gl_marker);
    const uint32_t sectors = sectors_of_map(original_wad, source.map_marker);
    const size_t reject = lump_index(original_wad, "REJECT", source.map_marker);
    const std::vector<uint32_t> sector = some_sectors(n, sectors);
    const Pvs pvs = pattern_pvs(n, 6);

    GlPvsWriteOptions options;
    options.rebuild_reject = true;
    const GlPvsWriteResult result = write_gl_pvs(source, pvs, sector, sectors, options);
    EXPECT_FALSE(result.inserted);
    EXPECT_TRUE(result.reject_written);
    EXPECT_EQ(result.backup_file, dir.path("freedoom2.~gw"));
    EXPECT_EQ(result.wad_backup_file, dir.path("freedoom2.~wa"));
    EXPECT_TRUE(std::ranges::equal(read_whole_file(result.backup_file), original_gwa.bytes));
    EXPECT_TRUE(std::ranges::equal(read_whole_file(result.wad_backup_file), original_wad.bytes));

    const WadFile written_gwa = read_wad(gwa);
    expect_lumps_kept(original_gwa, written_gwa, std::nullopt, {source.gl_marker + 5});
    expect_gl_pvs_rows(written_gwa.data(source.gl_marker + 5), pvs);
    const WadFile written_wad = read_wad(wad);
    expect_lumps_kept(original_wad, written_wad, std::nullopt, {reject});
    EXPECT_TRUE(same_bytes(written_wad.data(reject), reject_from_pvs(pvs, sector, sectors)));
}

TEST(GlPvsWriter, GlSsectSizeGivesTheSameCountInEveryVersion)
{
    FREEDOOM_OR_SKIP(iwad, "freedoom2.wad");
    GL_NODES_OR_SKIP(v2, iwad, pvs::test::GlBuilder::glbsp_v2);
    GL_NODES_OR_SKIP(v3, iwad, pvs::test::GlBuilder::glbsp_v3);
    GL_NODES_OR_SKIP(v5, iwad, pvs::test::GlBuilder::glbsp_v5);
    const WadFile gl2 = read_wad(v2), gl3 = read_wad(v3), gl5 = read_wad(v5);
    for (const char* map : {"GL_MAP01", "GL_MAP07", "GL_MAP20"}) {
        const size_t at = lump_index(gl2, map);
        const size_t count = v2_subsectors(gl2, at);
        EXPECT_EQ(gl_subsector_count(gl3, lump_index(gl3, map)), count) << map;
        EXPECT_EQ(gl_subsector_count(gl5, lump_index(gl5, map)), count) << map;
    }
}

// --- Refusals: nothing is written -------------------------------------------------------------

TEST(GlPvsWriter, WrongSizePvsThrowsAndLeavesTheFileAlone)
{
    FREEDOOM_OR_SKIP(iwad, "freedoom2.wad");
    GL_NODES_OR_SKIP(made, iwad, pvs::test::GlBuilder::zdbsp_v2);
    ScratchDir dir;
    const std::string wad = dir.copy(made, "freedoom2.wad");
    const WadFile original = read_wad(wad);
    const MapSource source = source_for(original, original, "MAP01");
    const uint32_t n = v2_subsectors(original, source.gl_marker);
    const uint32_t sectors = sectors_of_map(original, source.map_marker);
    GlPvsWriteOptions reject;
    reject.rebuild_reject = true;

    EXPECT_THROW(write_gl_pvs(source, pattern_pvs(n + 1, 7), {}, 0), std::invalid_argument);
    EXPECT_THROW(write_gl_pvs(source, pattern_pvs(n - 1, 7), {}, 0), std::invalid_argument);
    const Pvs not_square = Pvs::build_rows(n + 3, n, [](uint32_t, std::span<uint64_t>) { return true; });
    EXPECT_THROW(write_gl_pvs(source, not_square, {}, 0), std::invalid_argument);
    const Pvs pvs = pattern_pvs(n, 7);
    const std::vector<uint32_t> too_few(n - 1, 0);
    EXPECT_THROW(write_gl_pvs(source, pvs, too_few, sectors, reject), std::invalid_argument);
    std::vector<uint32_t> past_the_end = some_sectors(n, sectors);
    past_the_end[n / 2] = sectors;
    EXPECT_THROW(write_gl_pvs(source, pvs, past_the_end, sectors, reject), std::invalid_argument);

    EXPECT_TRUE(std::ranges::equal(read_whole_file(wad), original.bytes));
    EXPECT_EQ(dir.names(), (std::set<std::string>{"freedoom2.wad"})) << "no backup, no temporary";
}

TEST(GlPvsWriter, MapSourceNotMatchingTheFileThrowsFileError)
{
    FREEDOOM_OR_SKIP(iwad, "freedoom2.wad");
    GL_NODES_OR_SKIP(made, iwad, pvs::test::GlBuilder::zdbsp_v2);
    ScratchDir dir;
    const std::string wad = dir.copy(made, "freedoom2.wad");
    const WadFile original = read_wad(wad);
    const MapSource good = source_for(original, original, "MAP01");
    const uint32_t n = v2_subsectors(original, good.gl_marker);
    const uint32_t sectors = sectors_of_map(original, good.map_marker);
    const Pvs pvs = pattern_pvs(n, 8);
    const std::vector<uint32_t> sector = some_sectors(n, sectors);
    GlPvsWriteOptions reject;
    reject.rebuild_reject = true;

    const auto expect_file_error = [&](MapSource source, uint32_t sector_count, const GlPvsWriteOptions& options) {
        try {
            write_gl_pvs(source, pvs, sector, sector_count, options);
            ADD_FAILURE() << "no FileError for gl_marker " << source.gl_marker << ", map_marker " << source.map_marker;
        } catch (const FileError& e) {
            EXPECT_EQ(e.file(), wad);
        }
    };
    MapSource at = good;
    at.gl_marker = good.map_marker; // MAP01: not a GL marker
    expect_file_error(at, sectors, {});
    at.gl_marker = good.gl_marker + 1; // GL_VERT: a GL_ name, but not followed by the group
    expect_file_error(at, sectors, {});
    at.gl_marker = original.lumps.size() - 2; // the group would run past the directory
    expect_file_error(at, sectors, {});
    at = good;
    at.map_marker = good.map_marker + 1; // THINGS: not a map marker
    expect_file_error(at, sectors, reject);
    expect_file_error(good, sectors + 1, reject); // SECTORS holds another count

    EXPECT_TRUE(std::ranges::equal(read_whole_file(wad), original.bytes));
    EXPECT_EQ(dir.names(), (std::set<std::string>{"freedoom2.wad"}));
}

TEST(GlPvsWriter, BackupNamesFollowGlvis)
{
    EXPECT_EQ(gl_pvs_backup_path("maps/doom2.gwa"), "maps/doom2.~gw");
    EXPECT_EQ(gl_pvs_backup_path("maps/DOOM2.GWA"), "maps/DOOM2.~gw");
    EXPECT_EQ(gl_pvs_backup_path("maps/doom2.wad"), "maps/doom2.~wa");
    EXPECT_EQ(gl_pvs_backup_path("maps/doom2"), "maps/doom2.~wa");
}

// --- In memory, on a small hand-made WAD --------------------------------------------------------

// Distinct bytes for every lump, so a lump moved or swapped shows.
WadLumpData lump(const std::string& name, size_t size, uint8_t seed)
{
    WadLumpData data{name, std::vector<uint8_t>(size)};
    for (size_t i = 0; i < size; ++i)
        data.bytes[i] = uint8_t(seed * 31 + i * 7);
    return data;
}

// MAP01 and MAP02 (classic lumps, MAP02 with a Hexen BEHAVIOR), then the GL groups of both, the
// last one ending the file (GL_PVS is then inserted at the very end), and a lower-case name.
std::vector<WadLumpData> two_maps(bool map01_reject = true)
{
    std::vector<WadLumpData> lumps;
    uint8_t seed = 1;
    for (const char* map : {"MAP01", "MAP02"}) {
        lumps.push_back(lump(map, 0, seed++));
        for (const char* name : {"THINGS", "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS", "SSECTORS", "NODES"}) {
            lumps.push_back(lump(name, 40 + size_t(seed), seed));
            ++seed;
        }
        lumps.push_back(lump("SECTORS", 2 * 26, seed++));
        if (map01_reject || std::string(map) == "MAP02")
            lumps.push_back(lump("REJECT", 1, seed++));
        lumps.push_back(lump("BLOCKMAP", 17, seed++));
        if (std::string(map) == "MAP02")
            lumps.push_back(lump("BEHAVIOR", 9, seed++));
    }
    lumps.push_back(lump("music", 5, seed++));
    for (const char* map : {"GL_MAP01", "GL_MAP02"}) {
        lumps.push_back(lump(map, 0, seed++));
        lumps.push_back(lump("GL_VERT", 4 + 8 * 3, seed++));
        std::memcpy(lumps.back().bytes.data(), "gNd2", 4);
        lumps.push_back(lump("GL_SEGS", 10 * 9, seed++));
        lumps.push_back(lump("GL_SSECT", 4 * 3, seed++));
        lumps.push_back(lump("GL_NODES", 28 * 2, seed++));
    }
    return lumps;
}

WadFile parsed(const std::vector<WadLumpData>& lumps)
{
    return parse_wad(write_wad(false, lumps), "two_maps.wad");
}

TEST(WithGlPvs, InsertsAtTheEndOfTheFileThenReplaces)
{
    const WadFile original = parsed(two_maps());
    const size_t marker = lump_index(original, "GL_MAP02");
    ASSERT_EQ(marker + 5, original.lumps.size());
    EXPECT_EQ(gl_subsector_count(original, marker), 3u);
    const Pvs pvs = pvs_from_rows({{0, 1}, {1}, {0, 1, 2}});
    const std::vector<uint8_t> lump_bytes = gl_pvs_lump(pvs);
    EXPECT_EQ(lump_bytes, (std::vector<uint8_t>{0x03, 0x02, 0x07}));

    const WadFile inserted = parse_wad(with_gl_pvs(original, marker, lump_bytes), "inserted");
    expect_lumps_kept(original, inserted, marker + 5, {});
    EXPECT_EQ(inserted.lumps.back().name, "GL_PVS");
    expect_gl_pvs_rows(inserted.data(marker + 5), pvs);

    const Pvs other = pvs_from_rows({{0}, {1, 2}, {2}});
    const WadFile replaced = parse_wad(with_gl_pvs(inserted, marker, gl_pvs_lump(other)), "replaced");
    expect_lumps_kept(inserted, replaced, std::nullopt, {marker + 5});
    expect_gl_pvs_rows(replaced.data(marker + 5), other);
}

TEST(WithGlPvs, InsertsInTheMiddleAndKeepsTheCaseOfNames)
{
    const WadFile original = parsed(two_maps());
    const size_t marker = lump_index(original, "GL_MAP01");
    const size_t music = lump_index(original, "MUSIC");
    const std::vector<uint8_t> bytes = with_gl_pvs(original, marker, gl_pvs_lump(pvs_from_rows({{0}, {1}, {2}})));
    const WadFile written = parse_wad(bytes, "written");
    expect_lumps_kept(original, written, marker + 5, {});
    EXPECT_EQ(written.lumps[marker + 5].name, "GL_PVS");
    EXPECT_EQ(written.lumps[marker + 6].name, "GL_MAP02");
    const uint8_t* raw = written.bytes.data() + written.lumps[music].directory_offset + 8;
    EXPECT_EQ(std::string(reinterpret_cast<const char*>(raw), 5), "music") << "the name as the file spelled it";
}

TEST(WithGlPvs, RefusesWhatIsNotAGlGroup)
{
    const WadFile original = parsed(two_maps());
    const size_t marker = lump_index(original, "GL_MAP01");
    const std::vector<uint8_t> empty;
    EXPECT_THROW(with_gl_pvs(original, lump_index(original, "MAP01"), empty), FileError);
    EXPECT_THROW(with_gl_pvs(original, marker + 4, empty), FileError); // GL_NODES itself
    EXPECT_THROW(with_gl_pvs(original, original.lumps.size(), empty), FileError);
    EXPECT_THROW(with_gl_pvs(original, original.lumps.size() + 100, empty), FileError);
    std::vector<WadLumpData> renamed = two_maps();
    renamed[marker + 4].name = "NODES"; // the group's fourth lump is not GL_NODES
    EXPECT_THROW(with_gl_pvs(parsed(renamed), marker, empty), FileError);
    try {
        with_gl_pvs(parsed(renamed), marker, empty);
    } catch (const FileError& e) {
        EXPECT_EQ(e.file(), "two_maps.wad");
        EXPECT_EQ(e.offset(), parsed(renamed).lumps[marker + 4].directory_offset) << "the entry that is wrong";
    }
}

TEST(WithReject, ReplacesOnlyThatMapsReject)
{
    const WadFile original = parsed(two_maps());
    const size_t map01 = lump_index(original, "MAP01"), map02 = lump_index(original, "MAP02");
    const size_t reject01 = lump_index(original, "REJECT", map01), reject02 = lump_index(original, "REJECT", map02);
    const std::vector<uint8_t> new_reject{0x5A};

    const WadFile first = parse_wad(with_reject(original, map01, new_reject), "first");
    expect_lumps_kept(original, first, std::nullopt, {reject01});
    EXPECT_TRUE(same_bytes(first.data(reject01), new_reject));

    const WadFile second = parse_wad(with_reject(original, map02, new_reject), "second");
    expect_lumps_kept(original, second, std::nullopt, {reject02});
    EXPECT_TRUE(same_bytes(second.data(reject02), new_reject));
}

TEST(WithReject, RefusesAMapWithoutRejectRatherThanTakingTheNextMaps)
{
    const WadFile no_reject = parsed(two_maps(false));
    EXPECT_THROW(with_reject(no_reject, lump_index(no_reject, "MAP01"), std::vector<uint8_t>{0}), FileError);
    const WadFile original = parsed(two_maps());
    EXPECT_THROW(with_reject(original, lump_index(original, "THINGS"), std::vector<uint8_t>{0}), FileError);
    EXPECT_THROW(with_reject(original, lump_index(original, "GL_MAP01"), std::vector<uint8_t>{0}), FileError);
    EXPECT_THROW(with_reject(original, original.lumps.size(), std::vector<uint8_t>{0}), FileError);
}

TEST(WithReject, KeepsEveryOtherLumpOfFreedoom)
{
    FREEDOOM_OR_SKIP(iwad, "freedoom2.wad");
    const WadFile original = read_wad(iwad);
    const size_t map = lump_index(original, "MAP05");
    const size_t reject = lump_index(original, "REJECT", map);
    const std::vector<uint8_t> new_reject(original.lumps[reject].size, 0xA5);
    const WadFile written = parse_wad(with_reject(original, map, new_reject), "written");
    EXPECT_TRUE(written.iwad);
    expect_lumps_kept(original, written, std::nullopt, {reject});
    EXPECT_TRUE(same_bytes(written.data(reject), new_reject));
}

// --- REJECT from a PVS --------------------------------------------------------------------------

TEST(RejectFromPvs, ThreeSubsectorsInTwoSectors)
{
    // Subsector 0 is sector 0; subsectors 1 and 2 are sector 1.
    // 0 sees {0}; 1 sees {1, 2}; 2 sees {2, 0}: sector 0 sees 0 only, sector 1 sees 1 and 0.
    const Pvs pvs = pvs_from_rows({{0}, {1, 2}, {0, 2}});
    const std::vector<uint32_t> sector{0, 1, 1};
    const std::vector<uint8_t> reject = reject_from_pvs(pvs, sector, 2);
    // Bits (a * 2 + b): (0,0) clear, (0,1) set, (1,0) clear, (1,1) clear; padding bits 4..7 set.
    EXPECT_EQ(reject, (std::vector<uint8_t>{0xF2}));
    EXPECT_EQ(reject, reject_by_sector_pairs(pvs, sector, 2));
}

TEST(RejectFromPvs, MatchesSectorPairsAcrossBytes)
{
    // 3 sectors (9 bits: two bytes), sector 2 with no subsector: its row and column stay set.
    // Pairs seen: (0,0), (0,1), (1,1), (1,0): bits 0, 1, 4, 3 clear.
    const Pvs pvs = pvs_from_rows({{0, 1}, {1}, {2, 3}, {3, 0}});
    const std::vector<uint32_t> sector{0, 1, 1, 0};
    EXPECT_EQ(reject_from_pvs(pvs, sector, 3), reject_by_sector_pairs(pvs, sector, 3));
    EXPECT_EQ(reject_from_pvs(pvs, sector, 3), (std::vector<uint8_t>{0xE4, 0xFF}));

    const Pvs big = pattern_pvs(70, 9);
    const std::vector<uint32_t> many = some_sectors(70, 11);
    EXPECT_EQ(reject_from_pvs(big, many, 11), reject_by_sector_pairs(big, many, 11));
}

TEST(RejectFromPvs, RefusesSectorsThatDoNotFit)
{
    const Pvs pvs = pvs_from_rows({{0}, {1}, {2}});
    EXPECT_THROW(reject_from_pvs(pvs, std::vector<uint32_t>{0, 1}, 2), std::invalid_argument);
    EXPECT_THROW(reject_from_pvs(pvs, std::vector<uint32_t>{0, 1, 2}, 2), std::invalid_argument);
    const Pvs not_square = Pvs::build_rows(2, 3, [](uint32_t, std::span<uint64_t>) { return true; });
    EXPECT_THROW(reject_from_pvs(not_square, std::vector<uint32_t>{0, 0, 0}, 1), std::invalid_argument);
    EXPECT_THROW(gl_pvs_lump(not_square), std::invalid_argument);
}

} // namespace
} // namespace pvs::doom
