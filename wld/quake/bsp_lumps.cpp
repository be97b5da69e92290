#include "wld/quake/bsp_lumps.h"

#include <algorithm>

namespace pvs::quake {

namespace {

constexpr const char* kNames[kBspLumpCount] = {"entities", "planes", "textures", "vertexes", "visibility",
                                               "nodes", "texinfo", "faces", "lighting", "clipnodes",
                                               "leafs", "marksurfaces", "edges", "surfedges", "models"};

} // namespace

const char* bsp_lump_name(BspLump lump) { return lump >= 0 && lump < kBspLumpCount ? kNames[lump] : "?"; }

uint32_t BspLumps::record_size(BspLump lump) const
{
    switch (lump) {
    case kLumpPlanes: return 20;
    case kLumpVertexes: return 12;
    case kLumpNodes: return layout.node_size;
    case kLumpTexinfo: return 40;
    case kLumpFaces: return layout.face_size;
    case kLumpClipnodes: return layout.clipnode_size;
    case kLumpLeafs: return layout.leaf_size;
    case kLumpMarksurfaces: return layout.marksurface_size;
    case kLumpEdges: return layout.edge_size;
    case kLumpSurfedges: return 4;
    case kLumpModels: return 64;
    default: return 1; // entities, textures, visibility, lighting: bytes
    }
}

void BspLumps::check_index(const ByteReader& in, BspLump lump, int64_t index, uint64_t at, const char* what) const
{
    if (index < 0 || index >= lumps[lump].count)
        in.fail(at, std::string(what) + " " + std::to_string(index) + " is out of range (the " + kNames[lump] +
                        " lump has " + std::to_string(lumps[lump].count) + ")");
}

BspLumps read_bsp_lumps(const ByteReader& in)
{
    in.require(0, 4, "header version");
    const std::span<const uint8_t> head = in.bytes(0, std::min<uint64_t>(in.size(), 8), "header");
    const auto variant = detect_bsp_variant(head);
    if (!variant)
        in.fail(0, "not a Quake BSP (29, BSP2 or 2PSB): the header says " + describe_bsp_header(head));
    BspLumps bsp;
    bsp.layout = bsp_layout(*variant);
    in.require(0, 4 + 8 * kBspLumpCount, "header");
    for (int i = 0; i < kBspLumpCount; ++i) {
        const uint64_t at = 4 + 8 * uint64_t(i);
        const auto ofs = in.read<int32_t>(at, "lump offset");
        const auto len = in.read<int32_t>(at + 4, "lump length");
        if (ofs < 0 || len < 0)
            in.fail(at, std::string(kNames[i]) + " lump has a negative offset or length");
        in.require(uint64_t(ofs), uint64_t(len), (std::string(kNames[i]) + " lump").c_str());
        const uint32_t size = bsp.record_size(BspLump(i));
        if (uint32_t(len) % size != 0)
            in.fail(at + 4, std::string(kNames[i]) + " lump length " + std::to_string(len) +
                                " is not a multiple of its " + bsp_variant_name(*variant) + " record size " +
                                std::to_string(size));
        bsp.lumps[i] = {uint64_t(ofs), uint64_t(len), uint32_t(uint32_t(len) / size)};
    }
    return bsp;
}

} // namespace pvs::quake
