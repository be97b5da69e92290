// Doom textures (wld/doom/doom_textures.h).
//  - A tiny WAD built here gives exactly the texels it was made of: a gap between posts is
//    transparent, patches are clipped and drawn in order, a missing patch is left out, tall
//    patches add their topdelta, the first palette is used, flats come from the marker ranges.
//  - Freedoom (Debian's freedoom2.wad), checked against what the test reads from the lumps
//    itself: every flat texel is PLAYPAL[raw byte]; every TEXTURE1 texture decodes at the size
//    its record gives; a texture of one patch that covers it is opaque and its first posts are
//    the patch's bytes through the palette; a masked texture has holes.
//  - Corrupt input (truncated patches, bad records, garbage, a composition that would never
//    end) throws FileError naming the lump; never a crash (CI runs this under ASan + UBSan).
#include "tests/support/freedoom.h"
#include "visibility/file_error.h"
#include "wld/doom/doom_textures.h"
#include "wld/doom/wad_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <map>
#include <random>
#include <set>

namespace {

using pvs::FileError;
using pvs::doom::DoomImage;
using pvs::doom::DoomTextures;
using pvs::doom::WadFile;
using pvs::doom::WadLumpData;

void put16(std::vector<uint8_t>& out, int v)
{
    out.push_back(uint8_t(v & 0xFF));
    out.push_back(uint8_t((v >> 8) & 0xFF));
}

void put32(std::vector<uint8_t>& out, int64_t v)
{
    for (int k = 0; k < 4; ++k)
        out.push_back(uint8_t((v >> (8 * k)) & 0xFF));
}

void put_name(std::vector<uint8_t>& out, const std::string& name)
{
    for (size_t k = 0; k < 8; ++k)
        out.push_back(k < name.size() ? uint8_t(name[k]) : 0);
}

int16_t get16(std::span<const uint8_t> bytes, size_t at)
{
    int16_t v;
    std::memcpy(&v, bytes.data() + at, 2);
    return v;
}

int32_t get32(std::span<const uint8_t> bytes, size_t at)
{
    int32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}

std::string get_name(std::span<const uint8_t> bytes, size_t at)
{
    std::string name;
    for (size_t k = 0; k < 8 && bytes[at + k] != 0; ++k)
        name.push_back(char(std::toupper(bytes[at + k])));
    return name;
}

// Palette 0 of the tiny WAD: index i is (i, 255 - i, 3i mod 256). Palette 1 is all grey, to
// show that only the first palette is used.
std::array<uint8_t, 4> color(uint8_t i) { return {i, uint8_t(255 - i), uint8_t(3 * i), 255}; }

std::vector<uint8_t> playpal()
{
    std::vector<uint8_t> out;
    for (int i = 0; i < 256; ++i)
        for (int c = 0; c < 3; ++c)
            out.push_back(color(uint8_t(i))[size_t(c)]);
    out.resize(2 * 768, 0x80);
    return out;
}

struct Post {
    uint8_t topdelta;
    std::vector<uint8_t> texels;
};
using Column = std::vector<Post>;

// A Doom picture: header, column offsets, then each column's posts and 0xFF.
std::vector<uint8_t> picture(int width, int height, const std::vector<Column>& columns)
{
    std::vector<uint8_t> out;
    put16(out, width);
    put16(out, height);
    put16(out, 0);
    put16(out, 0);
    std::vector<uint8_t> data;
    for (const Column& column : columns) {
        put32(out, int64_t(8 + 4 * columns.size() + data.size()));
        for (const Post& post : column) {
            data.push_back(post.topdelta);
            data.push_back(uint8_t(post.texels.size()));
            data.push_back(0);
            data.insert(data.end(), post.texels.begin(), post.texels.end());
            data.push_back(0);
        }
        data.push_back(0xFF);
    }
    out.insert(out.end(), data.begin(), data.end());
    return out;
}

std::vector<uint8_t> pnames(const std::vector<std::string>& names)
{
    std::vector<uint8_t> out;
    put32(out, int64_t(names.size()));
    for (const std::string& name : names)
        put_name(out, name);
    return out;
}

struct PatchRef {
    int x, y, index;
};
struct TextureDef {
    std::string name;
    int width, height;
    std::vector<PatchRef> patches;
};

std::vector<uint8_t> texture_lump(const std::vector<TextureDef>& textures)
{
    std::vector<uint8_t> out;
    put32(out, int64_t(textures.size()));
    std::vector<uint8_t> records;
    for (const TextureDef& t : textures) {
        put32(out, int64_t(4 + 4 * textures.size() + records.size()));
        put_name(records, t.name);
        put32(records, 0);
        put16(records, t.width);
        put16(records, t.height);
        put32(records, 0);
        put16(records, int(t.patches.size()));
        for (const PatchRef& p : t.patches) {
            put16(records, p.x);
            put16(records, p.y);
            put16(records, p.index);
            put16(records, 1);
            put16(records, 0);
        }
    }
    out.insert(out.end(), records.begin(), records.end());
    return out;
}

// PATCHA 3x6: column 0 has posts at rows 0-1 and 4-5 (a gap at 2-3), column 1 is solid,
// column 2 is empty.
std::vector<uint8_t> patch_a()
{
    return picture(3, 6, {{{0, {1, 2}}, {4, {3, 4}}}, {{0, {10, 11, 12, 13, 14, 15}}}, {}});
}

// The tiny WAD's lumps, for tests to change before writing.
std::vector<WadLumpData> tiny_lumps()
{
    std::vector<uint8_t> flat1(4096), flat4(16), flat2(9, 7);
    for (size_t i = 0; i < flat1.size(); ++i)
        flat1[i] = uint8_t(i % 251);
    for (size_t i = 0; i < flat4.size(); ++i)
        flat4[i] = uint8_t(100 + i);
    return {
        {"PLAYPAL", playpal()},
        {"PNAMES", pnames({"PATCHA", "NOPATCH", "patchb", "TALL"})},
        {"TEXTURE1", texture_lump({
                         {"TEXA", 4, 6, {{0, 0, 0}}},
                         {"TEXB", 3, 3, {{0, 0, 1}, {-1, -1, 2}, {2, 1, 0}, {1, 0, 2}}},
                         {"TALLTEX", 1, 8, {{0, 0, 3}}},
                         {"texc", 4, 6, {{0, 0, 0}}},
                     })},
        {"TEXTURE2", texture_lump({{"TEXA", 2, 2, {{0, 0, 2}}}, {"TEX2ONLY", 1, 1, {{0, 0, 2}}}})},
        {"PATCHA", patch_a()},
        {"PATCHB", picture(2, 2, {{{0, {20, 21}}}, {{0, {22, 23}}}})},
        // Rows: topdelta 2 -> 2; 4 > 2 -> 4; 3 <= 4 -> 4 + 3 = 7 (DeePsea).
        {"TALL", picture(1, 8, {{{2, {5}}, {4, {6}}, {3, {7}}}})},
        {"F_START", {}},
        {"FLAT1", flat1},
        {"F1_START", {}},
        {"FLAT4", flat4},
        {"FLAT2", std::vector<uint8_t>(16, 1)},
        {"FLATBAD", std::vector<uint8_t>(10, 1)},
        {"F_END", {}},
        {"OUTSIDE", flat1},
        {"FF_START", {}},
        {"FLAT2", flat2}, // a later range: this FLAT2 wins
        {"FF_END", {}},
    };
}

WadFile make_wad(const std::vector<WadLumpData>& lumps)
{
    return pvs::doom::parse_wad(pvs::doom::write_wad(false, lumps), "tiny.wad");
}

WadLumpData& lump_named(std::vector<WadLumpData>& lumps, const std::string& name)
{
    for (WadLumpData& lump : lumps)
        if (lump.name == name)
            return lump;
    throw std::logic_error("no lump " + name);
}

std::array<uint8_t, 4> texel(const DoomImage& image, uint32_t x, uint32_t y)
{
    const size_t at = (size_t(y) * image.width + x) * 4;
    return {image.rgba[at], image.rgba[at + 1], image.rgba[at + 2], image.rgba[at + 3]};
}

constexpr std::array<uint8_t, 4> kClear = {0, 0, 0, 0};

// Expected texels of a texture as rows of palette indices, -1 = transparent.
void expect_texels(const DoomImage& image, const std::vector<std::vector<int>>& rows)
{
    ASSERT_EQ(image.height, rows.size());
    ASSERT_EQ(image.width, rows[0].size());
    ASSERT_EQ(image.rgba.size(), size_t(image.width) * image.height * 4);
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x) {
            const int want = rows[y][x];
            EXPECT_EQ(texel(image, x, y), want < 0 ? kClear : color(uint8_t(want))) << "texel " << x << "," << y;
        }
}

