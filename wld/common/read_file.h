// Reads a whole file into memory; throws pvs::FileError when it cannot be opened or read (a
// directory included).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace pvs {

std::vector<uint8_t> read_whole_file(const std::string& path);
void write_whole_file(const std::string& path, std::span<const uint8_t> bytes);
// Readers see the old file or the new one, never half of one: the bytes go to a temporary beside
// `path` (same file system, so the rename is atomic), which then replaces it, keeping its
// permissions. Throws FileError naming `path`; the temporary is gone after a failure.
void replace_atomically(const std::string& path, std::span<const uint8_t> bytes);
inline void write_whole_file(const std::string& path, const std::vector<uint8_t>& bytes)
{
    write_whole_file(path, std::span<const uint8_t>(bytes));
}

} // namespace pvs
