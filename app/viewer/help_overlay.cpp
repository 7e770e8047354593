#include "viewer/help_overlay.hpp"

#include <imgui.h>

#include <string>

namespace rad {

const std::vector<KeyHelp>& viewer_key_help() {
    static const std::vector<KeyHelp> keys{
        {"W A S D", "fly forward, left, back, right"},
        {"Q / E", "fly down / up"},
        {"right mouse drag", "look around (in orbit mode: turn around the scene)"},
        {"mouse wheel", "flying speed"},
        {"Tab or O", "orbit mode on / off"},
        {"R", "reset the view to the scene's camera"},
        {"N", "one solver step"},
        {"Space", "run / pause the solver"},
        {"B", "one bounce alone / all bounces"},
        {"P or F12", "screenshot of the view (PNG in the working folder)"},
        {"C", "copy the camera as render's --camera and --fov options"},
        {"K", "keep this view (Save, export, views)"},
        {"1 to 9", "go to a kept view"},
        {"F1", "this help"},
        {"Esc", "quit"},
        {"drop a file", "open a scene or a saved solution"},
    };
    return keys;
}

void draw_help_overlay(bool& open, float x, float y) {
    if (!open) return;
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(0.9f);
    if (ImGui::Begin(
            "keys (F1)", &open,
            ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove)) {
        if (ImGui::BeginTable("keys", 2)) {
            for (const KeyHelp& key : viewer_key_help()) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(std::string(key.keys).c_str());
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(std::string(key.action).c_str());
            }
            ImGui::EndTable();
        }
    }
    ImGui::End();
}

}  // namespace rad
