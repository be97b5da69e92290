#include "wld/eq/stb_image_io.h"

#include <cstring>
#include <stdexcept>
#include <string>

// stb's implementation lives in this translation unit only, with nothing but its BMP code.
#define STBI_ONLY_BMP
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_MAX_DIMENSIONS 16384
#define STB_IMAGE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#define STB_IMAGE_WRITE_IMPLEMENTATION
// Installed under /usr/include, stb is a system header and GCC already keeps quiet about it;
// these are what our flags raise when it is found through a plain -I path instead.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

static_assert(STBI_MAX_DIMENSIONS == pvs::kMaxBmpSide, "stb's limit is the documented one");

namespace pvs {

namespace {

uint32_t le32(std::span<const uint8_t> b, size_t at)
{
    return uint32_t{b[at]} | uint32_t{b[at + 1]} << 8 | uint32_t{b[at + 2]} << 16 | uint32_t{b[at + 3]} << 24;
}

// Checks what stb would allocate against what the file holds: stb allocates width * height *
// 4 bytes from the header before it reads a pixel. An uncompressed BMP (the only kind stb
// reads) holds at least width * height * bits / 8 bytes of pixels, so a header asking for more
// than the file can hold is refused before stb sees it.
bool plausible_size(std::span<const uint8_t> bytes, int width, int height, std::string& why)
{
    if (bytes.size() < 30) {
        why = "too short for a BMP header";
        return false;
    }
    const uint32_t header_size = le32(bytes, 14);
    const size_t bpp_at = header_size == 12 ? 24 : 28;
    const uint32_t bpp = uint32_t{bytes[bpp_at]} | uint32_t{bytes[bpp_at + 1]} << 8;
    const uint64_t pixel_bits = uint64_t(width) * uint64_t(height) * (bpp == 0 ? 1 : bpp);
    if (pixel_bits / 8 > bytes.size()) {
        why = std::to_string(width) + "x" + std::to_string(height) + " at " + std::to_string(bpp) +
              " bits needs more bytes than the file's " + std::to_string(bytes.size());
        return false;
    }
    return true;
}

void append_bytes(void* context, void* data, int size)
{
    auto* out = static_cast<std::vector<uint8_t>*>(context);
    const auto* p = static_cast<const uint8_t*>(data);
    out->insert(out->end(), p, p + size);
}

} // namespace

std::optional<RgbaImage> decode_bmp(std::span<const uint8_t> bytes, std::string* why)
{
    std::string reason;
    const auto fail = [&](std::string text) -> std::optional<RgbaImage> {
        if (why)
            *why = std::move(text);
        return std::nullopt;
    };
    if (bytes.size() > size_t{1} << 30)
        return fail("larger than 1 GiB");
    const int length = static_cast<int>(bytes.size());
    int width = 0, height = 0, channels = 0;
    if (bytes.size() < 2 || bytes[0] != 'B' || bytes[1] != 'M')
        return fail("not a BMP (no 'BM' signature)");
    if (!stbi_info_from_memory(bytes.data(), length, &width, &height, &channels))
        return fail(stbi_failure_reason());
    if (width <= 0 || height <= 0 || uint32_t(width) > kMaxBmpSide || uint32_t(height) > kMaxBmpSide)
        return fail("unsupported size " + std::to_string(width) + "x" + std::to_string(height));
    if (!plausible_size(bytes, width, height, reason))
        return fail(reason);
    stbi_uc* pixels = stbi_load_from_memory(bytes.data(), length, &width, &height, &channels, 4);
    if (!pixels)
        return fail(stbi_failure_reason());
    RgbaImage image;
    image.width = uint32_t(width);
    image.height = uint32_t(height);
    image.rgba.assign(pixels, pixels + size_t(image.width) * image.height * 4);
    stbi_image_free(pixels);
    return image;
}

std::vector<uint8_t> encode_bmp(uint32_t width, uint32_t height, std::span<const uint8_t> rgba)
{
    if (width == 0 || height == 0 || width > kMaxBmpSide || height > kMaxBmpSide)
        throw std::invalid_argument("encode_bmp: unsupported size " + std::to_string(width) + "x" +
                                    std::to_string(height));
    const size_t pixels = size_t{width} * height;
    if (rgba.size() != pixels * 4)
        throw std::invalid_argument("encode_bmp: " + std::to_string(rgba.size()) + " bytes for " +
                                    std::to_string(width) + "x" + std::to_string(height) + " RGBA pixels");
    std::vector<uint8_t> rgb(pixels * 3);
    for (size_t i = 0; i < pixels; ++i)
        std::memcpy(&rgb[3 * i], &rgba[4 * i], 3);
    std::vector<uint8_t> out;
    if (!stbi_write_bmp_to_func(append_bytes, &out, int(width), int(height), 3, rgb.data()))
        throw std::invalid_argument("encode_bmp: stb could not write the image");
    return out;
}

} // namespace pvs
