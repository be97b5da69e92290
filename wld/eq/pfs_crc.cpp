#include "wld/eq/pfs_crc.h"

#include <array>

namespace pvs::eq {

namespace {

constexpr uint32_t kPolynomial = 0x04C11DB7;

// T[i] = i << 24 shifted left 8 times, XORing the polynomial whenever bit 31 falls out (§1.6).
constexpr std::array<uint32_t, 256> make_table()
{
    std::array<uint32_t, 256> table{};
    for (uint32_t i = 0; i < 256; ++i) {
        uint32_t c = i << 24;
        for (int bit = 0; bit < 8; ++bit)
            c = (c & 0x80000000u) ? (c << 1) ^ kPolynomial : c << 1;
        table[i] = c;
    }
    return table;
}

constexpr std::array<uint32_t, 256> kTable = make_table();

constexpr uint32_t update(uint32_t crc, std::string_view bytes)
{
    for (const char ch : bytes)
        crc = (crc << 8) ^ kTable[((crc >> 24) ^ static_cast<uint8_t>(ch)) & 0xFF];
    return crc;
}

// The spec's table entries and known answers (§1.6, §8.3), checked when this file compiles.
static_assert(kTable[1] == 0x04C11DB7 && kTable[255] == 0xB1F740B4);
static_assert(update(0, "123456789") == 0x89A1897F);
static_assert(update(update(0, "gfaydark.wld"), std::string_view("\0", 1)) == 0x5942C027);

} // namespace

uint32_t pfs_crc_update(uint32_t crc, std::string_view bytes) { return update(crc, bytes); }

uint32_t pfs_crc(std::string_view bytes) { return update(0, bytes); }

uint32_t pfs_filename_crc(std::string_view name) { return update(update(0, name), std::string_view("\0", 1)); }

} // namespace pvs::eq