// Runs `f`, which must throw FileError whose message holds every one of `words`.
template <class F>
void expect_file_error(F&& f, const std::vector<std::string>& words, const std::string& file = "tiny.wad")
{
    try {
        f();
        ADD_FAILURE() << "no FileError";
    } catch (const FileError& e) {
        EXPECT_EQ(e.file(), file);
        for (const std::string& word : words)
            EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << "'" << word << "' not in: " << e.what();
    }
}

} // namespace

TEST(DoomTextures, TinyWadTextureHasPostsAndTransparentGapBetweenThem)
{
    const WadFile wad = make_wad(tiny_lumps());
    const DoomTextures textures(wad);
    const auto texa = textures.wall("TEXA");
    ASSERT_TRUE(texa);
    // TEXTURE1's TEXA (4x6) wins over TEXTURE2's TEXA (2x2). Column 2 of the patch is empty and
    // column 3 lies past the patch: both transparent.
    expect_texels(*texa, {
                             {1, 10, -1, -1},
                             {2, 11, -1, -1},
                             {-1, 12, -1, -1},
                             {-1, 13, -1, -1},
                             {3, 14, -1, -1},
                             {4, 15, -1, -1},
                         });
}

TEST(DoomTextures, TinyWadPatchesAreClippedDrawnInOrderAndMissingOnesLeftOut)
{
    const WadFile wad = make_wad(tiny_lumps());
    const DoomTextures textures(wad);
    const auto texb = textures.wall("TEXB");
    ASSERT_TRUE(texb);
    // NOPATCH has no lump: left out. PATCHB at (-1,-1) leaves only its texel 23 at (0,0);
    // PATCHA at (2,1) puts 1, 2 in column 2 (the rest clipped); PATCHB at (1,0), drawn last,
    // covers (2,1) with 23.
    expect_texels(*texb, {
                             {23, 20, 22},
                             {-1, 21, 23},
                             {-1, -1, 2},
                         });
}

