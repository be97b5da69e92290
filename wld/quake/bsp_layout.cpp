#include "wld/quake/bsp_layout.h"

#include <cstring>

namespace pvs::quake {

const char* bsp_variant_name(BspVariant variant)
{
    switch (variant) {
    case BspVariant::Bsp29: return "BSP 29";
    case BspVariant::Bsp2: return "BSP2";
    case BspVariant::Bsp2Rmq: return "2PSB";
    }
    return "?";
}

BspLayout bsp_layout(BspVariant variant)
{
    BspLayout l;
    l.variant = variant;
    if (variant == BspVariant::Bsp29)
        return l;
    l.wide = true;
    l.face_size = 28;
    l.clipnode_size = 12;
    l.edge_size = 8;
    l.marksurface_size = 4;
    l.face_side = 4;
    l.face_first_edge = 8;
    l.face_edge_count = 12;
    l.face_texinfo = 16;
    l.face_styles = 20;
    l.face_light = 24;
    l.node_bounds = 12;
    if (variant == BspVariant::Bsp2) {
        l.float_bounds = true;
        l.node_size = 44;
        l.leaf_size = 44;
        l.node_first_face = 36;
        l.node_face_count = 40;
        l.leaf_first_marksurface = 32;
        l.leaf_marksurface_count = 36;
        l.leaf_ambient = 40;
    } else {
        l.node_size = 32;
        l.leaf_size = 32;
        l.node_first_face = 24;
        l.node_face_count = 28;
        l.leaf_first_marksurface = 20;
        l.leaf_marksurface_count = 24;
        l.leaf_ambient = 28;
    }
    return l;
}

std::optional<BspVariant> detect_bsp_variant(std::span<const uint8_t> bytes)
{
    if (bytes.size() < 4)
        return std::nullopt;
    if (std::memcmp(bytes.data(), "BSP2", 4) == 0)
        return BspVariant::Bsp2;
    if (std::memcmp(bytes.data(), "2PSB", 4) == 0)
        return BspVariant::Bsp2Rmq;
    int32_t version;
    std::memcpy(&version, bytes.data(), 4);
    if (version == 29)
        return BspVariant::Bsp29;
    return std::nullopt;
}

std::string describe_bsp_header(std::span<const uint8_t> bytes)
{
    if (bytes.size() < 4)
        return "too short for a header";
    if (const auto variant = detect_bsp_variant(bytes))
        return bsp_variant_name(*variant);
    if (std::memcmp(bytes.data(), "IBSP", 4) == 0 || std::memcmp(bytes.data(), "RBSP", 4) == 0) {
        if (bytes.size() < 8)
            return "an IBSP tag without a version";
        int32_t version;
        std::memcpy(&version, bytes.data() + 4, 4);
        const char* game = version == 38 ? "Quake 2 " : version == 46 || version == 47 ? "Quake 3 " : "";
        return std::string(game) + (bytes[0] == 'R' ? "RBSP" : "IBSP") + " version " + std::to_string(version);
    }
    int32_t version;
    std::memcpy(&version, bytes.data(), 4);
    if (version == 30)
        return "Half-Life BSP 30";
    return "version " + std::to_string(version);
}

} // namespace pvs::quake
