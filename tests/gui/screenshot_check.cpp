// Checks a screenshot of the whole inspector window (`pvscope inspect --screenshot`): the
// viewport area is not blank (many colours, not one flat fill) and the side panels drew (text
// and widgets in each side column, which would otherwise be the flat clear colour).
// Usage: gui_screenshot_check FILE.png. Prints what it measured; exit 0 when the checks pass.
//
// The areas follow the tiling in ui/gui/inspector_layout.cpp: the zone and region panels take
// the left min(300, 25 %) of the width, the culling panel the right min(330, 28 %), the viewport
// the rest. Only well-inside parts of each are sampled, so small layout changes do not matter.
#include <stb_image.h>

#include <algorithm>
#include <cstdio>
#include <set>

namespace {

struct Area {
    int x0, y0, x1, y1;
};

struct Measure {
    size_t colours = 0;        // distinct RGB values
    double bright_share = 0;   // share of pixels with a channel above 150 (text, widgets)
};

Measure measure(const unsigned char* rgba, int width, Area a)
{
    std::set<unsigned> colours;
    size_t bright = 0, total = 0;
    for (int y = a.y0; y < a.y1; ++y)
        for (int x = a.x0; x < a.x1; ++x) {
            const unsigned char* p = rgba + (size_t(y) * size_t(width) + size_t(x)) * 4;
            colours.insert(unsigned(p[0]) << 16 | unsigned(p[1]) << 8 | p[2]);
            bright += std::max({p[0], p[1], p[2]}) > 150 ? 1 : 0;
            ++total;
        }
    return {colours.size(), total ? double(bright) / double(total) : 0.0};
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s FILE.png\n", argv[0]);
        return 2;
    }
    int width = 0, height = 0, channels = 0;
    unsigned char* rgba = stbi_load(argv[1], &width, &height, &channels, 4);
    if (!rgba) {
        std::fprintf(stderr, "%s: cannot read: %s\n", argv[1], stbi_failure_reason());
        return 1;
    }
    const int left = std::min(300, width / 4), right = std::min(330, width * 28 / 100);
    const Area viewport{left + 20, height / 5, width - right - 20, height * 4 / 5};
    const Area left_column{5, 5, left - 5, height - 5};
    const Area right_column{width - right + 5, 5, width - 5, height - 5};
    const Measure v = measure(rgba, width, viewport), l = measure(rgba, width, left_column),
                  r = measure(rgba, width, right_column);
    stbi_image_free(rgba);

    std::printf("%s: %dx%d; viewport %zu colours; left panels %zu colours, %.2f%% bright; right panel %zu colours, "
                "%.2f%% bright\n",
                argv[1], width, height, v.colours, l.colours, l.bright_share * 100.0, r.colours,
                r.bright_share * 100.0);
    bool ok = true;
    if (v.colours < 200) {
        std::fprintf(stderr, "FAIL: the viewport area looks blank (%zu colours)\n", v.colours);
        ok = false;
    }
    for (const auto& [name, m] : {std::pair{"left", l}, std::pair{"right", r}})
        if (m.colours < 8 || m.bright_share < 0.005) {
            std::fprintf(stderr, "FAIL: the %s panels did not draw (%zu colours, %.3f%% bright)\n", name, m.colours,
                         m.bright_share * 100.0);
            ok = false;
        }
    return ok ? 0 : 1;
}
