// A whole file as read-only bytes, mapped rather than copied: a map of a 28 MB WAD reads only the
// pages its lumps touch (a copy read every byte and doubled the process's memory). Falls back to
// reading the file when it cannot be mapped (an empty file, a pipe).
//
// Contract. map_whole_file throws pvs::FileError when the file cannot be opened or read. The bytes
// stay valid while a copy of `storage` lives, even when the file is replaced or deleted meanwhile
// (writers here replace files by renaming a new one over them). A file truncated in place by
// another process while mapped is outside this contract (reading past its new end faults).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>

namespace pvs {

struct FileBytes {
    std::span<const uint8_t> bytes;
    std::shared_ptr<const void> storage; // the mapping, or the buffer read
};

FileBytes map_whole_file(const std::string& path);

} // namespace pvs
