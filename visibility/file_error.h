// The one exception type for bad input files.
//
// Every loader and decoder of untrusted bytes reports a problem by throwing FileError, which
// names the file (or archive member), the byte offset where the problem was found, and what
// is wrong. Hot paths never throw; they return plain values. Library code never exits.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace pvs {

class FileError : public std::runtime_error {
public:
    FileError(std::string file, uint64_t offset, std::string reason);

    const std::string& file() const { return file_; }
    uint64_t offset() const { return offset_; }
    const std::string& reason() const { return reason_; }

private:
    std::string file_;
    uint64_t offset_;
    std::string reason_;
};

} // namespace pvs