TEST(DoomTextures, TinyWadTallPatchAddsTopdeltaNotAboveThePreviousTop)
{
    const WadFile wad = make_wad(tiny_lumps());
    const auto tall = DoomTextures(wad).wall("TALLTEX");
    ASSERT_TRUE(tall);
    expect_texels(*tall, {{-1}, {-1}, {5}, {-1}, {6}, {-1}, {-1}, {7}});
}

TEST(DoomTextures, TinyWadNamesAreUpperCaseAndTexture2IsRead)
{
    const WadFile wad = make_wad(tiny_lumps());
    const DoomTextures textures(wad);
    const auto lower = textures.wall("texa");
    const auto texc = textures.wall("TEXC"); // written "texc" in TEXTURE1
    ASSERT_TRUE(lower && texc);
    EXPECT_EQ(lower->rgba, textures.wall("TEXA")->rgba);
    EXPECT_EQ(texc->rgba, lower->rgba);
    const auto only2 = textures.wall("tex2only");
    ASSERT_TRUE(only2);
    expect_texels(*only2, {{20}});
    EXPECT_FALSE(textures.wall("NOSUCH"));
    EXPECT_FALSE(textures.wall("PATCHA")); // a patch is not a texture
    EXPECT_FALSE(textures.wall("FLAT1"));
}

