#include "viewer/log_plot.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rad {

namespace {

constexpr float kPlotHeight = 96.0f;
// More decades than this get a label on every other one, so labels do not overlap.
constexpr int kLabelledDecades = 4;

std::string latest_value(float log10_value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", std::pow(10.0, double(log10_value)));
    return text;
}

}  // namespace

DecadeRange decade_range(float low, float high) {
    if (!std::isfinite(low) || !std::isfinite(high)) return {};
    DecadeRange range{static_cast<int>(std::floor(low)), static_cast<int>(std::ceil(high))};
    if (range.high <= range.low) range.high = range.low + 1;
    return range;
}

std::string decade_label(int decade) {
    if (decade == 0) return "1";
    if (decade == 1) return "10";
    char text[16];
    std::snprintf(text, sizeof text, "1e%+03d", decade);
    return text;
}

void log_plot(const std::string& title, const std::vector<float>& log10_values, std::size_t first_step) {
    if (log10_values.empty()) {
        ImGui::TextDisabled("%s: no steps yet", title.c_str());
        return;
    }
    ImGui::TextWrapped("%s, now %s", title.c_str(), latest_value(log10_values.back()).c_str());
    const auto [low, high] = std::minmax_element(log10_values.begin(), log10_values.end());
    const DecadeRange range = decade_range(*low, *high);

    ImDrawList& draw = *ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = std::max(ImGui::GetContentRegionAvail().x, 80.0f);
    const float line = ImGui::GetTextLineHeight();
    const float label_width = ImGui::CalcTextSize("1e-10").x + 6.0f;
    const ImVec2 top_left(origin.x + label_width, origin.y + 0.5f * line);
    const ImVec2 bottom_right(origin.x + width - 4.0f, origin.y + kPlotHeight - line - 2.0f);
    const ImU32 frame = ImGui::GetColorU32(ImGuiCol_FrameBg);
    const ImU32 grid = ImGui::GetColorU32(ImGuiCol_Border);
    const ImU32 text = ImGui::GetColorU32(ImGuiCol_TextDisabled);
    const ImU32 curve = ImGui::GetColorU32(ImGuiCol_PlotLines);
    draw.AddRectFilled(top_left, bottom_right, frame);

    const auto y_of = [&](float value) {
        const float t = (value - float(range.low)) / float(range.high - range.low);
        return bottom_right.y - t * (bottom_right.y - top_left.y);
    };
    const int decades = range.high - range.low;
    const int label_every =
        decades > kLabelledDecades ? (decades + kLabelledDecades - 1) / kLabelledDecades : 1;
    for (int d = range.low; d <= range.high; ++d) {
        const float y = y_of(float(d));
        draw.AddLine(ImVec2(top_left.x, y), ImVec2(bottom_right.x, y), grid);
        if ((d - range.low) % label_every != 0 && d != range.high) continue;
        const std::string label = decade_label(d);
        const float label_x = top_left.x - 4.0f - ImGui::CalcTextSize(label.c_str()).x;
        draw.AddText(ImVec2(label_x, y - 0.5f * line), text, label.c_str());
    }

    const std::size_t n = log10_values.size();
    const auto x_of = [&](std::size_t i) {
        const float t = n == 1 ? 0.5f : float(i) / float(n - 1);
        return top_left.x + t * (bottom_right.x - top_left.x);
    };
    std::vector<ImVec2> points(n);
    for (std::size_t i = 0; i < n; ++i) points[i] = ImVec2(x_of(i), y_of(log10_values[i]));
    if (n == 1) {
        draw.AddCircleFilled(points[0], 2.5f, curve);
    } else {
        draw.AddPolyline(points.data(), static_cast<int>(n), curve, ImDrawFlags_None, 1.5f);
    }

    // The x axis: the first and last steps at the ends, the axis' name between.
    const float label_y = bottom_right.y + 2.0f;
    const std::string first = std::to_string(first_step);
    const std::string last = std::to_string(first_step + n - 1);
    draw.AddText(ImVec2(top_left.x, label_y), text, first.c_str());
    if (n > 1) {
        draw.AddText(ImVec2(bottom_right.x - ImGui::CalcTextSize(last.c_str()).x, label_y), text,
                     last.c_str());
    }
    const char* axis = "step";
    draw.AddText(ImVec2(0.5f * (top_left.x + bottom_right.x - ImGui::CalcTextSize(axis).x), label_y), text,
                 axis);
    ImGui::Dummy(ImVec2(width, kPlotHeight));
}

}  // namespace rad
