#include "wld/eq/dds_decode.h"

#include "visibility/shared_library.h"

#include <squish.h>

#include <cstring>

#ifndef PVSCOPE_SQUISH_SONAME
#error "PVSCOPE_SQUISH_SONAME (libsquish's soname) comes from wld/CMakeLists.txt"
#endif

namespace pvs {

namespace {

constexpr uint32_t kHeaderSize = 124;
constexpr uint32_t kPixelFormatSize = 32;
constexpr uint32_t kPixelFormatFourCC = 0x4; // DDPF_FOURCC

uint32_t u32_at(std::span<const uint8_t> bytes, size_t at)
{
    return uint32_t(bytes[at]) | uint32_t(bytes[at + 1]) << 8 | uint32_t(bytes[at + 2]) << 16 |
           uint32_t(bytes[at + 3]) << 24;
}

std::string printable(std::span<const uint8_t> four)
{
    std::string out;
    for (const uint8_t c : four)
        out += (c >= 0x20 && c < 0x7F) ? char(c) : '?';
    return out;
}

// squish::DecompressImage(rgba, width, height, blocks, flags), from libsquish opened on first use
// (not linked: it brings OpenMP's runtime into every process, and only an EverQuest zone with
// DDS textures decodes one). By its mangled name: the library exports C++ only.
using DecompressImage = void (*)(squish::u8*, int, int, const void*, int);

struct LoadedSquish {
    DecompressImage decompress = nullptr;
    std::string error;
};

const LoadedSquish& squish_library()
{
    static const LoadedSquish loaded = [] {
        constexpr const char* kWhat = "libsquish";
        LoadedSquish out;
        if (void* library = open_shared_library(PVSCOPE_SQUISH_SONAME, kWhat, "libsquish0", out.error))
            out.decompress = reinterpret_cast<DecompressImage>(shared_library_symbol(
                library, PVSCOPE_SQUISH_SONAME, kWhat, "_ZN6squish15DecompressImageEPhiiPKvi", out.error));
        return out;
    }();
    return loaded;
}

// The squish flag of the FourCC at offset 84; 0 when it is not one we decode.
int squish_format(std::span<const uint8_t> bytes)
{
    const std::span<const uint8_t> four = bytes.subspan(84, 4);
    if (std::memcmp(four.data(), "DXT1", 4) == 0)
        return squish::kDxt1;
    if (std::memcmp(four.data(), "DXT3", 4) == 0)
        return squish::kDxt3;
    if (std::memcmp(four.data(), "DXT5", 4) == 0)
        return squish::kDxt5;
    return 0;
}

std::optional<RgbaImage> refuse(std::string* why, size_t offset, const std::string& problem)
{
    if (why)
        *why = "DDS offset " + std::to_string(offset) + ": " + problem;
    return std::nullopt;
}

} // namespace

bool looks_like_dds(std::span<const uint8_t> bytes)
{
    return bytes.size() >= 4 && std::memcmp(bytes.data(), "DDS ", 4) == 0;
}

std::optional<RgbaImage> decode_dds(std::span<const uint8_t> bytes, std::string* why)
{
    if (!looks_like_dds(bytes))
        return refuse(why, 0, "no magic \"DDS \"");
    if (bytes.size() < kDdsHeaderBytes)
        return refuse(why, bytes.size(),
                      "the header needs " + std::to_string(kDdsHeaderBytes) + " bytes, the file has " +
                          std::to_string(bytes.size()));
    if (const uint32_t size = u32_at(bytes, 4); size != kHeaderSize)
        return refuse(why, 4, "header size " + std::to_string(size) + " is not 124");
    const uint32_t height = u32_at(bytes, 12), width = u32_at(bytes, 16);
    if (height == 0 || height > kMaxDdsSide)
        return refuse(why, 12, "height " + std::to_string(height) + " is not in 1.." + std::to_string(kMaxDdsSide));
    if (width == 0 || width > kMaxDdsSide)
        return refuse(why, 16, "width " + std::to_string(width) + " is not in 1.." + std::to_string(kMaxDdsSide));
    if (const uint32_t size = u32_at(bytes, 76); size != kPixelFormatSize)
        return refuse(why, 76, "pixel format size " + std::to_string(size) + " is not 32");
    if ((u32_at(bytes, 80) & kPixelFormatFourCC) == 0)
        return refuse(why, 80, "the pixel format has no FourCC (uncompressed DDS is not decoded)");
    const int format = squish_format(bytes);
    if (format == 0)
        return refuse(why, 84, "FourCC '" + printable(bytes.subspan(84, 4)) + "' is not DXT1, DXT3 or DXT5");

    const uint64_t blocks = uint64_t{(width + 3) / 4} * ((height + 3) / 4);
    const uint64_t data_bytes = blocks * (format == squish::kDxt1 ? 8 : 16);
    if (bytes.size() - kDdsHeaderBytes < data_bytes)
        return refuse(why, bytes.size(),
                      std::to_string(width) + "x" + std::to_string(height) + " needs " + std::to_string(data_bytes) +
                          " bytes of blocks after offset 128, the file has " +
                          std::to_string(bytes.size() - kDdsHeaderBytes));
    const LoadedSquish& squish = squish_library();
    if (!squish.decompress)
        return refuse(why, 0, squish.error);
    RgbaImage image;
    image.width = width;
    image.height = height;
    image.rgba.resize(size_t{width} * height * 4);
    squish.decompress(image.rgba.data(), int(width), int(height), bytes.data() + kDdsHeaderBytes, format);
    return image;
}

} // namespace pvs