TEST(DoomTextures, TinyWadFlatsComeFromTheMarkerRangesThroughTheFirstPalette)
{
    const WadFile wad = make_wad(tiny_lumps());
    const DoomTextures textures(wad);
    const auto flat1 = textures.flat("flat1");
    ASSERT_TRUE(flat1);
    ASSERT_EQ(flat1->width, 64u);
    ASSERT_EQ(flat1->height, 64u);
    for (uint32_t i = 0; i < 4096; ++i)
        ASSERT_EQ(texel(*flat1, i % 64, i / 64), color(uint8_t(i % 251))) << i;
    const auto flat4 = textures.flat("FLAT4"); // 16 bytes: 4x4, rows top to bottom
    ASSERT_TRUE(flat4);
    EXPECT_EQ(flat4->width, 4u);
    EXPECT_EQ(flat4->height, 4u);
    EXPECT_EQ(texel(*flat4, 1, 2), color(100 + 9));
    const auto flat2 = textures.flat("FLAT2"); // the FF_START one, 3x3 of index 7
    ASSERT_TRUE(flat2);
    EXPECT_EQ(flat2->width, 3u);
    EXPECT_EQ(texel(*flat2, 2, 2), color(7));
    EXPECT_FALSE(textures.flat("FLATBAD"));  // 10 bytes: not a square
    EXPECT_FALSE(textures.flat("OUTSIDE"));  // after F_END
    EXPECT_FALSE(textures.flat("F1_START")); // a marker
    EXPECT_FALSE(textures.flat("TEXA"));
}

TEST(DoomTextures, NamesListEveryFlatAndWallTextureSortedUpperCase)
{
    const WadFile wad = make_wad(tiny_lumps());
    const DoomTextures textures(wad);
    const std::vector<std::string> walls = textures.wall_names();
    const std::vector<std::string> flats = textures.flat_names();
    EXPECT_TRUE(std::is_sorted(walls.begin(), walls.end()));
    EXPECT_TRUE(std::is_sorted(flats.begin(), flats.end()));
    for (const char* name : {"TEXA", "TEXC", "TALLTEX", "TEX2ONLY"})
        EXPECT_NE(std::find(walls.begin(), walls.end(), name), walls.end()) << name;
    for (const char* name : {"FLAT1", "FLAT2", "FLAT4", "FLATBAD"}) // FLATBAD: listed, does not decode
        EXPECT_NE(std::find(flats.begin(), flats.end(), name), flats.end()) << name;
    EXPECT_EQ(std::find(flats.begin(), flats.end(), "OUTSIDE"), flats.end());
    EXPECT_EQ(std::find(flats.begin(), flats.end(), "F1_START"), flats.end());
}

TEST(DoomTextures, MissingLumpsMeanNoTexturesNotAnError)
{
    std::vector<WadLumpData> lumps = tiny_lumps();
    lump_named(lumps, "PLAYPAL").name = "NOPAL"; // without colors nothing decodes
    const WadFile no_palette = make_wad(lumps);
    const DoomTextures without_palette(no_palette);
    EXPECT_FALSE(without_palette.wall("TEXA"));
    EXPECT_FALSE(without_palette.flat("FLAT1"));

    const WadFile empty = make_wad({{"PLAYPAL", playpal()}});
    const DoomTextures nothing(empty);
    EXPECT_FALSE(nothing.wall("TEXA"));
    EXPECT_FALSE(nothing.flat("FLAT1"));
}

TEST(DoomTextures, TruncatedPatchThrowsFileErrorNamingPatchAndTextureAtEveryLength)
{
    const size_t full = patch_a().size();
    for (size_t length = 0; length < full; ++length) {
        std::vector<WadLumpData> lumps = tiny_lumps();
        lump_named(lumps, "PATCHA").bytes.resize(length);
        const WadFile wad = make_wad(lumps);
        const DoomTextures textures(wad);
        SCOPED_TRACE("PATCHA cut to " + std::to_string(length) + " bytes");
        expect_file_error([&] { textures.wall("TEXA"); }, {"PATCHA", "TEXA", "TEXTURE1"});
        try {
            textures.wall("TEXA");
        } catch (const FileError& e) {
            const auto& patch = wad.lumps[*wad.find_last("PATCHA")];
            // The offset is in the file, in the lump or just past it (a post's texels start
            // 3 bytes after its top delta).
            EXPECT_GE(e.offset(), patch.offset);
            EXPECT_LT(e.offset(), uint64_t(patch.offset) + patch.size + 3);
        }
    }
}

TEST(DoomTextures, CorruptPatchColumnOffsetThrowsFileError)
{
    std::vector<WadLumpData> lumps = tiny_lumps();
    std::vector<uint8_t>& patch = lump_named(lumps, "PATCHA").bytes;
    patch[8 + 4] = 0xF0; // column 1 far past the lump
    patch[8 + 7] = 0x7F;
    const WadFile wad = make_wad(lumps);
    expect_file_error([&] { DoomTextures(wad).wall("TEXA"); }, {"PATCHA", "post top delta"});
}

