// EverQuest WLD strings: the XOR-encoded string hash and names looked up in it
// (../shared/formats/eq-s3d-wld.md §2.2, §2.4; known answers §8.3).
//
// Encoding: byte i is XORed with kWldStringKey[i % 8], i counted from the first byte of the
// block. The same XOR, restarting at key index 0, encodes the strings stored inside fragment
// bodies (0x03 file names, 0x29 user data). XOR is its own inverse.
//
// The decoded hash is back-to-back NUL-terminated strings starting with the empty string (byte
// 0 is a NUL). A string is addressed by its byte offset: a fragment's name_ref is the negated
// offset (-1 is the string at offset 1), 0 is the empty name, and a positive name_ref means "no
// name" (LQ's reading; pvscope never writes one). Writers pad the ENCODED block to a multiple
// of 4 with raw 0x00 bytes, which decode to garbage after the last NUL; decoding drops
// everything after the last NUL so a lookup always finds a terminator.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace pvs::eq {

inline constexpr std::array<uint8_t, 8> kWldStringKey = {0x95, 0x3A, 0xC5, 0x2A, 0x95, 0x7A, 0x95, 0x6A};

// XORs `bytes` in place with the key, starting at key index 0 (encodes and decodes).
void wld_xor(std::span<uint8_t> bytes);

// The decoded string hash: the whole block XOR-decoded, cut right after its last NUL (no NUL
// at all: empty). Never throws.
std::vector<char> decode_string_hash(std::span<const uint8_t> encoded);

// The encoded block for decoded strings, padded with raw 0x00 to a multiple of 4 bytes. The
// caller provides the NULs (a well-formed block starts and ends with one; see WldStringTable).
std::vector<uint8_t> encode_string_hash(std::span<const char> decoded);

// A string stored inside a fragment body (0x03 name, 0x29 user data): decoded, up to its first
// NUL (or the end of the bytes when there is none).
std::string decode_wld_string(std::span<const uint8_t> encoded);

// `text` + NUL, encoded: what a fragment stores, with the NUL counted in the stored length
// (the LQ form, §5.1). `text` must not contain a NUL (std::invalid_argument).
std::vector<uint8_t> encode_wld_string(std::string_view text);

// The string a name_ref names in the decoded hash: "" for name_ref >= 0, the NUL-terminated
// string at offset -name_ref otherwise, nullopt when that offset is outside `strings`.
std::optional<std::string_view> wld_string_at(std::span<const char> strings, int32_t name_ref);

// Builds a decoded string hash for writing: starts with the empty string, appends each distinct
// string once and returns its name_ref (0 for "", -offset otherwise).
class WldStringTable {
public:
    WldStringTable() : data_(1, '\0') {}

    // Throws std::invalid_argument for a string with a NUL inside or when the table would pass
    // 2^31 - 1 bytes (a name_ref is an i32).
    int32_t add(std::string_view text);
    const std::vector<char>& data() const { return data_; }

private:
    std::vector<char> data_;
    std::unordered_map<std::string, int32_t> refs_;
};

} // namespace pvs::eq
