#include "render/render_mode.h"

namespace pvs::ui {

const char* render_mode_name(RenderMode mode)
{
    switch (mode) {
    case RenderMode::Textured: return "textured";
    case RenderMode::RegionColors: return "regions";
    case RenderMode::IdBuffer: return "ids";
    case RenderMode::Flags: return "flags";
    }
    return "?";
}

std::optional<RenderMode> parse_render_mode(std::string_view name)
{
    for (RenderMode m : kRenderModes)
        if (name == render_mode_name(m))
            return m;
    return std::nullopt;
}

} // namespace pvs::ui
