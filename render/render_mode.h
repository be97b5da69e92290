// How the software renderer draws a zone (software_renderer.h says what each mode shows), and
// the mode's name on the command line (`render --mode`, the inspector's menu).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace pvs::ui {

enum class RenderMode : uint8_t { Textured, RegionColors, IdBuffer, Flags };
inline constexpr std::array<RenderMode, 4> kRenderModes{RenderMode::Textured, RenderMode::RegionColors,
                                                        RenderMode::IdBuffer, RenderMode::Flags};
const char* render_mode_name(RenderMode mode); // "textured", "regions", "ids", "flags"
std::optional<RenderMode> parse_render_mode(std::string_view name);

} // namespace pvs::ui
