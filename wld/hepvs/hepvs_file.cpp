#include "wld/hepvs/hepvs_file.h"

#include "wld/common/byte_reader.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace pvs {

namespace {

void read_header(const ByteReader& in, HepvsFile& out)
{
    in.require(0, kHepvsHeaderBytes, "the 28-byte header");
    out.version = in.read<uint32_t>(0, "version");
    if (out.version < 1)
        in.fail(0, "version 0: a .hepvs starts with version 1 or later");
    if (out.version != 1)
        out.warnings.push_back("version " + std::to_string(out.version) + ": read as version 1");
    for (int a = 0; a < 3; ++a)
        out.min[a] = in.read<float>(4 + 4 * uint64_t(a), "min");
    out.cell_size = in.read<float>(16, "cell size");
    if (!std::isfinite(out.min.x) || !std::isfinite(out.min.y) || !std::isfinite(out.min.z))
        in.fail(4, "the grid's min corner is not a finite number");
    if (!(out.cell_size > 0.0f) || !std::isfinite(out.cell_size))
        in.fail(16, "cell size " + std::to_string(out.cell_size) + " is not a positive number");
    for (int a = 0; a < 3; ++a) {
        out.counts[a] = in.read<uint16_t>(20 + 2 * uint64_t(a), "cell count");
        if (out.counts[a] == 0)
            in.fail(20 + 2 * uint64_t(a), std::string("cell count ") + "xyz"[a] + " is 0");
    }
}

uint64_t read_names(const ByteReader& in, uint64_t at, uint16_t count, HepvsFile& out)
{
    out.names.reserve(count);
    for (uint32_t i = 0; i < count; ++i) {
        const uint16_t length = in.read<uint16_t>(at, "name length");
        const std::span<const uint8_t> text = in.bytes(at + 2, length, "object name");
        out.names.emplace_back(reinterpret_cast<const char*>(text.data()), text.size());
        at += 2 + uint64_t(length);
    }
    return at;
}

uint64_t read_cells(const ByteReader& in, uint64_t at, HepvsFile& out)
{
    // Every cell takes at least its 2-byte count: a header declaring more cells than the bytes
    // left could hold is refused before anything is reserved for them (65535^3 cells would ask
    // for terabytes).
    const uint64_t cells = out.cell_count();
    const uint64_t left = at <= in.size() ? in.size() - at : 0;
    if (cells > left / 2)
        in.fail(20, std::to_string(out.counts.x) + " x " + std::to_string(out.counts.y) + " x " +
                        std::to_string(out.counts.z) + " cells need at least " + std::to_string(2 * cells) +
                        " bytes, " + std::to_string(left) + " left after the names");
    out.cell_offsets.reserve(cells + 1);
    out.cell_offsets.push_back(0);
    for (uint64_t c = 0; c < cells; ++c) {
        const uint16_t count = in.read<uint16_t>(at, "cell object count");
        const std::span<const uint8_t> raw = in.bytes(at + 2, 2 * uint64_t(count), "cell object indices");
        for (uint16_t k = 0; k < count; ++k) {
            uint16_t index;
            std::memcpy(&index, raw.data() + 2 * k, 2);
            if (index >= out.names.size())
                in.fail(at + 2 + 2 * uint64_t(k), "cell " + std::to_string(c) + " lists object " +
                                                      std::to_string(index) + " of " +
                                                      std::to_string(out.names.size()));
            out.cell_objects.push_back(index);
        }
        at += 2 + 2 * uint64_t(count);
        out.cell_offsets.push_back(uint32_t(out.cell_objects.size()));
    }
    return at;
}

void put16(std::vector<uint8_t>& out, uint32_t v)
{
    out.push_back(uint8_t(v & 0xff));
    out.push_back(uint8_t(v >> 8));
}

void put32(std::vector<uint8_t>& out, uint32_t v)
{
    for (int i = 0; i < 4; ++i)
        out.push_back(uint8_t(v >> (8 * i)));
}

void put_float(std::vector<uint8_t>& out, float f)
{
    uint32_t v;
    std::memcpy(&v, &f, 4);
    put32(out, v);
}

} // namespace

HepvsFile read_hepvs(std::span<const uint8_t> bytes, const std::string& file)
{
    const ByteReader in(bytes, file);
    HepvsFile out;
    read_header(in, out);
    const uint16_t object_count = in.read<uint16_t>(26, "object count");
    uint64_t at = read_names(in, kHepvsHeaderBytes, object_count, out);
    at = read_cells(in, at, out);
    if (at != bytes.size())
        in.fail(at, std::to_string(bytes.size() - at) + " bytes after the last cell (a .hepvs ends with its "
                                                        "last cell; is the header really 28 bytes?)");
    return out;
}

std::vector<uint8_t> write_hepvs(const HepvsFile& h)
{
    if (h.names.size() > 0xffff)
        throw std::invalid_argument(".hepvs: " + std::to_string(h.names.size()) + " objects, at most 65535");
    for (int a = 0; a < 3; ++a)
        if (h.counts[a] == 0 || h.counts[a] > 0xffff)
            throw std::invalid_argument(".hepvs: a cell count is outside 1 .. 65535");
    if (h.cell_offsets.size() != h.cell_count() + 1 || h.cell_offsets.back() != h.cell_objects.size())
        throw std::invalid_argument(".hepvs: the cell offsets do not describe the cells");
    std::vector<uint8_t> out;
    put32(out, h.version);
    put_float(out, h.min.x);
    put_float(out, h.min.y);
    put_float(out, h.min.z);
    put_float(out, h.cell_size);
    for (int a = 0; a < 3; ++a)
        put16(out, h.counts[a]);
    put16(out, uint32_t(h.names.size()));
    for (const std::string& name : h.names) {
        if (name.size() > 0xffff)
            throw std::invalid_argument(".hepvs: an object name is longer than 65535 bytes");
        put16(out, uint32_t(name.size()));
        out.insert(out.end(), name.begin(), name.end());
    }
    for (uint64_t c = 0; c < h.cell_count(); ++c) {
        const std::span<const uint16_t> objects = h.cell(uint32_t(c));
        if (objects.size() > 0xffff)
            throw std::invalid_argument(".hepvs: a cell lists more than 65535 objects");
        put16(out, uint32_t(objects.size()));
        for (uint16_t index : objects) {
            if (index >= h.names.size())
                throw std::invalid_argument(".hepvs: a cell lists an object past the names");
            put16(out, index);
        }
    }
    return out;
}

} // namespace pvs
