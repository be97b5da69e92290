#include "render/colour_codes.h"

namespace pvs::ui {

uint32_t region_color(uint32_t region)
{
    // splitmix32-style finaliser: neighbouring ids get unrelated colours.
    uint32_t h = region * 0x9E3779B9u + 0x7F4A7C15u;
    h = (h ^ (h >> 16)) * 0x85EBCA6Bu;
    h = (h ^ (h >> 13)) * 0xC2B2AE35u;
    h ^= h >> 16;
    auto channel = [](uint32_t bits) { return ((24 + bits % 104) << 1) | 1; }; // odd, 49 .. 255
    return channel(h & 0x3FF) << 16 | channel((h >> 10) & 0x3FF) << 8 | channel(h >> 20);
}

} // namespace pvs::ui
