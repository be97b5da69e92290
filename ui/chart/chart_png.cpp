#include "ui/chart/chart_png.h"

#include "ui/chart/imgui_canvas.h"

#include <algorithm>
#include <cmath>

namespace pvs::ui::chart {

namespace {

struct AlphaTexture {
    const unsigned char* texels = nullptr;
    int width = 0, height = 0;

    float sample(ImVec2 uv) const
    {
        const int x = std::clamp(int(uv.x * float(width)), 0, width - 1);
        const int y = std::clamp(int(uv.y * float(height)), 0, height - 1);
        return float(texels[size_t(y) * size_t(width) + size_t(x)]) / 255.0f;
    }
};

float edge(ImVec2 a, ImVec2 b, float px, float py) { return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x); }

// One triangle, pixel centres inside it (either winding), blended over the image.
void fill_triangle(const ImDrawVert& v0, const ImDrawVert& v1, const ImDrawVert& v2, const ImVec4& clip,
                   const AlphaTexture& texture, Image& image)
{
    const float area = edge(v0.pos, v1.pos, v2.pos.x, v2.pos.y);
    if (std::abs(area) < 1e-8f)
        return;
    const int x0 = std::max({0, int(std::floor(std::min({v0.pos.x, v1.pos.x, v2.pos.x}))), int(clip.x)});
    const int y0 = std::max({0, int(std::floor(std::min({v0.pos.y, v1.pos.y, v2.pos.y}))), int(clip.y)});
    const int x1 = std::min({int(image.width) - 1, int(std::ceil(std::max({v0.pos.x, v1.pos.x, v2.pos.x}))), int(clip.z) - 1});
    const int y1 = std::min({int(image.height) - 1, int(std::ceil(std::max({v0.pos.y, v1.pos.y, v2.pos.y}))), int(clip.w) - 1});
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const float px = float(x) + 0.5f, py = float(y) + 0.5f;
            const float w0 = edge(v1.pos, v2.pos, px, py) / area, w1 = edge(v2.pos, v0.pos, px, py) / area;
            const float w2 = 1.0f - w0 - w1;
            if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f)
                continue;
            const ImVec2 uv(w0 * v0.uv.x + w1 * v1.uv.x + w2 * v2.uv.x, w0 * v0.uv.y + w1 * v1.uv.y + w2 * v2.uv.y);
            auto channel = [&](int shift) {
                return w0 * float((v0.col >> shift) & 0xFF) + w1 * float((v1.col >> shift) & 0xFF) +
                       w2 * float((v2.col >> shift) & 0xFF);
            };
            const float alpha = channel(IM_COL32_A_SHIFT) / 255.0f * texture.sample(uv);
            uint8_t* out = image.rgba.data() + (size_t(y) * image.width + size_t(x)) * 4;
            const int shifts[3] = {IM_COL32_R_SHIFT, IM_COL32_G_SHIFT, IM_COL32_B_SHIFT};
            for (int c = 0; c < 3; ++c)
                out[c] = uint8_t(std::lround(channel(shifts[c]) * alpha + float(out[c]) * (1.0f - alpha)));
        }
}

void rasterise(const ImDrawData& data, const AlphaTexture& texture, Image& image)
{
    for (int l = 0; l < data.CmdListsCount; ++l) {
        const ImDrawList& list = *data.CmdLists[l];
        for (const ImDrawCmd& cmd : list.CmdBuffer) {
            if (cmd.UserCallback)
                continue;
            for (unsigned i = 0; i + 2 < cmd.ElemCount; i += 3) {
                const ImDrawIdx* idx = list.IdxBuffer.Data + cmd.IdxOffset + i;
                const ImDrawVert* v = list.VtxBuffer.Data + cmd.VtxOffset;
                fill_triangle(v[idx[0]], v[idx[1]], v[idx[2]], cmd.ClipRect, texture, image);
            }
        }
    }
}

// A private ImGui context for its lifetime; the previous one is current again afterwards.
class HeadlessImgui {
public:
    HeadlessImgui(uint32_t width, uint32_t height) : previous_(ImGui::GetCurrentContext()), own_(ImGui::CreateContext())
    {
        ImGui::SetCurrentContext(own_);
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.LogFilename = nullptr;
        io.DisplaySize = ImVec2(float(width), float(height));
        unsigned char* texels = nullptr;
        io.Fonts->GetTexDataAsAlpha8(&texels, &texture.width, &texture.height);
        texture.texels = texels;
    }
    ~HeadlessImgui()
    {
        ImGui::DestroyContext(own_);
        ImGui::SetCurrentContext(previous_);
    }
    HeadlessImgui(const HeadlessImgui&) = delete;
    HeadlessImgui& operator=(const HeadlessImgui&) = delete;

    AlphaTexture texture;

private:
    ImGuiContext* previous_;
    ImGuiContext* own_;
};

} // namespace

Image render_chart_image(std::span<const ChartPoint> points, const std::string& title, uint32_t width, uint32_t height)
{
    const HeadlessImgui imgui(width, height);
    ImGui::NewFrame();
    ImguiCanvas canvas(ImGui::GetBackgroundDrawList(), ImGui::GetFont(), ImGui::GetFontSize());
    draw_speed_accuracy_chart(points, title, canvas, {0.0f, 0.0f}, {float(width), float(height)});
    ImGui::Render();
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.assign(size_t(width) * height * 4, 255);
    rasterise(*ImGui::GetDrawData(), imgui.texture, image);
    return image;
}

void write_chart_png(std::span<const ChartPoint> points, const std::string& title, uint32_t width, uint32_t height,
                     const std::string& path)
{
    save_png(render_chart_image(points, title, width, height), path);
}

} // namespace pvs::ui::chart
