// DDS textures (wld/eq/dds_decode.h): images compressed here with libsquish decode back within
// the block codec's error; bad headers and truncated files give the offset and the problem;
// an EverQuest archive holding a DDS texture (under a .bmp name) is decoded by its magic.
#include "visibility/zone.h"
#include "wld/eq/dds_decode.h"
#include "wld/eq/eq_zone_reader.h"
#include "wld/eq/eq_zone_writer.h"
#include "wld/eq/pfs_archive.h"
#include "gen/generate_zone.h"

#include <gtest/gtest.h>
#include <squish.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <random>

namespace pvs {
namespace {

// A smooth picture: gradients in each channel, opaque unless `alpha` (then alpha ramps too).
std::vector<uint8_t> test_image(uint32_t width, uint32_t height, bool alpha)
{
    std::vector<uint8_t> rgba;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x)
            rgba.insert(rgba.end(), {uint8_t(x * 255 / width), uint8_t(y * 255 / height),
                                     uint8_t((x + y) * 127 / (width + height)),
                                     uint8_t(alpha ? x * 255 / width : 255)});
    return rgba;
}

void put_u32(std::vector<uint8_t>& bytes, size_t at, uint32_t value)
{
    for (int k = 0; k < 4; ++k)
        bytes[at + size_t(k)] = uint8_t(value >> (8 * k));
}

// A DDS file as the format describes it: magic, 124-byte header, DXTn blocks of mip 0.
std::vector<uint8_t> make_dds(const std::vector<uint8_t>& rgba, uint32_t width, uint32_t height, const char* fourcc,
                              int squish_flags)
{
    std::vector<uint8_t> bytes(kDdsHeaderBytes, 0);
    std::memcpy(bytes.data(), "DDS ", 4);
    put_u32(bytes, 4, 124);
    put_u32(bytes, 8, 0x1 | 0x2 | 0x4 | 0x1000 | 0x80000); // caps, height, width, pixel format, linear size
    put_u32(bytes, 12, height);
    put_u32(bytes, 16, width);
    const int size = squish::GetStorageRequirements(int(width), int(height), squish_flags);
    put_u32(bytes, 20, uint32_t(size));
    put_u32(bytes, 28, 1);
    put_u32(bytes, 76, 32);
    put_u32(bytes, 80, 0x4);
    std::memcpy(&bytes[84], fourcc, 4);
    put_u32(bytes, 108, 0x1000);
    bytes.resize(kDdsHeaderBytes + size_t(size));
    squish::CompressImage(rgba.data(), int(width), int(height), bytes.data() + kDdsHeaderBytes, squish_flags);
    return bytes;
}

// Largest difference of any channel of any texel.
int worst_channel_error(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b)
{
    int worst = 0;
    for (size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
    return worst;
}

double mean_channel_error(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b)
{
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        sum += std::abs(int(a[i]) - int(b[i]));
    return sum / double(a.size());
}

struct Format {
    const char* fourcc;
    int flags;
    bool alpha;
};
constexpr Format kFormats[] = {{"DXT1", squish::kDxt1, false}, {"DXT3", squish::kDxt3, true},
                               {"DXT5", squish::kDxt5, true}};
// A 4x4 block holds 4 colours on one line between two 5:6:5 end points: a texel whose three
// channels vary independently can miss by a few tens. A decoding fault (wrong block order, end
// points or format) misses by a hundred and more.
constexpr int kMaxChannelError = 40;
constexpr double kMaxMeanError = 10.0; // measured 4.5 to 7.2 on these steep 2-D gradients

TEST(DdsDecode, CompressedImagesDecodeBackWithinTheCodecError)
{
    for (const Format& f : kFormats)
        for (const auto& [w, h] : {std::pair{64u, 32u}, std::pair{13u, 7u}, std::pair{1u, 1u}}) {
            const std::vector<uint8_t> original = test_image(w, h, f.alpha);
            std::string why;
            const auto image = decode_dds(make_dds(original, w, h, f.fourcc, f.flags), &why);
            ASSERT_TRUE(image) << f.fourcc << " " << w << "x" << h << ": " << why;
            EXPECT_EQ(image->width, w);
            EXPECT_EQ(image->height, h);
            ASSERT_EQ(image->rgba.size(), original.size());
            EXPECT_LE(worst_channel_error(image->rgba, original), kMaxChannelError) << f.fourcc << " " << w << "x" << h;
            EXPECT_LE(mean_channel_error(image->rgba, original), kMaxMeanError) << f.fourcc << " " << w << "x" << h;
        }
}

TEST(DdsDecode, SolidColoursAreExact)
{
    // Pure black and white are block end points in every format: no rounding.
    std::vector<uint8_t> rgba;
    for (int i = 0; i < 16; ++i)
        rgba.insert(rgba.end(), {uint8_t(i % 2 ? 255 : 0), uint8_t(i % 2 ? 255 : 0), uint8_t(i % 2 ? 255 : 0), 255});
    for (const Format& f : kFormats) {
        const auto image = decode_dds(make_dds(rgba, 4, 4, f.fourcc, f.flags));
        ASSERT_TRUE(image) << f.fourcc;
        EXPECT_EQ(image->rgba, rgba) << f.fourcc;
    }
}

std::string why_refused(const std::vector<uint8_t>& bytes)
{
    std::string why;
    EXPECT_FALSE(decode_dds(bytes, &why));
    return why;
}

TEST(DdsDecode, BadHeadersNameTheOffsetAndTheProblem)
{
    const std::vector<uint8_t> good = make_dds(test_image(8, 8, false), 8, 8, "DXT1", squish::kDxt1);
    ASSERT_TRUE(decode_dds(good));
    const auto with = [&](size_t at, uint32_t value) {
        std::vector<uint8_t> bytes = good;
        put_u32(bytes, at, value);
        return bytes;
    };
    EXPECT_EQ(why_refused(with(0, 0x20534444u + 1)), "DDS offset 0: no magic \"DDS \"");
    EXPECT_EQ(why_refused(with(4, 100)), "DDS offset 4: header size 100 is not 124");
    EXPECT_EQ(why_refused(with(12, 0)), "DDS offset 12: height 0 is not in 1..16384");
    EXPECT_EQ(why_refused(with(16, 70000)), "DDS offset 16: width 70000 is not in 1..16384");
    EXPECT_EQ(why_refused(with(76, 0)), "DDS offset 76: pixel format size 0 is not 32");
    EXPECT_NE(why_refused(with(80, 0x40)).find("DDS offset 80: the pixel format has no FourCC"), std::string::npos);
    std::vector<uint8_t> dxt2 = good;
    std::memcpy(&dxt2[84], "DXT2", 4);
    EXPECT_EQ(why_refused(dxt2), "DDS offset 84: FourCC 'DXT2' is not DXT1, DXT3 or DXT5");
    std::memcpy(&dxt2[84], "DX10", 4);
    EXPECT_NE(why_refused(dxt2).find("'DX10'"), std::string::npos);
    // 16384 x 16384 DXT5 would need 256 MiB of blocks: refused before anything is allocated.
    std::vector<uint8_t> huge = with(12, 16384);
    put_u32(huge, 16, 16384);
    EXPECT_NE(why_refused(huge).find("needs 134217728 bytes of blocks"), std::string::npos) << why_refused(huge);
}

TEST(DdsDecode, TruncatedFilesAreRefused)
{
    const std::vector<uint8_t> good = make_dds(test_image(16, 12, true), 16, 12, "DXT5", squish::kDxt5);
    for (size_t size = 0; size < good.size(); ++size) {
        const std::vector<uint8_t> cut(good.begin(), good.begin() + std::ptrdiff_t(size));
        std::string why;
        ASSERT_FALSE(decode_dds(cut, &why)) << size;
        EXPECT_EQ(why.rfind("DDS offset ", 0), 0u) << why;
    }
    EXPECT_EQ(why_refused(std::vector<uint8_t>(good.begin(), good.begin() + 100)),
              "DDS offset 100: the header needs 128 bytes, the file has 100");
}

TEST(DdsDecode, RandomByteChangesNeverCrash)
{
    const std::vector<uint8_t> good = make_dds(test_image(8, 8, false), 8, 8, "DXT3", squish::kDxt3);
    std::mt19937 rng(11);
    for (int trial = 0; trial < 2000; ++trial) {
        std::vector<uint8_t> bytes = good;
        for (int k = 0; k < 3; ++k)
            bytes[rng() % kDdsHeaderBytes] = uint8_t(rng());
        std::string why;
        const auto image = decode_dds(bytes, &why);
        if (image)
            EXPECT_EQ(image->rgba.size(), size_t(image->width) * image->height * 4);
        else
            EXPECT_FALSE(why.empty());
    }
}

TEST(DdsDecode, EverQuestArchiveTextureIsDecodedByItsMagic)
{
    const Zone generated = gen::generate_zone({.rooms = 5, .seed = 3, .cell_size = 32.0f});
    const std::vector<std::string> files = eq::eq_texture_file_names(generated);
    const eq::PfsArchive written(eq::write_eq_zone(generated, "gen"), "gen.s3d");
    // The same archive with the first texture replaced by a DXT1 DDS under its .bmp name.
    const std::vector<uint8_t> original = material_rgba(generated.materials[0]);
    const uint32_t w = generated.materials[0].width, h = generated.materials[0].height;
    const std::vector<uint8_t> dds = make_dds(original, w, h, "DXT1", squish::kDxt1);
    std::vector<eq::PfsMember> members;
    for (const std::string& name : written.members())
        members.push_back({name, name == files[0] ? dds : written.read(name)});
    const Zone loaded = eq::load_eq_zone(eq::write_pfs(members), "gen.s3d");
    const Material& m = loaded.materials[0];
    ASSERT_EQ(m.name, files[0]);
    ASSERT_TRUE(m.has_pixels());
    EXPECT_EQ(m.width, w);
    EXPECT_EQ(m.height, h);
    EXPECT_EQ(material_rgba(m), decode_dds(dds)->rgba);
    const auto count = std::find_if(loaded.source.counts.begin(), loaded.source.counts.end(),
                                    [](const auto& c) { return c.first == "textures.dds"; });
    ASSERT_NE(count, loaded.source.counts.end());
    EXPECT_EQ(count->second, 1u);

    // A broken DDS is noted with its problem, and the zone still loads.
    for (eq::PfsMember& member : members)
        if (member.name == files[0])
            member.data.resize(kDdsHeaderBytes + 3);
    const Zone broken = eq::load_eq_zone(eq::write_pfs(members), "gen.s3d");
    EXPECT_FALSE(broken.materials[0].has_pixels());
    bool noted = false;
    for (const std::string& note : broken.source.notes)
        noted = noted || note.find("DDS offset 131") != std::string::npos;
    EXPECT_TRUE(noted);
}

} // namespace
} // namespace pvs