TEST(DoomTextures, BadTextureRecordsThrowFileErrorNamingTheTexture)
{
    const auto with_texture = [](const TextureDef& def) {
        std::vector<WadLumpData> lumps = tiny_lumps();
        lump_named(lumps, "TEXTURE1").bytes = texture_lump({def});
        return lumps;
    };
    for (const TextureDef& def : {TextureDef{"BAD", 0, 8, {}}, TextureDef{"BAD", 8, -1, {}},
                                  TextureDef{"BAD", 4097, 8, {}}, TextureDef{"BAD", 8, 8, {{0, 0, 4}}},
                                  TextureDef{"BAD", 8, 8, {{0, 0, -1}}}}) {
        const WadFile wad = make_wad(with_texture(def));
        expect_file_error([&] { DoomTextures(wad).wall("BAD"); }, {"texture 'BAD' in TEXTURE1"});
    }
    // A negative patch count: the i16 at record offset 20.
    std::vector<WadLumpData> lumps = with_texture({"BAD", 8, 8, {}});
    lump_named(lumps, "TEXTURE1").bytes[8 + 20 + 1] = 0x80;
    const WadFile negative = make_wad(lumps);
    expect_file_error([&] { DoomTextures(negative).wall("BAD"); }, {"BAD", "negative patch count"});
    // A record cut short.
    lumps = with_texture({"BAD", 8, 8, {{0, 0, 0}}});
    lump_named(lumps, "TEXTURE1").bytes.resize(8 + 24);
    const WadFile cut = make_wad(lumps);
    expect_file_error([&] { DoomTextures(cut).wall("BAD"); }, {"BAD", "patch records"});
}

TEST(DoomTextures, BadDirectoriesThrowFileErrorFromTheConstructor)
{
    std::vector<WadLumpData> lumps = tiny_lumps();
    lump_named(lumps, "TEXTURE1").bytes[0] = 0xFF; // count 255: offsets past the lump
    const WadFile texture1 = make_wad(lumps);
    expect_file_error([&] { DoomTextures{texture1}; }, {"TEXTURE1", "texture offsets"});

    lumps = tiny_lumps();
    lump_named(lumps, "TEXTURE2").bytes[4] = 0xFF; // first record offset 255: past the lump
    const WadFile texture2 = make_wad(lumps);
    expect_file_error([&] { DoomTextures{texture2}; }, {"TEXTURE2", "texture name"});

    lumps = tiny_lumps();
    lump_named(lumps, "PNAMES").bytes[3] = 0x80; // negative count
    const WadFile names = make_wad(lumps);
    expect_file_error([&] { DoomTextures{names}; }, {"PNAMES", "negative"});

    lumps = tiny_lumps();
    lump_named(lumps, "PLAYPAL").bytes.resize(700);
    const WadFile palette = make_wad(lumps);
    expect_file_error([&] { DoomTextures{palette}; }, {"PLAYPAL", "first palette"});
}

TEST(DoomTextures, EndlessCompositionOfGarbageIsStoppedWithFileError)
{
    // 32767 patches on a 64x64 texture, each patch 64 columns that all point at one column of
    // 65535 empty posts at row 0: 1.4e11 posts to walk without a bound.
    std::vector<uint8_t> garbage;
    put16(garbage, 64);
    put16(garbage, 64);
    put32(garbage, 0);
    for (int x = 0; x < 64; ++x)
        put32(garbage, 8 + 4 * 64);
    for (int k = 0; k < 65535; ++k)
        put32(garbage, 0); // topdelta 0, length 0, two pad bytes
    garbage.push_back(0xFF);
    std::vector<WadLumpData> lumps = tiny_lumps();
    lump_named(lumps, "PATCHA").bytes = garbage;
    lump_named(lumps, "TEXTURE1").bytes = texture_lump({{"HANG", 64, 64, std::vector<PatchRef>(32767, {0, 0, 0})}});
    const WadFile wad = make_wad(lumps);
    expect_file_error([&] { DoomTextures(wad).wall("HANG"); }, {"HANG", "PATCHA", "steps"});
}

