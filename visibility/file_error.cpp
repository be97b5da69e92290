#include "visibility/file_error.h"

#include <cstdio>

namespace pvs {

namespace {
std::string format_message(const std::string& file, uint64_t offset, const std::string& reason)
{
    char where[64];
    std::snprintf(where, sizeof where, ": offset %llu (0x%llx): ",
                  static_cast<unsigned long long>(offset), static_cast<unsigned long long>(offset));
    return file + where + reason;
}
} // namespace

FileError::FileError(std::string file, uint64_t offset, std::string reason)
    : std::runtime_error(format_message(file, offset, reason)), file_(std::move(file)), offset_(offset),
      reason_(std::move(reason))
{
}

} // namespace pvs
