#include "wld/common/mapped_file.h"

#include "wld/common/read_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <vector>

namespace pvs {

namespace {

struct Mapping {
    void* address = nullptr;
    size_t size = 0;
    ~Mapping() { munmap(address, size); }
};

FileBytes read_instead(const std::string& path)
{
    auto buffer = std::make_shared<std::vector<uint8_t>>(read_whole_file(path));
    return {std::span<const uint8_t>(*buffer), buffer};
}

} // namespace

FileBytes map_whole_file(const std::string& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return read_instead(path); // read_whole_file throws the FileError with the reason
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size <= 0) {
        ::close(fd);
        return read_instead(path);
    }
    const size_t size = size_t(st.st_size);
    void* address = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    ::close(fd);
    if (address == MAP_FAILED)
        return read_instead(path);
    auto mapping = std::make_shared<Mapping>();
    mapping->address = address;
    mapping->size = size;
    return {std::span<const uint8_t>(static_cast<const uint8_t*>(address), size), mapping};
}

} // namespace pvs
