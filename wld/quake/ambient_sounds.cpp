#include "wld/quake/ambient_sounds.h"

#include "visibility/bit_row.h"
#include "wld/quake/bsp_lumps.h"

#include <cctype>
#include <cstring>
#include <stdexcept>

namespace pvs::quake {

namespace {

constexpr uint8_t kNoChannel = 0xFF;

bool has_prefix(const char* name, size_t length, const char* prefix)
{
    const size_t n = std::strlen(prefix);
    if (length < n)
        return false;
    for (size_t i = 0; i < n; ++i)
        if (std::tolower(static_cast<unsigned char>(name[i])) != prefix[i])
            return false;
    return true;
}

// The channel a texture name feeds (vis's order: sky, water, slime, lava), or kNoChannel.
uint8_t channel_of(const char* name, size_t length, const AmbientOptions& o)
{
    if (o.sky && has_prefix(name, length, "sky"))
        return kAmbientSky;
    if (o.water && (has_prefix(name, length, "*water") || has_prefix(name, length, "*04water")))
        return kAmbientWater;
    if (o.slime && has_prefix(name, length, "*slime"))
        return kAmbientWater; // vis's slime goes to the water channel
    if (o.lava && has_prefix(name, length, "*lava"))
        return kAmbientLava;
    return kNoChannel;
}

uint32_t read_count(const ByteReader& in, const BspLayout& layout, uint64_t at, const char* what)
{
    return layout.wide ? in.read<uint32_t>(at, what) : in.read<uint16_t>(at, what);
}

int64_t read_index(const ByteReader& in, const BspLayout& layout, uint64_t at, const char* what)
{
    return layout.wide ? int64_t{in.read<int32_t>(at, what)} : int64_t{in.read<int16_t>(at, what)};
}

// The channel of each miptex (kNoChannel for an unnamed or unused one).
std::vector<uint8_t> miptex_channels(const ByteReader& in, const BspLumps& bsp, const AmbientOptions& o)
{
    const BspLumpSpan& lump = bsp.lumps[kLumpTextures];
    if (lump.length < 4)
        return {};
    const auto count = in.read<int32_t>(lump.offset, "miptex count");
    if (count < 0 || uint64_t(count) > (lump.length - 4) / 4)
        in.fail(lump.offset, "miptex count " + std::to_string(count) + " does not fit the texture lump");
    std::vector<uint8_t> channels(size_t(count), kNoChannel);
    for (int32_t i = 0; i < count; ++i) {
        const uint64_t dir_at = lump.offset + 4 + 4 * uint64_t(i);
        const auto ofs = in.read<int32_t>(dir_at, "miptex offset");
        if (ofs < 0)
            continue; // a texture qbsp could not find: no name
        if (uint64_t(ofs) + 16 > lump.length)
            in.fail(dir_at, "miptex " + std::to_string(i) + " offset is outside the texture lump");
        const auto name = in.bytes(lump.offset + uint64_t(ofs), 16, "miptex name");
        const char* text = reinterpret_cast<const char*>(name.data());
        channels[size_t(i)] = channel_of(text, strnlen(text, 16), o);
    }
    return channels;
}

// Per face, the channel its texture feeds.
std::vector<uint8_t> face_channels(const ByteReader& in, const BspLumps& bsp, const std::vector<uint8_t>& miptex)
{
    std::vector<uint8_t> channels(bsp.lumps[kLumpFaces].count, kNoChannel);
    for (uint32_t f = 0; f < channels.size(); ++f) {
        const uint64_t at = bsp.record(kLumpFaces, f) + bsp.layout.face_texinfo;
        const int64_t texinfo = read_index(in, bsp.layout, at, "face texinfo");
        bsp.check_index(in, kLumpTexinfo, texinfo, at, "face texinfo");
        const uint64_t mt_at = bsp.record(kLumpTexinfo, uint32_t(texinfo)) + 32;
        const auto mt = in.read<int32_t>(mt_at, "texinfo miptex");
        if (mt >= 0 && size_t(mt) < miptex.size())
            channels[f] = miptex[size_t(mt)];
    }
    return channels;
}

uint32_t world_visleafs(const ByteReader& in, const BspLumps& bsp)
{
    if (bsp.lumps[kLumpModels].count == 0)
        in.fail(bsp.lumps[kLumpModels].offset, "the models lump is empty: no world model");
    const uint64_t at = bsp.record(kLumpModels, 0) + 52;
    const auto visleafs = in.read<int32_t>(at, "model visleafs");
    if (visleafs < 0 || uint64_t(visleafs) >= bsp.lumps[kLumpLeafs].count)
        in.fail(at, "world visleafs " + std::to_string(visleafs) + " does not fit the leafs lump (" +
                        std::to_string(bsp.lumps[kLumpLeafs].count) + " leaves)");
    return uint32_t(visleafs);
}

// Per vis leaf (region r = leaf r+1), the channels its marksurfaces feed, as bits.
std::vector<uint8_t> leaf_channel_bits(const ByteReader& in, const BspLumps& bsp, uint32_t visleafs,
                                       const std::vector<uint8_t>& faces)
{
    std::vector<uint8_t> bits_of(visleafs, 0);
    const BspLayout& l = bsp.layout;
    for (uint32_t r = 0; r < visleafs; ++r) {
        const uint64_t at = bsp.record(kLumpLeafs, r + 1);
        const uint32_t first = read_count(in, l, at + l.leaf_first_marksurface, "leaf firstmarksurface");
        const uint32_t count = read_count(in, l, at + l.leaf_marksurface_count, "leaf nummarksurfaces");
        if (uint64_t{first} + count > bsp.lumps[kLumpMarksurfaces].count)
            in.fail(at + l.leaf_first_marksurface,
                    "leaf " + std::to_string(r + 1) + " marksurface range is outside the lump");
        for (uint32_t k = 0; k < count; ++k) {
            const uint64_t ms_at = bsp.record(kLumpMarksurfaces, first + k);
            const uint32_t face = read_count(in, l, ms_at, "marksurface");
            bsp.check_index(in, kLumpFaces, face, ms_at, "marksurface face");
            if (faces[face] != kNoChannel)
                bits_of[r] |= uint8_t(1u << faces[face]);
        }
    }
    return bits_of;
}

} // namespace

std::vector<AmbientLevels> compute_ambient_levels(std::span<const uint8_t> bytes, const Pvs& pvs,
                                                  const AmbientOptions& options, const std::string& file)
{
    const ByteReader in(bytes, file);
    const BspLumps bsp = read_bsp_lumps(in);
    const uint32_t visleafs = world_visleafs(in, bsp);
    if (pvs.row_count() != visleafs || pvs.region_count() != visleafs)
        throw std::invalid_argument("the PVS has " + std::to_string(pvs.row_count()) + " rows of " +
                                    std::to_string(pvs.region_count()) + " bits; " + file + " has " +
                                    std::to_string(visleafs) + " vis leaves");
    const std::vector<uint8_t> leaf_bits =
        leaf_channel_bits(in, bsp, visleafs, face_channels(in, bsp, miptex_channels(in, bsp, options)));
    std::vector<AmbientLevels> levels(visleafs, AmbientLevels{0, 0, 0, 0});
    std::vector<uint64_t> row(pvs.words_per_row());
    for (uint32_t r = 0; r < visleafs; ++r) {
        pvs.decode_row(r, row);
        uint8_t heard = 0;
        bits::for_each_set(std::span<const uint64_t>(row), [&](size_t j) {
            if (j < visleafs)
                heard |= leaf_bits[j];
        });
        for (uint32_t c = 0; c < 4; ++c)
            levels[r][c] = (heard >> c) & 1 ? 255 : 0;
    }
    return levels;
}

std::vector<uint8_t> with_ambient_levels(std::span<const uint8_t> bytes, std::span<const AmbientLevels> levels,
                                         const std::string& file)
{
    const ByteReader in(bytes, file);
    const BspLumps bsp = read_bsp_lumps(in);
    const uint32_t visleafs = world_visleafs(in, bsp);
    if (levels.size() != visleafs)
        throw std::invalid_argument("ambient levels for " + std::to_string(levels.size()) + " leaves, " +
                                    std::to_string(visleafs) + " vis leaves in " + file);
    std::vector<uint8_t> out(bytes.begin(), bytes.end());
    for (uint32_t r = 0; r < visleafs; ++r) {
        const uint64_t at = bsp.record(kLumpLeafs, r + 1) + bsp.layout.leaf_ambient;
        in.require(at, 4, "leaf ambient levels");
        std::memcpy(out.data() + at, levels[r].data(), 4);
    }
    return out;
}

std::vector<AmbientLevels> read_ambient_levels(std::span<const uint8_t> bytes, const std::string& file)
{
    const ByteReader in(bytes, file);
    const BspLumps bsp = read_bsp_lumps(in);
    const uint32_t visleafs = world_visleafs(in, bsp);
    std::vector<AmbientLevels> levels(visleafs);
    for (uint32_t r = 0; r < visleafs; ++r) {
        const auto b = in.bytes(bsp.record(kLumpLeafs, r + 1) + bsp.layout.leaf_ambient, 4, "leaf ambient levels");
        std::memcpy(levels[r].data(), b.data(), 4);
    }
    return levels;
}

} // namespace pvs::quake
