#include "wld/quake2/ibsp38_file.h"

#include "visibility/bit_row.h"
#include "visibility/codec/quake_rle.h"
#include "wld/common/byte_reader.h"

#include <cstring>

namespace pvs::quake2 {

namespace {

const char* const kLumpNames[kIbsp38LumpCount] = {
    "entities", "planes", "vertexes", "visibility", "nodes", "texinfo", "faces", "lighting", "leafs", "leaffaces",
    "leafbrushes", "edges", "surfedges", "models", "brushes", "brushsides", "pop", "areas", "areaportals"};

void read_header(const ByteReader& in, Ibsp38File& f)
{
    in.require(0, 8 + 8 * kIbsp38LumpCount, "the IBSP header");
    const int32_t version = in.read<int32_t>(4, "the version");
    if (std::memcmp(in.bytes(0, 4, "the tag").data(), "IBSP", 4) != 0)
        in.fail(0, "not an IBSP file");
    if (version != 38)
        in.fail(4, version == 46 || version == 47 ? "a Quake 3 IBSP (version " + std::to_string(version) +
                                                        "): only Quake 2's IBSP 38 is read"
                                                  : "IBSP version " + std::to_string(version) + ", not Quake 2's 38");
    for (int l = 0; l < kIbsp38LumpCount; ++l) {
        const uint64_t at = 8 + 8 * uint64_t(l);
        const int32_t offset = in.read<int32_t>(at, "a lump offset"), length = in.read<int32_t>(at + 4, "a lump length");
        if (offset < 0 || length < 0 || uint64_t(offset) + uint64_t(length) > in.size())
            in.fail(at, std::string("the ") + kLumpNames[l] + " lump (offset " + std::to_string(offset) + ", length " +
                            std::to_string(length) + ") lies outside the file");
        f.lumps[l] = {uint32_t(offset), uint32_t(length)};
    }
}

void read_leaves(const ByteReader& in, Ibsp38File& f)
{
    const Ibsp38LumpSpan lump = f.lumps[kQ2LumpLeafs];
    if (lump.length % kQ2LeafBytes != 0)
        in.fail(8 + 8 * kQ2LumpLeafs, "the leafs lump is " + std::to_string(lump.length) +
                                          " bytes, not a whole number of 28-byte leaves");
    f.leaves.resize(lump.length / kQ2LeafBytes);
    for (size_t i = 0; i < f.leaves.size(); ++i) {
        const uint64_t at = lump.offset + i * kQ2LeafBytes;
        f.leaves[i] = {in.read<int32_t>(at, "a leaf's contents"), in.read<int16_t>(at + 4, "a leaf's cluster"),
                       in.read<int16_t>(at + 6, "a leaf's area")};
    }
}

// One row at `offset` bytes into the lump, decoded into `row`; returns its compressed length.
uint32_t read_row(const ByteReader& in, const Ibsp38LumpSpan& lump, uint32_t offset, uint64_t offset_at,
                  uint32_t clusters, std::span<uint64_t> row, const char* what)
{
    if (offset >= lump.length)
        in.fail(offset_at, std::string("a ") + what + " row offset (" + std::to_string(offset) +
                               ") lies outside the visibility lump (" + std::to_string(lump.length) + " bytes)");
    const std::span<const uint8_t> rest = in.bytes(lump.offset + offset, lump.length - offset, "a row");
    const QuakeRleResult r = decode_quake_rle(rest, clusters, row);
    if (!r.complete)
        in.fail(lump.offset + offset, std::string("a ") + what + " row ends before its " + std::to_string(clusters) +
                                          " bits are decoded");
    return uint32_t(r.consumed);
}

void read_visibility(const ByteReader& in, Ibsp38File& f)
{
    const Ibsp38LumpSpan lump = f.lumps[kQ2LumpVisibility];
    if (lump.length == 0)
        return;
    const int32_t clusters = in.read<int32_t>(lump.offset, "the cluster count");
    if (clusters < 0 || clusters > kMaxQ2Clusters || 4 + 8 * uint64_t(clusters) > lump.length)
        in.fail(lump.offset, "the cluster count " + std::to_string(clusters) + " does not fit the visibility lump (" +
                                 std::to_string(lump.length) + " bytes) or Quake 2's limit of " +
                                 std::to_string(kMaxQ2Clusters));
    f.clusters = uint32_t(clusters);
    const size_t words = bits::words_for(f.clusters);
    f.pvs_offsets.resize(f.clusters);
    f.phs_offsets.resize(f.clusters);
    f.pvs_rows.assign(size_t(f.clusters) * words, 0);
    f.phs_rows.assign(size_t(f.clusters) * words, 0);
    f.pvs_lengths.resize(f.clusters);
    f.phs_lengths.resize(f.clusters);
    for (uint32_t c = 0; c < f.clusters; ++c) {
        const uint64_t at = lump.offset + 4 + 8 * uint64_t(c);
        f.pvs_offsets[c] = in.read<uint32_t>(at, "a PVS row offset");
        f.phs_offsets[c] = in.read<uint32_t>(at + 4, "a PHS row offset");
        f.pvs_lengths[c] =
            read_row(in, lump, f.pvs_offsets[c], at, f.clusters, {f.pvs_rows.data() + c * words, words}, "PVS");
        f.phs_lengths[c] =
            read_row(in, lump, f.phs_offsets[c], at + 4, f.clusters, {f.phs_rows.data() + c * words, words}, "PHS");
    }
}

} // namespace

bool looks_like_ibsp38(std::span<const uint8_t> bytes)
{
    if (bytes.size() < 8 || std::memcmp(bytes.data(), "IBSP", 4) != 0)
        return false;
    int32_t version;
    std::memcpy(&version, bytes.data() + 4, 4);
    return version == 38;
}

Ibsp38File read_ibsp38(std::span<const uint8_t> bytes, const std::string& file)
{
    const ByteReader in(bytes, file);
    Ibsp38File f;
    read_header(in, f);
    read_leaves(in, f);
    read_visibility(in, f);
    for (size_t i = 0; i < f.leaves.size(); ++i)
        if (f.leaves[i].cluster >= 0 && f.clusters > 0 && uint32_t(f.leaves[i].cluster) >= f.clusters)
            in.fail(f.lumps[kQ2LumpLeafs].offset + i * kQ2LeafBytes + 4,
                    "leaf " + std::to_string(i) + " names cluster " + std::to_string(f.leaves[i].cluster) + " of " +
                        std::to_string(f.clusters));
    return f;
}

} // namespace pvs::quake2
