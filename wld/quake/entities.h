// The ENTITIES lump of a Quake BSP (../shared/formats/quake-doom-hepvs.md §1.7): blocks of
// { "key" "value" ... } pairs. Vanilla Quake has no escape sequences; a value runs to the next
// double quote. Parsing is strict about structure (an unterminated block or string is an error
// naming its offset) and tolerant about whitespace and a trailing NUL.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pvs::quake {

struct Entity {
    std::vector<std::pair<std::string, std::string>> pairs; // in file order
    uint64_t offset = 0;                                     // of the opening brace, in the lump

    // The value of the first pair with this key, if any.
    std::optional<std::string_view> get(std::string_view key) const;
};

// `text` is the lump; `file` and `lump_offset` only serve error messages (absolute offsets).
std::vector<Entity> parse_entities(std::span<const uint8_t> text, const std::string& file, uint64_t lump_offset);

} // namespace pvs::quake
