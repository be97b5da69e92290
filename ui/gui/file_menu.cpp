// The main menu bar: File -> Open (a file browser over list_directory), recent files, the demo
// zone, Save viewport PNG; and the modal that shows a load error.
#include "ui/gui/panels.h"

#include <imgui_stdlib.h>

#include <cstdio>
#include <exception>
#include <system_error>

namespace pvs::gui {

namespace {

std::string absolute_string(const std::string& path)
{
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    return error ? path : absolute.lexically_normal().string();
}

void draw_browser(InspectorState& state, FileMenu& menu)
{
    if (menu.browser_open && !ImGui::IsPopupOpen("Open zone")) {
        ImGui::OpenPopup("Open zone");
        if (menu.listing.directory.empty())
            browse_to(menu, std::filesystem::current_path());
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowSize({std::min(700.0f, display.x * 0.9f), std::min(500.0f, display.y * 0.8f)},
                             ImGuiCond_Appearing);
    if (!ImGui::BeginPopupModal("Open zone", &menu.browser_open))
        return;
    ImGui::SetNextItemWidth(-160.0f);
    if (ImGui::InputText("##dir", &menu.browser_field, ImGuiInputTextFlags_EnterReturnsTrue))
        browse_to(menu, menu.browser_field);
    ImGui::SameLine();
    if (ImGui::Button("Up"))
        browse_to(menu, menu.listing.directory.parent_path());
    ImGui::SameLine();
    if (ImGui::Checkbox("all files", &menu.browser_all_files))
        browse_to(menu, menu.listing.directory);
    if (!menu.listing.error.empty())
        ImGui::TextColored({1.0f, 0.4f, 0.3f, 1.0f}, "%s", menu.listing.error.c_str());
    std::string enter, open;
    if (ImGui::BeginChild("entries", {0.0f, -ImGui::GetFrameHeightWithSpacing()}, true)) {
        ImGuiListClipper clipper;
        clipper.Begin(int(menu.listing.entries.size()));
        while (clipper.Step())
            for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
                const BrowserEntry& e = menu.listing.entries[size_t(i)];
                char label[512];
                if (e.directory)
                    std::snprintf(label, sizeof label, "[dir] %s", e.name.c_str());
                else
                    std::snprintf(label, sizeof label, "%s  (%.1f MiB)", e.name.c_str(), double(e.size) / 1048576.0);
                const bool chosen = !e.directory && menu.chosen == e.name;
                if (ImGui::Selectable(label, chosen, ImGuiSelectableFlags_AllowDoubleClick)) {
                    if (e.directory)
                        enter = e.name;
                    else if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left))
                        open = e.name;
                    else
                        menu.chosen = e.name;
                }
            }
    }
    ImGui::EndChild();
    if (ImGui::Button("Open") && !menu.chosen.empty())
        open = menu.chosen;
    ImGui::SameLine();
    if (ImGui::Button("Cancel"))
        menu.browser_open = false;
    if (!enter.empty())
        browse_to(menu, menu.listing.directory / enter);
    if (!open.empty()) {
        menu.browser_open = false;
        open_zone_file(state, menu, (menu.listing.directory / open).string());
    }
    if (!menu.browser_open)
        ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

void draw_error_modal(FileMenu& menu)
{
    if (menu.error_pending) {
        ImGui::OpenPopup("Cannot open");
        menu.error_pending = false;
    }
    ImGui::SetNextWindowSize({std::min(600.0f, ImGui::GetIO().DisplaySize.x * 0.9f), 0.0f}, ImGuiCond_Appearing);
    if (!ImGui::BeginPopupModal("Cannot open", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
        return;
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 560.0f);
    ImGui::TextUnformatted(menu.error.c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::Button("OK")) {
        menu.error.clear();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

void draw_png_dialog(const InspectorState& state, FileMenu& menu)
{
    if (menu.png_open && !ImGui::IsPopupOpen("Save viewport PNG"))
        ImGui::OpenPopup("Save viewport PNG");
    if (!ImGui::BeginPopupModal("Save viewport PNG", &menu.png_open, ImGuiWindowFlags_AlwaysAutoResize))
        return;
    ImGui::SetNextItemWidth(400.0f);
    ImGui::InputText("##png", &menu.png_path);
    if (ImGui::Button("Save")) {
        try {
            ui::save_png(state.image(), menu.png_path);
            menu.png_message = "wrote " + menu.png_path;
            menu.png_open = false;
        } catch (const std::exception& e) {
            menu.png_message = e.what();
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel"))
        menu.png_open = false;
    if (!menu.png_message.empty())
        ImGui::TextWrapped("%s", menu.png_message.c_str());
    if (!menu.png_open)
        ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

} // namespace

bool open_zone_file(InspectorState& state, FileMenu& menu, const std::string& path)
{
    if (state.open_zone(path)) {
        menu.recent.add(absolute_string(path));
        return true;
    }
    menu.error = state.error();
    menu.error_pending = true;
    return false;
}

void browse_to(FileMenu& menu, const std::filesystem::path& directory)
{
    menu.listing = list_directory(directory, menu.browser_all_files);
    menu.browser_field = menu.listing.directory.string();
    menu.chosen.clear();
}

float draw_file_menu(InspectorState& state, FileMenu& menu)
{
    float height = 0.0f;
    if (ImGui::BeginMainMenuBar()) {
        height = ImGui::GetWindowSize().y;
        if (ImGui::BeginMenu("File")) {
            if (ImGui::MenuItem("Open..."))
                menu.browser_open = true;
            if (ImGui::BeginMenu("Open recent", !menu.recent.paths().empty())) {
                std::string chosen;
                for (const std::string& path : menu.recent.paths())
                    if (ImGui::MenuItem(path.c_str()))
                        chosen = path;
                ImGui::EndMenu();
                if (!chosen.empty())
                    open_zone_file(state, menu, chosen);
            }
            if (ImGui::MenuItem("Open demo zone"))
                state.open_demo();
            ImGui::Separator();
            if (ImGui::MenuItem("Save viewport PNG...", nullptr, false, !state.image().rgba.empty())) {
                menu.png_open = true;
                menu.png_message.clear();
            }
            ImGui::EndMenu();
        }
        if (state.has_zone()) {
            ImGui::TextDisabled("  %s", state.zone().source.path.c_str());
        }
        if (!menu.png_message.empty() && !menu.png_open)
            ImGui::TextDisabled("  %s", menu.png_message.c_str());
        ImGui::EndMainMenuBar();
    }
    return height;
}

void draw_file_dialogs(InspectorState& state, FileMenu& menu)
{
    draw_browser(state, menu);
    draw_png_dialog(state, menu);
    draw_error_modal(menu);
}

} // namespace pvs::gui
