#include "wld/common/quote.h"

namespace pvs {

std::string quote_for_message(std::string_view text, size_t max_shown)
{
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out = "'";
    for (size_t i = 0; i < text.size() && i < max_shown; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7F) {
            out += static_cast<char>(c);
        } else {
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
        }
    }
    if (text.size() > max_shown)
        out += "...";
    return out + "'";
}

} // namespace pvs
