#include "wld/doom/doom_textures.h"

#include "visibility/file_error.h"
#include "wld/common/byte_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <span>

namespace pvs::doom {

namespace {

using Palette = std::array<uint8_t, 768>;

// The composition budget (see the header): generous for real textures, which write each texel
// a few times, and small enough that garbage (say, thousands of patches whose columns all
// point at one long run of empty posts) is stopped within a second or so.
constexpr uint64_t kStepsPerTexel = 32;
constexpr uint64_t kBaseSteps = uint64_t(1) << 22;

// A reader with absolute file offsets (for the messages) whose data ends where the lump ends,
// so a read past the lump fails like a read past the file. Reads never start before the lump:
// every offset below is the lump's own offset plus something non-negative.
ByteReader lump_reader(const WadFile& wad, size_t lump)
{
    const WadLump& entry = wad.lumps[lump];
    return ByteReader(std::span<const uint8_t>(wad.bytes).first(size_t(entry.offset) + entry.size), wad.path);
}

// Runs `body`; a FileError from it comes back with `context` before its reason, so the
// message names the lump (and texture) being read, not only the offset.
template <class Body>
decltype(auto) in_context(const std::string& context, Body&& body)
{
    try {
        return body();
    } catch (const FileError& e) {
        throw FileError(e.file(), e.offset(), context + ": " + e.reason());
    }
}

void put_texel(uint8_t* out, const Palette& palette, uint8_t index)
{
    const uint8_t* rgb = palette.data() + 3 * size_t(index);
    out[0] = rgb[0];
    out[1] = rgb[1];
    out[2] = rgb[2];
    out[3] = 255;
}

std::optional<Palette> read_palette(const WadFile& wad)
{
    const std::optional<size_t> lump = wad.find_last("PLAYPAL");
    if (!lump)
        return std::nullopt;
    const ByteReader reader = lump_reader(wad, *lump);
    const std::span<const uint8_t> first =
        in_context("PLAYPAL", [&] { return reader.bytes(wad.lumps[*lump].offset, 768, "first palette"); });
    Palette palette;
    std::copy(first.begin(), first.end(), palette.begin());
    return palette;
}

// Flats by name, the last of a name winning. Ranges may repeat (F_START..F_END, then a PWAD's
// FF_START..FF_END); size-0 lumps inside are nested markers (F1_START, ...).
std::unordered_map<std::string, size_t> index_flats(const WadFile& wad)
{
    std::unordered_map<std::string, size_t> flats;
    bool inside = false;
    for (size_t i = 0; i < wad.lumps.size(); ++i) {
        const WadLump& lump = wad.lumps[i];
        if (lump.name == "F_START" || lump.name == "FF_START")
            inside = true;
        else if (lump.name == "F_END" || lump.name == "FF_END")
            inside = false;
        else if (inside && lump.size > 0)
            flats[lump.name] = i;
    }
    return flats;
}

// PNAMES index -> patch lump (nullopt when no lump has the name). One map of the last lump of
// each name answers what find_last would, without a directory scan per name.
std::vector<std::optional<size_t>> resolve_patch_names(const WadFile& wad)
{
    const std::optional<size_t> lump = wad.find_last("PNAMES");
    if (!lump)
        return {};
    std::unordered_map<std::string, size_t> last_of_name;
    for (size_t i = 0; i < wad.lumps.size(); ++i)
        last_of_name[wad.lumps[i].name] = i;
    return in_context("PNAMES", [&] {
        const ByteReader reader = lump_reader(wad, *lump);
        const uint64_t base = wad.lumps[*lump].offset;
        const int32_t count = reader.read<int32_t>(base, "name count");
        if (count < 0)
            reader.fail(base, "negative name count " + std::to_string(count));
        reader.require(base + 4, uint64_t(count) * 8, "names");
        std::vector<std::optional<size_t>> patches;
        patches.reserve(size_t(count));
        for (int32_t k = 0; k < count; ++k) {
            const auto found = last_of_name.find(wad_name(reader.bytes(base + 4 + uint64_t(k) * 8, 8, "name")));
            patches.push_back(found == last_of_name.end() ? std::nullopt : std::optional<size_t>(found->second));
        }
        return patches;
    });
}

// Side of a square flat of `size` bytes, or 0 when the size is not a square up to the limit.
uint32_t flat_side(size_t size)
{
    auto side = uint64_t(std::sqrt(double(size)));
    while (side * side > size)
        --side;
    while ((side + 1) * (side + 1) <= size)
        ++side;
    return side * side == size && side <= kMaxDoomTextureSide ? uint32_t(side) : 0;
}

// One wall texture being composed: the picture so far and what is left of the step budget.
class Canvas {
public:
    Canvas(uint32_t width, uint32_t height, const Palette& palette)
        : palette_(palette), steps_left_(kStepsPerTexel * width * height + kBaseSteps)
    {
        image_.width = width;
        image_.height = height;
        image_.rgba.assign(size_t(width) * height * 4, 0); // all transparent until a post covers it
    }

