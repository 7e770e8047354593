#include "viewer/false_colour_legend.hpp"

#include <imgui.h>

#include <cmath>
#include <string>

#include "rad/util/srgb.hpp"
#include "viewer/log_plot.hpp"

namespace rad {

namespace {

constexpr float kBarWidth = 18.0f;
constexpr float kBarHeight = 200.0f;

// The window's 8-bit framebuffer holds sRGB codes; Dear ImGui's colours are those codes.
ImU32 display_colour(const glm::vec3& linear) {
    return ImGui::GetColorU32(
        ImVec4(srgb_encode(linear.r), srgb_encode(linear.g), srgb_encode(linear.b), 1.0f));
}

}  // namespace

void draw_false_colour_legend(const FalseColourScale& scale, float right, float top) {
    ImGui::SetNextWindowPos(ImVec2(right, top), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.75f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoNav;
    if (!ImGui::Begin("false colour legend", nullptr, flags)) {
        ImGui::End();
        return;
    }
    ImGui::TextUnformatted("luminance, cd/m2");
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float label_width = ImGui::CalcTextSize("1e+00").x;
    const float line = ImGui::GetTextLineHeight();
    ImDrawList& draw = *ImGui::GetWindowDrawList();
    // The bar, bright (high) at the top: one gradient per pair of neighbouring stops.
    const auto& stops = false_colour_stops();
    const float segment = kBarHeight / float(kFalseColourStops - 1);
    for (int i = 0; i + 1 < kFalseColourStops; ++i) {
        const float y0 = origin.y + kBarHeight - float(i + 1) * segment;
        const ImU32 upper = display_colour(stops[static_cast<std::size_t>(i + 1)]);
        const ImU32 lower = display_colour(stops[static_cast<std::size_t>(i)]);
        draw.AddRectFilledMultiColor(ImVec2(origin.x, y0), ImVec2(origin.x + kBarWidth, y0 + segment), upper,
                                     upper, lower, lower);
    }
    const int low = static_cast<int>(std::lround(scale.log10_low));
    const int high = static_cast<int>(std::lround(scale.log10_high));
    for (int d = low; d <= high && high > low; ++d) {
        const float y = origin.y + kBarHeight * (1.0f - float(d - low) / float(high - low));
        draw.AddLine(ImVec2(origin.x + kBarWidth, y), ImVec2(origin.x + kBarWidth + 4.0f, y),
                     ImGui::GetColorU32(ImGuiCol_Text));
        draw.AddText(ImVec2(origin.x + kBarWidth + 6.0f, y - 0.5f * line), ImGui::GetColorU32(ImGuiCol_Text),
                     decade_label(d).c_str());
    }
    ImGui::Dummy(ImVec2(kBarWidth + 8.0f + label_width, kBarHeight + 0.5f * line));
    ImGui::TextDisabled("Ke as W/(m2 sr), 683 lm/W");
    ImGui::End();
}

}  // namespace rad
