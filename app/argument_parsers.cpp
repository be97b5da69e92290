#include "app/argument_parsers.h"

#include <sstream>

#include <charconv>
#include <cmath>
#include <string_view>

namespace pvs::app {

namespace {

template <typename T>
bool parse_number(std::string_view text, T& value)
{
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end;
}

} // namespace

std::optional<std::array<float, 5>> parse_camera_argument(const std::string& text)
{
    std::array<float, 5> values{};
    std::string_view rest = text;
    for (size_t i = 0; i < values.size(); ++i) {
        const size_t comma = rest.find(',');
        const bool last = i + 1 == values.size();
        if (last != (comma == std::string_view::npos))
            return std::nullopt;
        if (!parse_number(rest.substr(0, comma), values[i]) || !std::isfinite(values[i]))
            return std::nullopt;
        if (!last)
            rest.remove_prefix(comma + 1);
    }
    return values;
}

std::optional<std::array<uint32_t, 2>> parse_size_argument(const std::string& text)
{
    const size_t x = text.find('x');
    std::array<uint32_t, 2> size{};
    if (x == std::string::npos || !parse_number(std::string_view(text).substr(0, x), size[0]) ||
        !parse_number(std::string_view(text).substr(x + 1), size[1]))
        return std::nullopt;
    if (size[0] == 0 || size[1] == 0 || size[0] > 8192 || size[1] > 8192)
        return std::nullopt;
    return size;
}

std::vector<std::string> split_comma_list(const std::string& text)
{
    std::vector<std::string> items;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty())
            items.push_back(item);
    return items;
}

SkyPortals sky_mode_from_name(const std::string& name)
{
    return name == "all" ? SkyPortals::All : name == "none" ? SkyPortals::None : SkyPortals::SkyToSky;
}

} // namespace pvs::app
