#include "wld/eq/wld_material.h"

#include "wld/eq/wld_body.h"
#include "wld/eq/wld_string_hash.h"

#include <stdexcept>

namespace pvs::eq {

namespace {

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
    WldByteWriter w;
    w.put(bitmap.name_ref);
    w.put(wld_count32(bitmap.files, "0x03 names") - 1);
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
    def.frames = r.fragment_refs(frame_count, "frame reference", kWldBitmapName);
    return def;
}

std::vector<uint8_t> write_sprite_def(const WldSpriteDef& def)
{
    WldByteWriter w;
    w.put(def.name_ref);
    w.put(def.flags);
    w.put_count(def.frames, "0x04 frames");
    if (def.flags & kWldSpriteDefCurrentFrame)
        w.put(def.current_frame);
    if (has_sleep(def.flags))
        w.put(def.sleep);
    w.put_each(def.frames);
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
    WldByteWriter w;
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
    WldByteWriter w;
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
    const uint32_t count = r.count("material count", 4);
    palette.materials = r.fragment_refs(count, "material reference", kWldMaterial);
    return palette;
}

std::vector<uint8_t> write_material_palette(const WldMaterialPalette& palette)
{
    WldByteWriter w;
    w.put(palette.name_ref);
    w.put(palette.flags);
    w.put_count(palette.materials, "0x31 materials");
    w.put_each(palette.materials);
    return w.finish();
}

// ---- Resolving ----

uint32_t material_fragment_of(const WldFile& wld, uint32_t palette_fragment, uint32_t material_index)
{
    const WldMaterialPalette palette = parse_material_palette(wld, palette_fragment);
    if (material_index >= palette.materials.size())
        throw std::out_of_range("material index " + std::to_string(material_index) + " is past the palette (" +
                                wld_fragment_label(palette_fragment, kWldMaterialPalette) + " has " +
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
