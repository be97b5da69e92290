#include "wld/eq/wld_material.h"

#include "visibility/file_error.h"
#include "wld/eq/wld_string_hash.h"

#include <cstdio>
#include <limits>
#include <stdexcept>

namespace pvs::eq {

// ---- Internal reader and writer ----

namespace detail {

namespace {

std::string hex(uint32_t value)
{
    char text[16];
    std::snprintf(text, sizeof text, "0x%02X", value);
    return text;
}

std::string indexed(const char* what, int64_t index)
{
    return index < 0 ? std::string(what) : std::string(what) + " " + std::to_string(index);
}

std::string type_label(uint32_t type)
{
    const char* name = wld_fragment_type_name(type);
    return hex(type) + (*name ? " " : "") + name;
}

} // namespace

std::string wld_fragment_label(uint32_t number, uint32_t type)
{
    return "fragment " + std::to_string(number) + " (" + type_label(type) + ")";
}

WldBodyReader::WldBodyReader(const WldFile& wld, uint32_t number, uint32_t expected_type)
    : wld_(wld), number_(number), type_(expected_type)
{
    if (number == 0 || number > wld.fragments.size())
        throw std::out_of_range("WLD fragment " + std::to_string(number) + " does not exist (the file has " +
                                std::to_string(wld.fragments.size()) + ")");
    const WldFragment& f = wld.fragments[number - 1];
    type_ = f.type;
    body_offset_ = f.body_offset;
    body_size_ = f.body_size;
    if (f.type != expected_type)
        fail(f.body_offset - kWldFragmentHeaderSize + 4, "expected a " + type_label(expected_type) + " fragment");
    // parse_wld checked this; a hand-made WldFile may not have been.
    if (f.body_offset > wld.bytes.size() || f.body_size > wld.bytes.size() - f.body_offset)
        fail(f.body_offset, "fragment body runs past the end of the data (" + std::to_string(f.body_size) +
                                " bytes needed)");
}

void WldBodyReader::fail(uint64_t offset, const std::string& reason) const
{
    throw FileError(wld_.name, offset, wld_fragment_label(number_, type_) + ": " + reason);
}

std::span<const uint8_t> WldBodyReader::bytes(uint64_t length, const char* what, int64_t index)
{
    if (length > left())
        fail(at(), indexed(what, index) + " runs past the end of the fragment (" + std::to_string(length) +
                       " bytes needed, " + std::to_string(left()) + " left)");
    const auto span = wld_.bytes.subspan(at(), length);
    pos_ += length;
    return span;
}

glm::vec3 WldBodyReader::vec3(const char* what, int64_t index)
{
    const auto x = read<float>(what, index);
    const auto y = read<float>(what, index);
    const auto z = read<float>(what, index);
    return {x, y, z};
}

void WldBodyReader::check_count(uint64_t count, uint64_t count_at, uint64_t min_bytes, const char* what,
                                int64_t index) const
{
    // count < 2^33 and min_bytes < 2^8 here: the product cannot overflow.
    if (count * min_bytes > left())
        fail(count_at, indexed(what, index) + " " + std::to_string(count) + " does not fit in the fragment (" +
                           std::to_string(left()) + " bytes left, at least " + std::to_string(min_bytes) +
                           " per element)");
}

int32_t WldBodyReader::fragment_ref(const char* what, uint32_t target_type, int64_t index)
{
    const uint64_t ref_at = at();
    const auto ref = read<int32_t>(what, index);
    const std::string name = indexed(what, index) + " " + std::to_string(ref);
    if (ref > 0 && uint32_t(ref) > wld_.fragments.size())
        fail(ref_at, name + " is out of range (the file has " + std::to_string(wld_.fragments.size()) +
                         " fragments)");
    if (ref > 0 && uint32_t(ref) >= number_)
        fail(ref_at, name + " is a forward reference (it must name an earlier fragment)");
    if (ref > 0 && target_type != 0 && wld_.fragments[uint32_t(ref) - 1].type != target_type) {
        const uint32_t type = wld_.fragments[uint32_t(ref) - 1].type;
        fail(ref_at, name + " names " + wld_fragment_label(uint32_t(ref), type) + ", not a " +
                         type_label(target_type));
    }
    if (ref < 0 && !wld_string_at(wld_.strings, ref))
        fail(ref_at, name + " names a string outside the string hash (" + std::to_string(wld_.strings.size()) +
                         " bytes)");
    return ref;
}

std::vector<uint8_t> WldBodyWriter::finish()
{
    out_.resize((out_.size() + 3) / 4 * 4, 0);
    return std::move(out_);
}

} // namespace detail

using detail::WldBodyReader;
using detail::WldBodyWriter;

namespace {

template <class Container>
uint32_t count32(const Container& items, const char* what)
{
    if (items.size() > std::numeric_limits<uint32_t>::max())
        throw std::invalid_argument(std::string(what) + ": more than 2^32 - 1 elements");
    return static_cast<uint32_t>(items.size());
}

// LQ/QL read the "sleep" field when both bits are set (ZU/WQ on bit 0x08 alone).
bool has_sleep(uint32_t flags)
{
    return (flags & kWldSpriteDefAnimated) && (flags & kWldSpriteDefBit4);
}

} // namespace

// ---- 0x03 ----

WldBitmapName parse_bitmap_name(const WldFile& wld, uint32_t number)
{
    WldBodyReader r(wld, number, kWldBitmapName);
    WldBitmapName bitmap;
    bitmap.name_ref = r.read<int32_t>("name_ref");
    const uint64_t count_at = r.at();
    // LQ/QL: the stored count is names - 1 ([D] ZU/WQ: names, 0 read as 1). In 64 bits, so
    // 0xFFFFFFFF asks for 2^32 names instead of wrapping to none.
    const auto stored = r.read<uint32_t>("name count");
    const uint64_t names = uint64_t{stored} + 1;
    if (names * 2 > r.left())
        r.fail(count_at, "name count " + std::to_string(stored) + " (" + std::to_string(names) +
                             " names) does not fit in the fragment (" + std::to_string(r.left()) +
                             " bytes left, at least 2 per name)");
    bitmap.files.reserve(names);
    for (uint64_t i = 0; i < names; ++i) {
        const auto index = static_cast<int64_t>(i);
        const auto length = r.read<uint16_t>("name length", index);
        bitmap.files.push_back(decode_wld_string(r.bytes(length, "name", index)));
    }
    return bitmap;
}

std::vector<uint8_t> write_bitmap_name(const WldBitmapName& bitmap)
{
    if (bitmap.files.empty())
        throw std::invalid_argument("0x03 bitmap name: at least one file name is needed (count = names - 1)");
    WldBodyWriter w;
    w.put(bitmap.name_ref);
    w.put(count32(bitmap.files, "0x03 names") - 1);
    for (const std::string& file : bitmap.files) {
        const std::vector<uint8_t> encoded = encode_wld_string(file); // throws for a NUL inside
        if (encoded.size() > 0xFFFF)
            throw std::invalid_argument("0x03 file name of " + std::to_string(file.size()) +
                                        " bytes: the length (NUL included) is a u16");
        w.put(static_cast<uint16_t>(encoded.size()));
        w.put_bytes(encoded);
    }
    return w.finish();
}

// ---- 0x04 ----

WldSpriteDef parse_sprite_def(const WldFile& wld, uint32_t number)
{
    WldBodyReader r(wld, number, kWldSpriteDef);
    WldSpriteDef def;
    def.name_ref = r.read<int32_t>("name_ref");
    def.flags = r.read<uint32_t>("flags");
    const uint64_t count_at = r.at();
    const auto frame_count = r.read<uint32_t>("frame_count");
    if (def.flags & kWldSpriteDefCurrentFrame)
        def.current_frame = r.read<uint32_t>("current_frame");
    if (has_sleep(def.flags))
        def.sleep = r.read<uint32_t>("sleep");
    r.check_count(frame_count, count_at, 4, "frame_count");
    def.frames.reserve(frame_count);
    for (uint32_t i = 0; i < frame_count; ++i)
        def.frames.push_back(r.fragment_ref("frame reference", kWldBitmapName, i));
    return def;
}

std::vector<uint8_t> write_sprite_def(const WldSpriteDef& def)
{
    WldBodyWriter w;
    w.put(def.name_ref);
    w.put(def.flags);
    w.put(count32(def.frames, "0x04 frames"));
    if (def.flags & kWldSpriteDefCurrentFrame)
        w.put(def.current_frame);
    if (has_sleep(def.flags))
        w.put(def.sleep);
    for (const int32_t frame : def.frames)
        w.put(frame);
    return w.finish();
}

// ---- 0x05 ----

WldSprite parse_sprite(const WldFile& wld, uint32_t number)
{
    WldBodyReader r(wld, number, kWldSprite);
    WldSprite sprite;
    sprite.name_ref = r.read<int32_t>("name_ref");
    sprite.sprite_def_ref = r.fragment_ref("sprite_def_ref", kWldSpriteDef);
    sprite.flags = r.read<uint32_t>("flags");
    return sprite;
}

std::vector<uint8_t> write_sprite(const WldSprite& sprite)
{
    WldBodyWriter w;
    w.put(sprite.name_ref);
    w.put(sprite.sprite_def_ref);
    w.put(sprite.flags);
    return w.finish();
}

// ---- 0x30 ----

WldMaterial parse_material(const WldFile& wld, uint32_t number)
{
    WldBodyReader r(wld, number, kWldMaterial);
    WldMaterial m;
    m.name_ref = r.read<int32_t>("name_ref");
    m.flags = r.read<uint32_t>("flags");
    m.render_method = r.read<uint32_t>("render_method");
    m.rgb_pen = r.read<uint32_t>("rgb_pen");
    m.brightness = r.read<float>("brightness");
    m.scaled_ambient = r.read<float>("scaled_ambient");
    // LQ/WQ: always here. [D] ZU skips 8 more bytes first when flags == 0.
    m.sprite_ref = r.fragment_ref("sprite_ref", kWldSprite);
    if (m.flags & kWldMaterialPair) {
        m.pair_value = r.read<uint32_t>("pair value");
        m.pair_factor = r.read<float>("pair factor");
    }
    return m;
}

std::vector<uint8_t> write_material(const WldMaterial& m)
{
    WldBodyWriter w;
    w.put(m.name_ref);
    w.put(m.flags);
    w.put(m.render_method);
    w.put(m.rgb_pen);
    w.put(m.brightness);
    w.put(m.scaled_ambient);
    w.put(m.sprite_ref);
    if (m.flags & kWldMaterialPair) {
        w.put(m.pair_value);
        w.put(m.pair_factor);
    }
    return w.finish();
}

WldRenderMethod decode_render_method(uint32_t raw)
{
    WldRenderMethod rm;
    rm.raw = raw;
    rm.user_defined = (raw & 0x80000000u) != 0;
    rm.draw_style = static_cast<uint8_t>(raw & 0x3);
    rm.lighting = static_cast<uint8_t>((raw >> 2) & 0x7);
    rm.shading = static_cast<uint8_t>((raw >> 5) & 0x3);
    rm.texture_style = static_cast<uint8_t>((raw >> 7) & 0xF);
    if (rm.user_defined) {
        rm.material_type = raw & 0x7FFFFFFFu;
        switch (rm.material_type) {
        case 0x00: rm.type = WldMaterialType::Boundary; break;
        case 0x01:
        case 0x02:
        case 0x12:
        case 0x14:
        case 0x15:
        case 0x19:
        case 0x31:
        case 0x553: rm.type = WldMaterialType::Diffuse; break;
        case 0x05:
            rm.type = WldMaterialType::Transparent;
            rm.opacity_percent = 50;
            break;
        case 0x09:
            rm.type = WldMaterialType::Transparent;
            rm.opacity_percent = 25;
            break;
        case 0x0A:
            rm.type = WldMaterialType::Transparent;
            rm.opacity_percent = 75;
            break;
        case 0x07: rm.type = WldMaterialType::TransparentMaskedPassable; break;
        case 0x13: rm.type = WldMaterialType::TransparentMasked; break;
        case 0x0B: rm.type = WldMaterialType::TransparentAdditiveUnlit; break;
        case 0x17: rm.type = WldMaterialType::TransparentAdditive; break;
        case 0x0D:
        case 0x0F:
        case 0x10: rm.type = WldMaterialType::SkyDome; break;
        case 0x03:
        case 0x4B:
        case 0x53: rm.type = WldMaterialType::Invisible; break;
        default: rm.type = WldMaterialType::Unknown; break;
        }
    }
    rm.drawn = (raw & 0x7FFFFFFFu) != 0 && rm.type != WldMaterialType::Boundary &&
               rm.type != WldMaterialType::Invisible;
    switch (rm.type) {
    case WldMaterialType::Transparent:
    case WldMaterialType::TransparentMasked:
    case WldMaterialType::TransparentMaskedPassable:
    case WldMaterialType::TransparentAdditive:
    case WldMaterialType::TransparentAdditiveUnlit: rm.transparent = true; break;
    default: break;
    }
    return rm;
}

// ---- 0x31 ----

WldMaterialPalette parse_material_palette(const WldFile& wld, uint32_t number)
{
    WldBodyReader r(wld, number, kWldMaterialPalette);
    WldMaterialPalette palette;
    palette.name_ref = r.read<int32_t>("name_ref");
    palette.flags = r.read<uint32_t>("flags");
    const uint64_t count_at = r.at();
    const auto count = r.read<uint32_t>("material count");
    r.check_count(count, count_at, 4, "material count");
    palette.materials.reserve(count);
    for (uint32_t i = 0; i < count; ++i)
        palette.materials.push_back(r.fragment_ref("material reference", kWldMaterial, i));
    return palette;
}

std::vector<uint8_t> write_material_palette(const WldMaterialPalette& palette)
{
    WldBodyWriter w;
    w.put(palette.name_ref);
    w.put(palette.flags);
    w.put(count32(palette.materials, "0x31 materials"));
    for (const int32_t ref : palette.materials)
        w.put(ref);
    return w.finish();
}

// ---- Resolving ----

uint32_t material_fragment_of(const WldFile& wld, uint32_t palette_fragment, uint32_t material_index)
{
    const WldMaterialPalette palette = parse_material_palette(wld, palette_fragment);
    if (material_index >= palette.materials.size())
        throw std::out_of_range("material index " + std::to_string(material_index) + " is past the palette (" +
                                detail::wld_fragment_label(palette_fragment, kWldMaterialPalette) + " has " +
                                std::to_string(palette.materials.size()) + " materials)");
    return resolve_fragment_ref(wld, palette.materials[material_index]);
}

std::string texture_file_of(const WldFile& wld, uint32_t palette_fragment, uint32_t material_index)
{
    // Each step parses its fragment with the typed parser, so a by-name reference that lands
    // on the wrong type fails there ("expected a 0x05 sprite fragment"). The types differ at
    // every step: the chain cannot loop.
    const uint32_t material = material_fragment_of(wld, palette_fragment, material_index);
    if (material == 0)
        return {};
    const uint32_t sprite = resolve_fragment_ref(wld, parse_material(wld, material).sprite_ref);
    if (sprite == 0)
        return {};
    const uint32_t sprite_def = resolve_fragment_ref(wld, parse_sprite(wld, sprite).sprite_def_ref);
    if (sprite_def == 0)
        return {};
    const WldSpriteDef def = parse_sprite_def(wld, sprite_def);
    if (def.frames.empty())
        return {};
    const uint32_t bitmap = resolve_fragment_ref(wld, def.frames.front());
    if (bitmap == 0)
        return {};
    return parse_bitmap_name(wld, bitmap).files.front(); // the parser always gives at least one
}

bool material_is_visible(const WldFile& wld, uint32_t palette_fragment, uint32_t material_index)
{
    const uint32_t number = material_fragment_of(wld, palette_fragment, material_index);
    if (number == 0)
        return false;
    const WldMaterial material = parse_material(wld, number);
    return material.sprite_ref != 0 && decode_render_method(material.render_method).drawn;
}

} // namespace pvs::eq
