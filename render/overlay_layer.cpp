#include "render/overlay_layer.h"

namespace pvs::ui {

void clear_layer(Image& layer, uint32_t width, uint32_t height)
{
    layer.width = width;
    layer.height = height;
    layer.rgba.assign(size_t(width) * height * 4, 0);
}

Image new_layer(uint32_t width, uint32_t height)
{
    Image layer;
    clear_layer(layer, width, height);
    return layer;
}

bool composite_layer(const Image& layer, Image& picture)
{
    if (layer.width != picture.width || layer.height != picture.height || layer.rgba.size() != picture.rgba.size())
        return false;
    const uint8_t* from = layer.rgba.data();
    uint8_t* to = picture.rgba.data();
    for (size_t i = 0; i < layer.rgba.size(); i += 4) {
        const uint32_t alpha = from[i + 3];
        if (alpha == 0)
            continue;
        blend_over(to + i, uint32_t(from[i]) << 16 | uint32_t(from[i + 1]) << 8 | from[i + 2], alpha);
    }
    return true;
}

} // namespace pvs::ui