    // Draws the patch in `lump` with its top-left corner at (origin_x, origin_y), clipped.
    void draw_patch(const WadFile& wad, size_t lump, int64_t origin_x, int64_t origin_y)
    {
        const ByteReader reader = lump_reader(wad, lump);
        const uint64_t base = wad.lumps[lump].offset;
        reader.require(base, 8, "patch header");
        const int16_t width = reader.read<int16_t>(base, "patch width");
        if (width < 0)
            reader.fail(base, "negative patch width " + std::to_string(width));
        reader.require(base + 8, uint64_t(width) * 4, "column offsets");
        // Only the columns that land inside the texture are read.
        const int64_t first = std::max<int64_t>(0, -origin_x);
        const int64_t end = std::min<int64_t>(width, int64_t(image_.width) - origin_x);
        for (int64_t x = first; x < end; ++x) {
            const uint32_t column = reader.read<uint32_t>(base + 8 + uint64_t(x) * 4, "column offset");
            draw_column(reader, base + column, origin_x + x, origin_y);
        }
    }

    DoomImage take() { return std::move(image_); }

private:
    void draw_column(const ByteReader& reader, uint64_t at, int64_t x, int64_t origin_y)
    {
        int64_t top = -1;
        for (;;) { // ends: each post moves `at` on by at least 4 bytes, and reads stay in the lump
            spend(1, reader, at);
            const uint8_t delta = reader.read<uint8_t>(at, "post top delta");
            if (delta == 0xFF)
                return;
            top = delta <= top ? top + delta : delta; // DeePsea tall patches: relative to the last post
            if (origin_y + top >= int64_t(image_.height))
                return; // tops never decrease, so no later post reaches the texture either
            const uint8_t length = reader.read<uint8_t>(at + 1, "post length");
            draw_post(reader, at, x, origin_y + top, reader.bytes(at + 3, length, "post texels"));
            at += 4 + uint64_t(length);
        }
    }

    // Texels of one post from row y_top down, clipped to the texture's rows.
    void draw_post(const ByteReader& reader, uint64_t at, int64_t x, int64_t y_top, std::span<const uint8_t> texels)
    {
        const int64_t y0 = std::max<int64_t>(y_top, 0);
        const int64_t y1 = std::min<int64_t>(y_top + int64_t(texels.size()), image_.height);
        if (y0 >= y1)
            return;
        spend(uint64_t(y1 - y0), reader, at);
        const size_t stride = size_t(image_.width) * 4;
        uint8_t* out = image_.rgba.data() + size_t(y0) * stride + size_t(x) * 4;
        for (int64_t y = y0; y < y1; ++y, out += stride)
            put_texel(out, palette_, texels[size_t(y - y_top)]);
    }

    void spend(uint64_t steps, const ByteReader& reader, uint64_t at)
    {
        if (steps > steps_left_)
            reader.fail(at, "composing the texture takes more than " +
                                std::to_string(kStepsPerTexel * image_.width * image_.height + kBaseSteps) +
                                " steps (posts and texels): the patches are garbage");
        steps_left_ -= steps;
    }

