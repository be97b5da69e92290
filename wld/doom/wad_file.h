// The WAD container of Doom-engine games (../shared/formats/quake-doom-hepvs.md §4.1): a 12-byte
// header ("IWAD"/"PWAD", lump count, directory offset) and a directory of 16-byte entries
// (offset, size, 8-character name). A .gwa (glBSP's GL nodes beside a WAD) is a PWAD.
//
// Contract. read_wad checks everything a later read relies on, once, and throws FileError naming
// the file, the offset and the lump: a header or directory past the end, a negative or
// past-the-end lump, two lumps with data that overlap (size-0 markers never overlap; several
// entries naming the very same bytes, as some tools write for identical lumps, are allowed).
// After that, WadFile::data(i) is a span of lump i's bytes that is always inside the file.
// Names are upper-cased and end at the first NUL or after 8 characters. Lookups that follow
// the engines (the last lump of a name wins) are find_last; map lumps are found relative to
// their marker (doom_map.h).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace pvs::doom {

struct WadLump {
    std::string name; // upper case, at most 8 characters
    uint32_t offset = 0;
    uint32_t size = 0;
    uint32_t directory_offset = 0; // where this entry sits in the file (for error messages)
};

struct WadFile {
    std::string path;
    bool iwad = false;
    std::span<const uint8_t> bytes;       // the whole file
    std::shared_ptr<const void> storage;  // what holds `bytes` (a mapping, or the buffer parsed)
    std::vector<WadLump> lumps;

    std::span<const uint8_t> data(size_t lump) const
    {
        return std::span<const uint8_t>(bytes).subspan(lumps[lump].offset, lumps[lump].size);
    }
    // Index of the last lump named `name` (upper case), or nullopt.
    std::optional<size_t> find_last(const std::string& name) const;
    // Index of the first lump named `name` at or after `from`, or nullopt.
    std::optional<size_t> find_from(const std::string& name, size_t from) const;
};

// Parses a WAD held in memory (`path` names it in errors). Throws FileError.
WadFile parse_wad(std::vector<uint8_t> bytes, std::string path);
// Reads and parses a WAD or .gwa file (mapped: only the pages of the lumps read are read; see
// wld/common/mapped_file.h). Throws FileError.
WadFile read_wad(const std::string& path);

// A name field of a WAD (lump, texture, flat: 8 bytes): upper case, ending at the first NUL or
// after the field. upper_case: any name in upper case (WAD names compare case-insensitively).
std::string wad_name(std::span<const uint8_t> raw);
std::string upper_case(std::string name);

// True when the bytes start like a WAD ("IWAD" or "PWAD").
bool looks_like_wad(std::span<const uint8_t> bytes);
// The same for a file, reading only its first 4 bytes (false when it cannot be read).
bool file_looks_like_wad(const std::string& path);

// A lump to write: its name (at most 8 characters) and bytes.
struct WadLumpData {
    std::string name;
    std::vector<uint8_t> bytes;
};
// A whole WAD file: header, lumps back to back (each at a 4-byte aligned offset, as glBSP writes
// them), directory at the end. Throws std::invalid_argument for a name longer than 8 characters.
std::vector<uint8_t> write_wad(bool iwad, std::span<const WadLumpData> lumps);

} // namespace pvs::doom
