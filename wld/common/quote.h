// Untrusted text shown in an error message: quoted, printable ASCII kept, other bytes as \xNN,
// cut after max_shown bytes with "..." so a hostile file cannot flood the message.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace pvs {

std::string quote_for_message(std::string_view text, size_t max_shown);

} // namespace pvs
