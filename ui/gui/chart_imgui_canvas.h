// A chart canvas (ui/chart/canvas.h) drawing into a Dear ImGui draw list: the inspector's Compare
// panel draws the speed-vs-accuracy chart into its window with it. The command line draws the same
// chart with cairo (ui/chart/chart_file.h); this canvas lives with the GUI so that only the
// inspector links ImGui.
#pragma once

#include "ui/chart/canvas.h"

#include <imgui.h>

namespace pvs::ui::chart {

class ImguiCanvas final : public Canvas {
public:
    ImguiCanvas(ImDrawList* list, ImFont* font, float font_size) : list_(list), font_(font), font_size_(font_size) {}
    void line(glm::vec2 a, glm::vec2 b, Color color, float thickness) override;
    void rect(glm::vec2 min, glm::vec2 max, Color fill) override;
    void circle(glm::vec2 center, float radius, Color fill, Color outline) override;
    void text(glm::vec2 pos, std::string_view text, Color color, Align align) override;
    float text_height() const override { return font_size_; }
    float text_width(std::string_view text) const override;

private:
    ImDrawList* list_;
    ImFont* font_;
    float font_size_;
};

} // namespace pvs::ui::chart
