// Checks a screenshot of the whole inspector window (`pvscope inspect --screenshot`): the
// viewport area is not blank (many colours, not one flat fill) and every panel drew (text and
// widgets in each panel's area, which would otherwise be the flat clear colour): zone and region
// on the left, culling, BSP and bake on the right, and the main menu bar.
// Usage: gui_screenshot_check FILE.png. Prints what it measured; exit 0 when the checks pass.
//
// The areas follow the tiling in ui/gui/inspector_layout.cpp: under a menu bar of about
// kMenuBar pixels, the zone (45 % of the rest) and region panels take the left min(300, 25 %) of
// the width; the culling (45 %), BSP (27 %) and bake panels the right min(330, 28 %); the
// viewport the rest. Only well-inside parts of each are sampled, so small layout changes do not
// matter.
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
    constexpr int kMenuBar = 19;
    const int left = std::min(300, width / 4), right = std::min(330, width * 28 / 100);
    const int rest = height - kMenuBar;
    auto band = [&](int x0, int x1, double from, double to) {
        return Area{x0 + 5, kMenuBar + int(rest * from) + 5, x1 - 5, kMenuBar + int(rest * to) - 5};
    };
    const Area viewport{left + 20, height / 5, width - right - 20, height * 4 / 5};
    // ImGui's default font is a bitmap font: a bar of plain text has only a few colours.
    const std::pair<const char*, Area> panels[] = {
        {"menu bar", Area{5, 2, 60, kMenuBar - 2}},
        {"zone", band(0, left, 0.0, 0.45)},
        {"region", band(0, left, 0.45, 1.0)},
        {"culling", band(width - right, width, 0.0, 0.45)},
        {"bsp", band(width - right, width, 0.45, 0.72)},
        {"bake", band(width - right, width, 0.72, 1.0)},
    };
    const Measure v = measure(rgba, width, viewport);
    std::printf("%s: %dx%d; viewport %zu colours", argv[1], width, height, v.colours);
    bool ok = true;
    for (const auto& [name, area] : panels) {
        const Measure m = measure(rgba, width, area);
        std::printf("; %s %zu colours, %.2f%% bright", name, m.colours, m.bright_share * 100.0);
        const size_t min_colours = area.y0 < kMenuBar ? 2 : 8;
        if (m.colours < min_colours || m.bright_share < 0.005) {
            std::fprintf(stderr, "\nFAIL: the %s panel did not draw (%zu colours, %.3f%% bright)", name, m.colours,
                         m.bright_share * 100.0);
            ok = false;
        }
    }
    stbi_image_free(rgba);
    std::printf("\n");
    if (v.colours < 200) {
        std::fprintf(stderr, "FAIL: the viewport area looks blank (%zu colours)\n", v.colours);
        ok = false;
    }
    return ok ? 0 : 1;
}