TEST(DoomTextures, RandomGarbageInTextureLumpsDecodesOrThrowsFileError)
{
    const std::vector<WadLumpData> original = tiny_lumps();
    std::mt19937 rng(11);
    const std::vector<std::string> targets = {"PNAMES", "TEXTURE1", "TEXTURE2", "PATCHA", "PATCHB", "TALL"};
    size_t decoded = 0, errors = 0;
    for (int round = 0; round < 3000; ++round) {
        std::vector<WadLumpData> lumps = original;
        std::vector<uint8_t>& bytes = lump_named(lumps, targets[size_t(round) % targets.size()]).bytes;
        const int changes = 1 + int(rng() % 4);
        for (int c = 0; c < changes; ++c)
            bytes[rng() % bytes.size()] = uint8_t(rng());
        const WadFile wad = make_wad(lumps);
        try {
            const DoomTextures textures(wad);
            for (const char* name : {"TEXA", "TEXB", "TALLTEX", "TEXC", "TEX2ONLY"})
                if (const auto image = textures.wall(name)) {
                    ASSERT_GE(image->width, 1u);
                    ASSERT_LE(image->width, pvs::doom::kMaxDoomTextureSide);
                    ASSERT_EQ(image->rgba.size(), size_t(image->width) * image->height * 4);
                    ++decoded;
                }
        } catch (const FileError& e) {
            EXPECT_EQ(e.file(), "tiny.wad");
            ++errors;
        }
    }
    EXPECT_GT(decoded, 0u);
    EXPECT_GT(errors, 0u);
}

namespace {

struct Freedoom {
    explicit Freedoom(const std::string& path) : wad(pvs::doom::read_wad(path)), playpal(lump("PLAYPAL")) {}
    std::span<const uint8_t> lump(const std::string& name) const { return wad.data(*wad.find_last(name)); }
    // PLAYPAL's first palette as the test reads it: RGBA of index i.
    std::array<uint8_t, 4> color(uint8_t i) const
    {
        return {playpal[3 * i], playpal[3 * i + 1], playpal[3 * i + 2], 255};
    }

    WadFile wad;
    std::span<const uint8_t> playpal;
};

struct TextureRecord {
    std::string name;
    int16_t width, height;
    std::vector<std::array<int16_t, 3>> patches; // originx, originy, PNAMES index
};

// TEXTURE1 as the test reads it.
std::vector<TextureRecord> texture1(const Freedoom& fd)
{
    const auto lump = fd.lump("TEXTURE1");
    std::vector<TextureRecord> out;
    for (int32_t i = 0; i < get32(lump, 0); ++i) {
        const size_t at = size_t(get32(lump, 4 + 4 * size_t(i)));
        TextureRecord t{get_name(lump, at), get16(lump, at + 12), get16(lump, at + 14), {}};
        for (int16_t k = 0; k < get16(lump, at + 20); ++k) {
            const size_t p = at + 22 + 10 * size_t(k);
            t.patches.push_back({get16(lump, p), get16(lump, p + 2), get16(lump, p + 4)});
        }
        out.push_back(t);
    }
    return out;
}

} // namespace

TEST(DoomTextures, FreedoomFlatTexelsArePlaypalOfTheRawBytes)
{
    FREEDOOM_OR_SKIP(path, "freedoom2.wad");
    const Freedoom fd(path);
    const DoomTextures textures(fd.wad);
    const auto start = fd.wad.find_last("F_START");
    const auto end = fd.wad.find_last("F_END");
    ASSERT_TRUE(start && end);
    std::map<std::string, size_t> flats; // the last of a name, as the engines find it
    for (size_t i = *start + 1; i < *end; ++i)
        if (fd.wad.lumps[i].size == 4096)
            flats[fd.wad.lumps[i].name] = i;
    ASSERT_GT(flats.size(), 100u);
    for (const auto& [name, lump] : flats) {
        const auto image = textures.flat(name);
        ASSERT_TRUE(image) << name;
        ASSERT_EQ(image->width, 64u);
        ASSERT_EQ(image->height, 64u);
        const auto raw = fd.wad.data(lump);
        std::vector<uint8_t> expected;
        for (uint8_t index : raw) {
            const auto rgba = fd.color(index);
            expected.insert(expected.end(), rgba.begin(), rgba.end());
        }
        // One comparison per flat (a gtest assertion per texel takes seconds under ASan).
        if (image->rgba != expected) {
            const auto differ = std::mismatch(expected.begin(), expected.end(), image->rgba.begin());
            FAIL() << name << " differs at texel " << (differ.first - expected.begin()) / 4;
        }
    }
    EXPECT_FALSE(textures.flat("NOTAFLAT"));
}

