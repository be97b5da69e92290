#include "render/image.h"

// The implementation is compiled here, with static linkage, so another module that also wants
// stb_image_write (or links Debian's libstb) cannot collide with it.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace pvs::ui {

void save_png(const Image& image, const std::string& path)
{
    if (image.width == 0 || image.height == 0 || image.rgba.size() != size_t(image.width) * image.height * 4)
        throw std::runtime_error("cannot write " + path + ": the image is empty or its size is inconsistent");
    if (image.width > 0x7FFFFFFFu / 4 || image.height > 0x7FFFFFFFu)
        throw std::runtime_error("cannot write " + path + ": the image is too large for PNG output");
    if (!stbi_write_png(path.c_str(), int(image.width), int(image.height), 4, image.rgba.data(), int(image.width * 4)))
        throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
}

} // namespace pvs::ui