    const Palette& palette_;
    uint64_t steps_left_;
    DoomImage image_;
};

// Composes the maptexture record at `at` in texture lump `lump` (its name already known).
DoomImage compose(const WadFile& wad, size_t lump, uint64_t at, const Palette& palette,
                  const std::vector<std::optional<size_t>>& patches)
{
    const ByteReader reader = lump_reader(wad, lump);
    reader.require(at, 22, "texture record");
    const int16_t width = reader.read<int16_t>(at + 12, "texture width");
    const int16_t height = reader.read<int16_t>(at + 14, "texture height");
    if (width < 1 || height < 1 || uint32_t(width) > kMaxDoomTextureSide || uint32_t(height) > kMaxDoomTextureSide)
        reader.fail(at + 12, "texture size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1.." +
                                 std::to_string(kMaxDoomTextureSide));
    const int16_t count = reader.read<int16_t>(at + 20, "patch count");
    if (count < 0)
        reader.fail(at + 20, "negative patch count " + std::to_string(count));
    reader.require(at + 22, uint64_t(count) * 10, "patch records");
    Canvas canvas(uint32_t(width), uint32_t(height), palette);
    for (int16_t k = 0; k < count; ++k) {
        const uint64_t record = at + 22 + uint64_t(k) * 10;
        const int16_t index = reader.read<int16_t>(record + 4, "patch index");
        if (index < 0 || size_t(index) >= patches.size())
            reader.fail(record + 4, "patch index " + std::to_string(index) + " is outside PNAMES (" +
                                        std::to_string(patches.size()) + " names)");
        const std::optional<size_t> patch = patches[size_t(index)];
        if (!patch)
            continue; // no lump of that name: better the texture without it than no texture
        const int16_t origin_x = reader.read<int16_t>(record, "patch origin x");
        const int16_t origin_y = reader.read<int16_t>(record + 2, "patch origin y");
        in_context("patch '" + wad.lumps[*patch].name + "'",
                   [&] { canvas.draw_patch(wad, *patch, origin_x, origin_y); });
    }
    return canvas.take();
}

} // namespace

DoomTextures::DoomTextures(const WadFile& wad) : wad_(wad)
{
    if (const std::optional<Palette> palette = read_palette(wad)) {
        has_palette_ = true;
        palette_ = *palette;
    }
    flats_ = index_flats(wad);
    patches_ = resolve_patch_names(wad);
    for (const char* directory : {"TEXTURE1", "TEXTURE2"}) // TEXTURE1 first: its names win
        if (const std::optional<size_t> lump = wad.find_last(directory))
            in_context(directory, [&] { index_textures(wad, *lump, textures_); });
}

void DoomTextures::index_textures(const WadFile& wad, size_t lump, std::unordered_map<std::string, TextureRecord>& out)
{
    const ByteReader reader = lump_reader(wad, lump);
    const uint64_t base = wad.lumps[lump].offset;
    const int32_t count = reader.read<int32_t>(base, "texture count");
    if (count < 0)
        reader.fail(base, "negative texture count " + std::to_string(count));
    reader.require(base + 4, uint64_t(count) * 4, "texture offsets");
    for (int32_t k = 0; k < count; ++k) {
        const uint64_t entry = base + 4 + uint64_t(k) * 4;
        const int32_t offset = reader.read<int32_t>(entry, "texture offset");
        if (offset < 0)
            reader.fail(entry, "negative texture offset " + std::to_string(offset));
        const uint64_t at = base + uint64_t(offset);
        out.try_emplace(wad_name(reader.bytes(at, 8, "texture name")), TextureRecord{lump, at});
    }
}

std::optional<DoomImage> DoomTextures::flat(const std::string& name) const
{
    const auto found = flats_.find(upper_case(name));
    if (!has_palette_ || found == flats_.end())
        return std::nullopt;
    const std::span<const uint8_t> raw = wad_.data(found->second);
    const uint32_t side = flat_side(raw.size());
    if (side == 0)
        return std::nullopt;
    DoomImage image;
    image.width = image.height = side;
    image.rgba.resize(raw.size() * 4);
    for (size_t i = 0; i < raw.size(); ++i)
        put_texel(image.rgba.data() + i * 4, palette_, raw[i]);
    return image;
}

std::optional<DoomImage> DoomTextures::wall(const std::string& name) const
{
    const auto found = textures_.find(upper_case(name));
    if (!has_palette_ || found == textures_.end())
        return std::nullopt;
    const TextureRecord& record = found->second;
    return in_context("texture '" + found->first + "' in " + wad_.lumps[record.lump].name,
                      [&] { return compose(wad_, record.lump, record.offset, palette_, patches_); });
}

namespace {

template <class Map>
std::vector<std::string> sorted_keys(const Map& map)
{
    std::vector<std::string> names;
    names.reserve(map.size());
    for (const auto& entry : map)
        names.push_back(entry.first);
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace

std::vector<std::string> DoomTextures::flat_names() const { return sorted_keys(flats_); }
std::vector<std::string> DoomTextures::wall_names() const { return sorted_keys(textures_); }

} // namespace pvs::doom
