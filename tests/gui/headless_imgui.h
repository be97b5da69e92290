// A Dear ImGui context that draws with no window and no GPU (the null backend): a fixed display
// size, 30 frames a second, no .ini file, and the font atlas built so NewFrame() accepts it.
// The panel tests create one in SetUp and destroy it in TearDown with ImGui::DestroyContext().
#pragma once

#include <imgui.h>

namespace pvs::test {

inline void create_headless_imgui_context()
{
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = {1024.0f, 640.0f};
    io.DeltaTime = 1.0f / 30.0f;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
}

} // namespace pvs::test
