#include "viewer/viewer_panel.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "viewer/panel_text.hpp"

namespace rad {

namespace {

constexpr const char* kFormFactorNames[] = {"hemisphere", "analytic"};

std::vector<std::string> solver_names() {
    std::vector<std::string> names;
    for (const SolverMethod method : all_solver_methods()) names.emplace_back(solver_method_name(method));
    return names;
}

// The core's list, so that a subdivision added there appears here without touching the panel.
std::vector<std::string> subdivision_names() {
    std::vector<std::string> names;
    for (const Subdivision subdivision : all_subdivisions())
        names.emplace_back(subdivision_name(subdivision));
    return names;
}

int index_of(const std::vector<std::string>& names, const std::string& name) {
    const auto found = std::find(names.begin(), names.end(), name);
    return found == names.end() ? 0 : static_cast<int>(found - names.begin());
}

bool combo(const char* label, int& index, const std::vector<std::string>& names) {
    bool changed = false;
    if (ImGui::BeginCombo(label, names[static_cast<std::size_t>(index)].c_str())) {
        for (int i = 0; i < static_cast<int>(names.size()); ++i) {
            if (ImGui::Selectable(names[static_cast<std::size_t>(i)].c_str(), i == index)) {
                index = i;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

void plot(const char* label, const std::vector<float>& values) {
    if (values.empty()) {
        ImGui::TextDisabled("%s: no steps yet", label);
        return;
    }
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    const std::string overlay = std::string(label) + " (log10): " + std::to_string(values.back());
    ImGui::PlotLines("##plot", values.data(), static_cast<int>(values.size()), 0, overlay.c_str(), *low,
                     std::max(*high, *low + 1e-3f), ImVec2(0, 60));
}

}  // namespace

ViewerPanel::ViewerPanel(const PipelineOptions& options)
    : options_(options), scene_path_(options.scene.scene) {
    show_options();
}

void ViewerPanel::show_options() {
    method_index_ = index_of(solver_names(), options_.solver.method);
    form_factor_index_ = options_.form_factors.method == FormFactorMethod::analytic ? 1 : 0;
    subdivision_index_ = index_of(subdivision_names(), options_.subdivision.method);
}

PanelRequests ViewerPanel::draw(SolverWorker& worker, ViewSettings& view, const FrameTimer& frames) {
    PanelRequests requests;
    const SolverSnapshot snapshot = worker.snapshot();
    if (snapshot.statistics.opened != opened_) {
        opened_ = snapshot.statistics.opened;
        // A saved solution's settings are what "Re-mesh and recompute" starts from, so the controls take
        // them, once per opening so that edits made since stay.
        if (const auto& saved = snapshot.statistics.saved_options) {
            const DisplayOptions display = options_.display;
            options_ = *saved;
            options_.display = display;
            show_options();
        }
    }
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::Begin("radiosity", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    draw_progress(worker);
    if (ImGui::CollapsingHeader("Solver", ImGuiTreeNodeFlags_DefaultOpen)) draw_solver(worker, snapshot);
    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) draw_view(worker, view, requests);
    if (ImGui::CollapsingHeader("Scene and meshing", ImGuiTreeNodeFlags_DefaultOpen)) {
        draw_scene(worker, snapshot.statistics);
    }
    if (ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) {
        draw_statistics(snapshot.statistics, frames);
    }
    if (!snapshot.error.empty()) {
        // Wrapped, so a long error does not stretch the panel.
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.4f, 0.3f, 1));
        ImGui::TextWrapped("%s", panel_text(snapshot.error).c_str());
        ImGui::PopStyleColor();
    }
    if (!message_.empty()) ImGui::TextWrapped("%s", panel_text(message_).c_str());
    ImGui::End();
    return requests;
}

void ViewerPanel::open_scene(SolverWorker& worker, const std::string& path) {
    scene_path_ = path;
    options_.scene.scene = path;
    worker.request_rebuild(options_);
}

void ViewerPanel::draw_progress(SolverWorker& worker) {
    const std::shared_ptr<const Progress> progress = worker.progress();
    if (!worker.busy() || !progress) {
        ImGui::TextDisabled("idle");
        return;
    }
    const std::string stage = progress->stage();
    ImGui::ProgressBar(static_cast<float>(progress->fraction()), ImVec2(-80, 0),
                       stage.empty() ? "working" : stage.c_str());
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) worker.cancel();
}

void ViewerPanel::draw_solver(SolverWorker& worker, const SolverSnapshot& snapshot) {
    const ViewerStatistics& statistics = snapshot.statistics;
    const std::vector<std::string> names = solver_names();
    combo("method", method_index_, names);
    ImGui::InputDouble("tolerance", &options_.solver.tolerance, 0.0, 0.0, "%.1e");
    options_.solver.tolerance = std::clamp(options_.solver.tolerance, 1e-12, 0.5);
    if (ImGui::Button("Step")) worker.request_steps(1);
    ImGui::SameLine();
    if (worker.running()) {
        if (ImGui::Button("Pause")) worker.set_running(false);
    } else if (ImGui::Button("Run")) {
        worker.set_running(true);
    }
    ImGui::SameLine();
    if (ImGui::Button("Reset to emission")) {
        options_.solver.method = names[static_cast<std::size_t>(method_index_)];
        worker.request_reset(options_.solver.method, options_.solver.tolerance);
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("A fresh solver (B = E) with the method and tolerance above");
    const std::size_t steps = snapshot.radiance ? snapshot.radiance->step : 0;
    ImGui::Text("bounce %zu (%s), %s", steps, std::string(solver_method_name(statistics.method)).c_str(),
                statistics.prepared        ? std::string(solver_status_name(statistics.status)).c_str()
                : statistics.saved_options ? "saved"
                                           : "not solved");
    if (!statistics.status_message.empty())
        ImGui::TextWrapped("%s", panel_text(statistics.status_message).c_str());
    ImGui::PushID("residual");
    plot("residual", statistics.log_residual);
    ImGui::PopID();
    ImGui::PushID("unshot");
    // Southwell's unshot power; for the others the power of the last update (Jacobi: the newest bounce).
    plot(statistics.method == SolverMethod::southwell ? "unshot power" : "update power",
         statistics.log_unshot);
    ImGui::PopID();
}

void ViewerPanel::draw_view(SolverWorker& worker, ViewSettings& view, PanelRequests& requests) {
    // The slider shows the metered value while auto is on; moving it fixes the exposure there.
    float exposure = static_cast<float>(view.exposure);
    if (ImGui::SliderFloat("exposure", &exposure, -8.0f, 8.0f, "%.1f")) {
        view.exposure = exposure;
        view.auto_exposure = false;
    }
    ImGui::SameLine();
    ImGui::Checkbox("auto", &view.auto_exposure);
    draw_bounce_choice(worker, view);
    int mode = view.mode == ColourMode::flat ? 1 : 0;
    const bool smooth_clicked = ImGui::RadioButton("smooth", &mode, 0);
    ImGui::SameLine();
    const bool flat_clicked = ImGui::RadioButton("flat", &mode, 1);
    if (smooth_clicked || flat_clicked) {
        view.mode = mode == 1 ? ColourMode::flat : ColourMode::smooth;
        worker.request_colour_mode(view.mode);
    }
    ImGui::SameLine();
    ImGui::Checkbox("outline", &view.outline);
    ImGui::Checkbox("orbit (Tab)", &view.orbit);
    ImGui::SameLine();
    if (ImGui::Button("Reset view (R)")) requests.reset_view = true;
    ImGui::SameLine();
    if (ImGui::Button("Screenshot (F12)")) requests.screenshot = true;
    ImGui::TextDisabled("WASD fly, Q/E down/up, right drag look, wheel speed");
}

void ViewerPanel::draw_bounce_choice(const SolverWorker& worker, ViewSettings& view) {
    int shown = view.bounce_only ? 1 : 0;
    ImGui::RadioButton("all bounces", &shown, 0);
    ImGui::SameLine();
    ImGui::RadioButton("one bounce alone (B)", &shown, 1);
    view.bounce_only = shown == 1;
    if (!view.bounce_only) return;
    const SolverSnapshot snapshot = worker.snapshot();
    if (!snapshot.radiance) return;
    const ViewerRadiance& radiance = *snapshot.radiance;
    ImGui::Checkbox("newest", &view.newest_bounce);
    if (view.newest_bounce) view.bounce = radiance.step;
    ImGui::SameLine();
    // The light of paths L D^k E (Jacobi); other solvers show what step k added.
    int k = static_cast<int>(std::clamp(view.bounce, radiance.first_bounce, radiance.step));
    if (ImGui::SliderInt("k", &k, static_cast<int>(radiance.first_bounce), static_cast<int>(radiance.step))) {
        view.newest_bounce = false;
    }
    view.bounce = static_cast<std::size_t>(k);
}

void ViewerPanel::draw_scene(SolverWorker& worker, const ViewerStatistics& statistics) {
    ImGui::InputText("scene", &scene_path_);
    ImGui::SameLine();
    if (ImGui::Button("Open")) open_scene(worker, scene_path_);
    ImGui::TextDisabled("or drop a .obj, .ply, .gltf, .glb or .radiosity (solve --save) file on the window");
    // As --sky and --sun; read when the scene is opened or recomputed, and a bad value is reported there.
    ImGui::InputText("sky", &options_.scene.sky);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "R,G,B or L: a uniform sky; overcast,L: the CIE overcast sky; none or empty: the scene's own");
    ImGui::InputText("sun", &options_.scene.sun);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "X,Y,Z,E or X,Y,Z,R,G,B: toward the sun, and its irradiance; none or empty: the scene's own");
    if (options_.scene.patch_size <= 0.0) options_.scene.patch_size = statistics.patch_size;
    ImGui::InputDouble("patch size", &options_.scene.patch_size, 0.0, 0.0, "%.4g");
    if (ImGui::Combo("form factors", &form_factor_index_, kFormFactorNames, 2)) {
        options_.form_factors.method =
            form_factor_index_ == 1 ? FormFactorMethod::analytic : FormFactorMethod::hemisphere;
    }
    const std::vector<std::string> subdivisions = subdivision_names();
    if (combo("subdivision", subdivision_index_, subdivisions)) {
        options_.subdivision.method = subdivisions[static_cast<std::size_t>(subdivision_index_)];
        options_.scene.patch_size = 0.0;  // each method has its own default (hierarchical: base patches)
    }
    // A saved solution is recomputed from the scene it was solved from.
    const std::optional<PipelineOptions>& saved = statistics.saved_options;
    ImGui::BeginDisabled(!statistics.remesh_unavailable.empty());
    if (ImGui::Button("Re-mesh and recompute")) {
        options_.solver.method = solver_names()[static_cast<std::size_t>(method_index_)];
        options_.scene.scene = saved                      ? saved->scene.scene
                               : statistics.scene.empty() ? scene_path_
                                                          : statistics.scene;
        worker.request_rebuild(options_);
    }
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
        if (!statistics.remesh_unavailable.empty()) {
            ImGui::SetTooltip("%s", statistics.remesh_unavailable.c_str());
        } else if (saved) {
            ImGui::SetTooltip(
                "Solves %s again, the scene this solution was saved from, with the settings above",
                saved->scene.scene.c_str());
        }
    }
}

void ViewerPanel::draw_statistics(const ViewerStatistics& statistics, const FrameTimer& frames) {
    ImGui::Text("%zu patches (%s, size %.4g), %zu %s", statistics.patches, statistics.subdivision.c_str(),
                statistics.patch_size, statistics.interactions, statistics.interaction_name.c_str());
    ImGui::Text("seconds: mesh %.3f, form factors %.3f, solve %.3f", statistics.seconds.mesh,
                statistics.seconds.form_factors, statistics.seconds.solve);
    ImGui::Text("frame %.1f ms (mean %.1f ms), longest while working %.1f ms", frames.latest() * 1e3,
                frames.mean() * 1e3, frames.longest_while_busy() * 1e3);
}

}  // namespace rad
