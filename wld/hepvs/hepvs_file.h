// HateEngine's PVS file, `.hepvs` (../shared/formats/quake-doom-hepvs.md §5), read and written
// byte for byte: a 28-byte header (version u32; min x, y, z and cell size f32; cell counts x, y,
// z and object count u16), the object names (u16 byte length + UTF-8, no terminator), then one
// entry per cell in x-outermost, z-innermost order (u16 count + count u16 object indices). All
// little-endian; the file ends exactly where the last cell ends.
//
// Reading follows the spec's loader policy (§5.7): the 28-byte header (never a 20-byte guess),
// version >= 1 (other than 1 is noted in `warnings`), counts >= 1, a positive finite cell size,
// names and cells bounds-checked, every index below the object count, and nothing after the
// last cell. Any failure throws FileError naming the file, the byte offset and the problem. A
// header declaring more cells than the bytes after the names could hold (2 bytes each at least)
// is refused at offset 20 before anything is allocated for them.
// Cells keep their indices in file order (the baker's colour-ID order), so write(read(f)) == f.
#pragma once

#include <cstdint>
#include <glm/ext/vector_uint3.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <string>
#include <vector>

namespace pvs {

inline constexpr size_t kHepvsHeaderBytes = 28;

struct HepvsFile {
    uint32_t version = 1;
    glm::vec3 min{0.0f};
    float cell_size = 1.0f;
    glm::uvec3 counts{0u};          // each 1 .. 65535
    std::vector<std::string> names; // object index -> name (at most 65535)
    // Cell c holds cell_objects[cell_offsets[c] .. cell_offsets[c + 1]); cell order as the file.
    std::vector<uint32_t> cell_offsets;
    std::vector<uint16_t> cell_objects;
    std::vector<std::string> warnings; // readable but odd (a version other than 1)

    uint64_t cell_count() const { return uint64_t(counts.x) * counts.y * counts.z; }
    std::span<const uint16_t> cell(uint32_t c) const
    {
        return std::span<const uint16_t>(cell_objects).subspan(cell_offsets[c], cell_offsets[c + 1] - cell_offsets[c]);
    }
};

HepvsFile read_hepvs(std::span<const uint8_t> bytes, const std::string& file);
// Throws std::invalid_argument when the file cannot be written as it is (counts or names out of
// the u16 range, a cell index not below the name count, offsets that do not describe the cells).
std::vector<uint8_t> write_hepvs(const HepvsFile& hepvs);

} // namespace pvs
