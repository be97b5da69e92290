#include "wld/doom/wad_file.h"

#include "wld/common/byte_reader.h"
#include "wld/common/mapped_file.h"
#include "wld/common/read_file.h"

#include <algorithm>
#include <cstdio>
#include <cctype>
#include <cstring>
#include <stdexcept>

namespace pvs::doom {

namespace {

// Two lumps overlap when their byte ranges share a byte, unless they are the very same range
// (one lump listed twice).
void check_overlaps(const WadFile& wad, const ByteReader& reader)
{
    std::vector<size_t> order;
    for (size_t i = 0; i < wad.lumps.size(); ++i)
        if (wad.lumps[i].size > 0)
            order.push_back(i);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        const WadLump &la = wad.lumps[a], &lb = wad.lumps[b];
        return la.offset != lb.offset ? la.offset < lb.offset : a < b;
    });
    for (size_t k = 1; k < order.size(); ++k) {
        const WadLump& prev = wad.lumps[order[k - 1]];
        const WadLump& lump = wad.lumps[order[k]];
        const bool same_bytes = prev.offset == lump.offset && prev.size == lump.size;
        if (!same_bytes && uint64_t(prev.offset) + prev.size > lump.offset)
            reader.fail(lump.directory_offset, "lump " + std::to_string(order[k]) + " '" + lump.name + "' (bytes " +
                                                   std::to_string(lump.offset) + ".." +
                                                   std::to_string(uint64_t(lump.offset) + lump.size) +
                                                   ") overlaps lump '" + prev.name + "' (bytes " +
                                                   std::to_string(prev.offset) + ".." +
                                                   std::to_string(uint64_t(prev.offset) + prev.size) + ")");
    }
}

} // namespace

std::string wad_name(std::span<const uint8_t> raw)
{
    std::string name;
    for (uint8_t c : raw) {
        if (c == 0)
            break;
        name.push_back(char(std::toupper(c)));
    }
    return name;
}

std::string upper_case(std::string name)
{
    for (char& c : name)
        c = char(std::toupper(static_cast<unsigned char>(c)));
    return name;
}

std::optional<size_t> WadFile::find_last(const std::string& name) const
{
    for (size_t i = lumps.size(); i-- > 0;)
        if (lumps[i].name == name)
            return i;
    return std::nullopt;
}

std::optional<size_t> WadFile::find_from(const std::string& name, size_t from) const
{
    for (size_t i = from; i < lumps.size(); ++i)
        if (lumps[i].name == name)
            return i;
    return std::nullopt;
}

bool looks_like_wad(std::span<const uint8_t> bytes)
{
    return bytes.size() >= 4 && (std::memcmp(bytes.data(), "IWAD", 4) == 0 || std::memcmp(bytes.data(), "PWAD", 4) == 0);
}

bool file_looks_like_wad(const std::string& path)
{
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f)
        return false;
    uint8_t magic[4] = {};
    const bool read = std::fread(magic, 1, 4, f) == 4;
    std::fclose(f);
    return read && looks_like_wad(magic);
}

namespace {

WadFile parse_wad_bytes(FileBytes file, std::string path)
{
    WadFile wad;
    wad.path = std::move(path);
    wad.bytes = file.bytes;
    wad.storage = std::move(file.storage);
    const ByteReader reader(wad.bytes, wad.path);
    reader.require(0, 12, "WAD header");
    if (!looks_like_wad(wad.bytes))
        reader.fail(0, "not a WAD: the file does not start with \"IWAD\" or \"PWAD\"");
    wad.iwad = wad.bytes[0] == 'I';
    const int32_t count = reader.read<int32_t>(4, "WAD lump count");
    const int32_t directory = reader.read<int32_t>(8, "WAD directory offset");
    if (count < 0)
        reader.fail(4, "negative lump count " + std::to_string(count));
    if (directory < 0)
        reader.fail(8, "negative directory offset " + std::to_string(directory));
    reader.require(uint64_t(directory), uint64_t(count) * 16, "WAD directory");
    wad.lumps.resize(size_t(count));
    for (int32_t i = 0; i < count; ++i) {
        const uint64_t at = uint64_t(directory) + uint64_t(i) * 16;
        WadLump& lump = wad.lumps[size_t(i)];
        lump.name = wad_name(reader.bytes(at + 8, 8, "lump name"));
        lump.directory_offset = uint32_t(at);
        const int32_t offset = reader.read<int32_t>(at, "lump offset");
        const int32_t size = reader.read<int32_t>(at + 4, "lump size");
        if (offset < 0 || size < 0)
            reader.fail(at, "lump " + std::to_string(i) + " '" + lump.name + "' has a negative offset or size");
        if (uint64_t(offset) + uint64_t(size) > wad.bytes.size())
            reader.fail(at, "lump " + std::to_string(i) + " '" + lump.name + "' (" + std::to_string(size) +
                                " bytes at " + std::to_string(offset) + ") runs past the end of the file (" +
                                std::to_string(wad.bytes.size()) + " bytes)");
        lump.offset = uint32_t(offset);
        lump.size = uint32_t(size);
    }
    check_overlaps(wad, reader);
    return wad;
}

} // namespace

WadFile parse_wad(std::vector<uint8_t> bytes, std::string path)
{
    auto buffer = std::make_shared<std::vector<uint8_t>>(std::move(bytes));
    return parse_wad_bytes({std::span<const uint8_t>(*buffer), buffer}, std::move(path));
}

WadFile read_wad(const std::string& path) { return parse_wad_bytes(map_whole_file(path), path); }

std::vector<uint8_t> write_wad(bool iwad, std::span<const WadLumpData> lumps)
{
    std::vector<uint8_t> out(12, 0);
    std::memcpy(out.data(), iwad ? "IWAD" : "PWAD", 4);
    std::vector<uint32_t> offsets;
    offsets.reserve(lumps.size());
    for (const WadLumpData& lump : lumps) {
        if (lump.name.size() > 8)
            throw std::invalid_argument("WAD lump name longer than 8 characters: " + lump.name);
        while (out.size() % 4 != 0)
            out.push_back(0);
        offsets.push_back(uint32_t(out.size()));
        out.insert(out.end(), lump.bytes.begin(), lump.bytes.end());
    }
    while (out.size() % 4 != 0)
        out.push_back(0);
    const auto put32 = [&](size_t at, uint32_t v) { std::memcpy(out.data() + at, &v, 4); };
    put32(4, uint32_t(lumps.size()));
    put32(8, uint32_t(out.size()));
    for (size_t i = 0; i < lumps.size(); ++i) {
        const size_t at = out.size();
        out.resize(at + 16, 0);
        put32(at, offsets[i]);
        put32(at + 4, uint32_t(lumps[i].bytes.size()));
        std::memcpy(out.data() + at + 8, lumps[i].name.data(), lumps[i].name.size());
    }
    return out;
}

} // namespace pvs::doom
