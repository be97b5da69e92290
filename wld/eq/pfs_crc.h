// The filename CRC of EverQuest PFS archives (.s3d/.eqg/.pfs), ../shared/formats/eq-s3d-wld.md §1.6.
//
// CRC-32 with polynomial 0x04C11DB7, MSB first (no reflection), initial value 0, no final XOR.
// This is not catalogue CRC-32/MPEG-2, which starts from 0xFFFFFFFF: the check value for
// "123456789" is 0x89A1897F here (MPEG-2 proper gives 0x0376E6E7).
//
// An index entry's filename_crc is this CRC over the name's bytes plus one terminating 0x00.
// The functions hash bytes exactly as given; lowercasing (which the client's case-insensitive
// lookup needs, §1.6 "Case") is the caller's job — see wld/eq/pfs_archive.h.
#pragma once

#include <cstdint>
#include <string_view>

namespace pvs::eq {

// The index entry holding the name list (§1.4). No known string hashes to it.
inline constexpr uint32_t kPfsNameListCrc = 0x61580AC9;

// Continues `crc` over `bytes`.
uint32_t pfs_crc_update(uint32_t crc, std::string_view bytes);

// The CRC of `bytes` alone, from 0 (pfs_crc("123456789") == 0x89A1897F).
uint32_t pfs_crc(std::string_view bytes);

// The CRC of `name` plus one NUL, as stored in the index (pfs_filename_crc("gfaydark.wld") ==
// 0x5942C027). Hashes the bytes as given: lowercase first for what the client looks up.
uint32_t pfs_filename_crc(std::string_view name);

} // namespace pvs::eq