TEST(DoomTextures, FreedoomEveryTexture1TextureDecodesAtItsRecordSize)
{
    FREEDOOM_OR_SKIP(path, "freedoom2.wad");
    const Freedoom fd(path);
    const DoomTextures textures(fd.wad);
    const std::vector<TextureRecord> records = texture1(fd);
    ASSERT_GT(records.size(), 500u);
    std::set<std::string> seen; // the first of a name wins
    size_t with_holes = 0;
    for (const TextureRecord& t : records) {
        if (!seen.insert(t.name).second)
            continue;
        const auto image = textures.wall(t.name);
        ASSERT_TRUE(image) << t.name;
        ASSERT_EQ(image->width, uint32_t(t.width)) << t.name;
        ASSERT_EQ(image->height, uint32_t(t.height)) << t.name;
        ASSERT_EQ(image->rgba.size(), size_t(t.width) * size_t(t.height) * 4) << t.name;
        bool hole = false;
        for (size_t i = 3; i < image->rgba.size(); i += 4)
            hole = hole || image->rgba[i] == 0;
        with_holes += hole;
    }
    EXPECT_GT(with_holes, 0u);                 // masked midtextures (grates, bars)
    EXPECT_LT(with_holes, records.size() / 2); // but most walls are solid
}

TEST(DoomTextures, FreedoomOnePatchTextureCoveredByItsPatchIsOpaqueWithThePatchBytes)
{
    FREEDOOM_OR_SKIP(path, "freedoom2.wad");
    const Freedoom fd(path);
    const DoomTextures textures(fd.wad);
    const std::vector<TextureRecord> records = texture1(fd);
    const auto found = std::find_if(records.begin(), records.end(), [](const auto& t) { return t.name == "BIGDOOR2"; });
    ASSERT_NE(found, records.end());
    // The premise, from the records: one patch at 0,0, at least as large as the texture.
    ASSERT_EQ(found->patches.size(), 1u);
    ASSERT_EQ(found->patches[0][0], 0);
    ASSERT_EQ(found->patches[0][1], 0);
    const auto names = fd.lump("PNAMES");
    const std::string patch_name = get_name(names, 4 + 8 * size_t(found->patches[0][2]));
    const auto patch = fd.lump(patch_name);
    ASSERT_GE(get16(patch, 0), found->width);
    ASSERT_GE(get16(patch, 2), found->height);

    const auto image = textures.wall("bigdoor2");
    ASSERT_TRUE(image);
    for (size_t i = 3; i < image->rgba.size(); i += 4)
        ASSERT_EQ(image->rgba[i], 255) << "transparent texel " << i / 4;
    // Each column's first post, read here, is the top of that column through the palette.
    for (uint32_t x = 0; x < image->width; ++x) {
        const size_t column = size_t(get32(patch, 8 + 4 * size_t(x)));
        ASSERT_EQ(patch[column], 0) << "column " << x << " does not start at the top";
        const uint8_t length = patch[column + 1];
        for (uint32_t y = 0; y < length && y < image->height; ++y)
            ASSERT_EQ(texel(*image, x, y), fd.color(patch[column + 3 + y])) << x << "," << y;
    }
}

TEST(DoomTextures, FreedoomMaskedTextureHasHolesAndNamesMatchAnyCase)
{
    FREEDOOM_OR_SKIP(path, "freedoom2.wad");
    const Freedoom fd(path);
    const DoomTextures textures(fd.wad);
    const auto grate = textures.wall("MIDGRATE");
    ASSERT_TRUE(grate);
    size_t clear = 0;
    for (size_t i = 3; i < grate->rgba.size(); i += 4)
        clear += grate->rgba[i] == 0;
    EXPECT_GT(clear, 0u);
    EXPECT_LT(clear, grate->rgba.size() / 4);
    const auto lower = textures.wall("midgrate");
    ASSERT_TRUE(lower);
    EXPECT_EQ(lower->rgba, grate->rgba);
    EXPECT_FALSE(textures.wall("NOTEXTUR"));
    EXPECT_FALSE(textures.flat("MIDGRATE"));
}
