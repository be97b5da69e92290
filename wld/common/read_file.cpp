#include "wld/common/read_file.h"

#include "visibility/file_error.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace pvs {

std::vector<uint8_t> read_whole_file(const std::string& path)
{
    // A directory opens as a stream on Linux and reports a size of 2^63 - 1.
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw FileError(path, 0, "is a directory, not a file");
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in)
        throw FileError(path, 0, std::string("cannot open: ") + std::strerror(errno));
    const std::streamoff size = in.tellg();
    if (size < 0)
        throw FileError(path, 0, "cannot determine the file size");
    std::vector<uint8_t> bytes(static_cast<size_t>(size));
    in.seekg(0);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), size))
        throw FileError(path, 0, "read failed");
    return bytes;
}

void write_whole_file(const std::string& path, std::span<const uint8_t> bytes)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out)
        throw FileError(path, 0, std::string("cannot create: ") + std::strerror(errno));
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.close(); // flushes: a full disk shows here, not silently in the destructor
    if (!out)
        throw FileError(path, 0, "write failed (" + std::string(std::strerror(errno)) + ")");
}

void replace_atomically(const std::string& path, std::span<const uint8_t> bytes)
{
    const std::string temporary = path + ".tmp" + std::to_string(::getpid());
    std::error_code ec;
    try {
        write_whole_file(temporary, bytes);
    } catch (...) {
        std::filesystem::remove(temporary, ec);
        throw;
    }
    if (const std::filesystem::file_status old = std::filesystem::status(path, ec); !ec && std::filesystem::exists(old))
        std::filesystem::permissions(temporary, old.permissions(), ec); // a rewrite should not change who may read it
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw FileError(path, 0, "cannot replace the file: " + ec.message());
    }
}

} // namespace pvs
