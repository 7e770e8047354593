#include "viewer/viewer_panel.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "rad/io/atomic_file.hpp"
#include "rad/io/saved_solution.hpp"
#include "text/camera_text.hpp"
#include "text/progress_bar.hpp"
#include "viewer/log_plot.hpp"
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

// What Save and Export are named after: the scene's file name without its folder or extension
// (builtin:cornell gives cornell).
std::string default_save_stem(const std::string& scene) {
    const std::string name =
        scene.starts_with("builtin:") ? scene.substr(8) : std::filesystem::path(scene).stem().string();
    return name.empty() ? std::string("radiosity") : name;
}

// A third of the window, within what the panel's widths need and leaving the view at least half.
float docked_panel_width(float window_width) {
    constexpr float kNarrowest = 260.0f;
    constexpr float kWidest = 400.0f;
    return std::min(std::clamp(0.3f * window_width, kNarrowest, kWidest), 0.5f * window_width);
}

// "form factors 42 %, about 17 s left": the share and the time left once they are known.
std::string progress_label(const ProgressState& state, double stage_seconds) {
    std::string label = state.stage.empty() ? std::string("working") : state.stage;
    if (!state.share_known()) return label;
    const double fraction = state.fraction();
    label += " " + std::to_string(static_cast<int>(fraction * 100.0)) + " %";
    if (progress_estimate_known(fraction, stage_seconds)) {
        const double left = stage_seconds * (1.0 - fraction) / fraction;
        label += ", about " + std::to_string(static_cast<long long>(std::llround(left))) + " s left";
    }
    return label;
}

// What one step of the method is: only Jacobi's steps are bounces (the light of one more reflection).
const char* step_name(SolverMethod method) {
    switch (method) {
        case SolverMethod::jacobi:
            return "bounce";
        case SolverMethod::southwell:
            return "shot";
        case SolverMethod::gauss_seidel:
            return "sweep";
        default:
            return "step";
    }
}

// "running" only while steps are being taken: a solver that has not finished but waits is paused.
std::string solver_state(const ViewerStatistics& statistics, bool stepping) {
    if (!statistics.prepared) return statistics.saved_options ? "saved" : "not solved";
    if (statistics.status == SolverStatus::running && !stepping) return "paused";
    return std::string(solver_status_name(statistics.status));
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
        material_ = -1;  // another scene's materials
        // A scene opened at its default patch size shows what that is (the statistics are the new scene's
        // from here on, not the previous one's).
        if (options_.scene.patch_size <= 0.0) options_.scene.patch_size = snapshot.statistics.patch_size;
    }
    // Docked: pinned to the left edge at the window's height, so no resize leaves it off-screen and it never
    // covers the scene.
    const ImVec2 window = ImGui::GetIO().DisplaySize;
    const float width = docked_panel_width(window.x);
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, window.y), ImGuiCond_Always);
    ImGui::Begin("radiosity", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
    requests.docked_width = ImGui::IsWindowCollapsed() ? 0.0f : width;
    draw_progress(worker);
    if (ImGui::CollapsingHeader("Solver", ImGuiTreeNodeFlags_DefaultOpen)) draw_solver(worker, snapshot);
    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) draw_view(worker, view, requests);
    if (ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) {
        draw_material(worker, snapshot.statistics);
    }
    if (ImGui::CollapsingHeader("Scene and meshing", ImGuiTreeNodeFlags_DefaultOpen)) {
        draw_scene(worker, snapshot.statistics);
    }
    if (ImGui::CollapsingHeader("Save, export, views", ImGuiTreeNodeFlags_DefaultOpen)) {
        draw_files(worker, view, requests);
    }
    if (ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) {
        draw_statistics(snapshot.statistics, frames);
    }
    for (const std::string& warning : snapshot.statistics.warnings) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.8f, 0.3f, 1));
        ImGui::TextWrapped("warning: %s", panel_text(warning).c_str());
        ImGui::PopStyleColor();
    }
    if (!snapshot.error.empty()) {
        // Wrapped, so a long error does not stretch the panel.
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.4f, 0.3f, 1));
        ImGui::TextWrapped("%s", panel_text(snapshot.error).c_str());
        ImGui::PopStyleColor();
    }
    if (!snapshot.written.empty()) ImGui::TextWrapped("%s", panel_text(snapshot.written).c_str());
    if (!message_.empty()) ImGui::TextWrapped("%s", panel_text(message_).c_str());
    ImGui::End();
    return requests;
}

PipelineOptions options_for_new_scene(PipelineOptions options, const std::string& path) {
    const PipelineOptions defaults;
    options.scene.scene = path;
    options.scene.patch_size = defaults.scene.patch_size;
    options.subdivision = defaults.subdivision;
    return options;
}

void ViewerPanel::open_scene(SolverWorker& worker, const std::string& path) {
    scene_path_ = path;
    options_ = options_for_new_scene(options_, path);
    show_options();
    // Opened at the first bounce, the direct light; a saved solution is shown at its own step.
    worker.request_rebuild(options_, is_saved_solution_path(path) ? 0 : 1);
}

void ViewerPanel::use_scene_defaults() {
    options_ = options_for_new_scene(options_, options_.scene.scene);
    show_options();
}

void ViewerPanel::draw_progress(SolverWorker& worker) {
    // The same widgets whether work runs or not, so the panel's layout does not jump when it starts.
    const std::shared_ptr<const Progress> progress = worker.progress();
    const bool working = worker.busy() && progress;
    const ProgressState state = working ? progress->state() : ProgressState{};
    if (working && (progress.get() != progress_seen_ || state.stage_number != stage_number_)) {
        progress_seen_ = progress.get();
        stage_number_ = state.stage_number;
        stage_start_ = ImGui::GetTime();
    }
    const std::string label =
        working ? progress_label(state, ImGui::GetTime() - stage_start_) : std::string("idle");
    ImGui::ProgressBar(working ? static_cast<float>(state.fraction()) : 0.0f, ImVec2(-80, 0), label.c_str());
    ImGui::SameLine();
    ImGui::BeginDisabled(!working);
    if (ImGui::Button("Cancel")) worker.cancel();
    ImGui::EndDisabled();
    // What the stage costs, as the library estimated it before starting ("13229 patches x 2048 rays, about
    // 170 MB"); one line kept for it either way.
    std::string note;
    if (working) {
        for (const ProgressNote& n : progress->notes())
            if (n.stage == state.stage) note = n.text;
    }
    ImGui::TextDisabled("%s", panel_text(note).c_str());
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
    ImGui::Text("%s %zu (%s), %s", step_name(statistics.method), steps,
                std::string(solver_method_name(statistics.method)).c_str(),
                solver_state(statistics, worker.running() || worker.pending_steps() > 0).c_str());
    if (!statistics.status_message.empty())
        ImGui::TextWrapped("%s", panel_text(statistics.status_message).c_str());
    log_plot("residual (share of emitted power)", statistics.log_residual);
    // Southwell's unshot power; for the others the power of the last update (Jacobi: the newest bounce).
    log_plot(statistics.method == SolverMethod::southwell ? "unshot power (radiosity x area)"
                                                          : "update power (radiosity x area)",
             statistics.log_unshot);
}

void ViewerPanel::draw_view(SolverWorker& worker, ViewSettings& view, PanelRequests& requests) {
    // The slider shows the metered value while auto is on; moving it fixes the exposure there.
    float exposure = static_cast<float>(view.exposure);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    if (ImGui::SliderFloat("exposure", &exposure, -24.0f, 24.0f, "%.1f")) {
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
    ImGui::Checkbox("false colour", &view.false_colour);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Luminance in cd/m2 (Ke read as W/(m2 sr), 683 lm/W), around the view's mean");
    if (view.false_colour) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.4f);
        ImGui::SliderInt("decades", &view.false_colour_decades, 1, 8);
    }
    ImGui::Checkbox("orbit (Tab)", &view.orbit);
    ImGui::SameLine();
    if (ImGui::Button("Reset view (R)")) requests.reset_view = true;
    if (ImGui::Button("Screenshot (F12)")) requests.screenshot = true;
    ImGui::SameLine();
    if (ImGui::Button("Copy --camera (C)")) requests.copy_camera = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The view as render's --camera and --fov, to the clipboard");
    ImGui::SameLine();
    if (ImGui::Button("Keys (F1)")) requests.show_help = true;
    ImGui::TextDisabled("WASD fly, Q/E down/up, right drag look");
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
    // Enter in the field opens it, as the button does.
    const bool entered = ImGui::InputText("scene", &scene_path_, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Open") || entered) open_scene(worker, scene_path_);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("or drop a .obj, .ply, .gltf, .glb or .radiosity (solve --save) file on the window");
    ImGui::PopStyleColor();
    // As --sky and --sun; Apply (or Enter) measures their light again on the same form factors; opening or
    // re-meshing reads them too. A bad value is reported in the panel.
    bool apply = ImGui::InputText("sky", &options_.scene.sky, ImGuiInputTextFlags_EnterReturnsTrue);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "R,G,B or L: a uniform sky; overcast,L: the CIE overcast sky; none; empty: as the scene was "
            "opened");
    apply |= ImGui::InputText("sun", &options_.scene.sun, ImGuiInputTextFlags_EnterReturnsTrue);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "X,Y,Z,E or X,Y,Z,R,G,B: toward the sun, and its irradiance; none; empty: as the scene was "
            "opened");
    ImGui::SameLine();
    apply |= ImGui::Button("Apply");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The sky and sun now, with the same form factors");
    if (apply) worker.request_outside_light(options_.scene.sky, options_.scene.sun);
    // 0 until the scene (or the subdivision) chosen says what its default is.
    ImGui::InputDouble("patch size", &options_.scene.patch_size, 0.0, 0.0,
                       options_.scene.patch_size > 0.0 ? "%.4g" : "default");
    options_.scene.patch_size = std::max(options_.scene.patch_size, 0.0);
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
    if (ImGui::Button("Re-mesh and recompute")) remesh(worker, statistics);
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
        if (!statistics.remesh_unavailable.empty()) {
            ImGui::SetTooltip("%s", statistics.remesh_unavailable.c_str());
        } else if (saved) {
            ImGui::SetTooltip(
                "Solves %s again, the scene this solution was saved from, with the settings above",
                saved->scene.scene.c_str());
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Scene defaults")) {
        use_scene_defaults();
        remesh(worker, statistics);
    }
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled) && statistics.remesh_unavailable.empty())
        ImGui::SetTooltip("Re-mesh at the scene's own patch size and subdivision (auto)");
}

void ViewerPanel::remesh(SolverWorker& worker, const ViewerStatistics& statistics) {
    options_.solver.method = solver_names()[static_cast<std::size_t>(method_index_)];
    const std::optional<PipelineOptions>& saved = statistics.saved_options;
    options_.scene.scene = saved                      ? saved->scene.scene
                           : statistics.scene.empty() ? scene_path_
                                                      : statistics.scene;
    worker.request_rebuild(options_, 1);
}

void ViewerPanel::select_material(std::uint32_t index) {
    material_ = static_cast<int>(index);
    material_loaded_ = false;
}

void ViewerPanel::draw_material(SolverWorker& worker, const ViewerStatistics& statistics) {
    if (!statistics.materials || statistics.materials->empty()) {
        ImGui::TextDisabled("no scene yet");
        return;
    }
    const std::vector<ViewerMaterial>& materials = *statistics.materials;
    if (material_ < 0 || material_ >= static_cast<int>(materials.size())) {
        material_ = 0;
        material_loaded_ = false;
    }
    std::vector<std::string> names;
    for (const ViewerMaterial& m : materials) names.push_back(m.name.empty() ? "(unnamed)" : m.name);
    if (combo("material", material_, names)) material_loaded_ = false;
    const ViewerMaterial& shown = materials[static_cast<std::size_t>(material_)];
    if (!material_loaded_) {
        for (int c = 0; c < 3; ++c) reflectance_[c] = static_cast<float>(shown.reflectance[c]);
        const double strength =
            std::max({shown.emitted_radiance.x, shown.emitted_radiance.y, shown.emitted_radiance.z});
        emission_strength_ = static_cast<float>(strength);
        for (int c = 0; c < 3; ++c)
            emission_colour_[c] =
                strength > 0.0 ? static_cast<float>(shown.emitted_radiance[c] / strength) : 1.0f;
        material_loaded_ = true;
    }
    ImGui::TextDisabled("or click a surface in the view");
    bool changed = false;
    ImGui::BeginDisabled(shown.textured);
    changed |= ImGui::ColorEdit3("reflectance", reflectance_, ImGuiColorEditFlags_Float);
    ImGui::EndDisabled();
    if (shown.textured && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("Textured: its texels give its reflectance");
    changed |= ImGui::ColorEdit3("emitted colour", emission_colour_, ImGuiColorEditFlags_Float);
    changed |=
        ImGui::DragFloat("emitted radiance", &emission_strength_, 0.05f * std::max(emission_strength_, 1.0f),
                         0.0f, 1e9f, "%.4g", ImGuiSliderFlags_Logarithmic);
    for (float& r : reflectance_) r = std::clamp(r, 0.0f, static_cast<float>(kMaxReflectance));
    emission_strength_ = std::max(emission_strength_, 0.0f);
    const glm::dvec3 le = double(emission_strength_) *
                          glm::dvec3(emission_colour_[0], emission_colour_[1], emission_colour_[2]);
    // π Le over the material's area, in the scene's units of radiosity × area (watts where Le is in W/(m² sr)
    // and lengths in metres).
    const double power = std::numbers::pi * (le.x + le.y + le.z) / 3.0 * shown.area;
    ImGui::TextDisabled("emitted power %.4g (mean of R, G, B), area %.4g", power, shown.area);
    if (changed) {
        worker.request_material_edit(shown.name,
                                     glm::dvec3(reflectance_[0], reflectance_[1], reflectance_[2]), le);
    }
}

void ViewerPanel::draw_files(SolverWorker& worker, const ViewSettings& view, PanelRequests& requests) {
    if (save_stem_.empty()) save_stem_ = default_save_stem(scene_path_);
    ImGui::InputText("file", &save_stem_);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Written in the working folder unless a folder is given; no extension");
    const auto write = [&](const char* extension) {
        worker.request_write(save_stem_ + extension, view.exposure);
    };
    if (ImGui::Button("Save .radiosity")) write(".radiosity");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The solution, for render and view to open without solving again");
    ImGui::SameLine();
    if (ImGui::Button("Export .ply")) write(".ply");
    ImGui::SameLine();
    if (ImGui::Button("Export .glb")) write(".glb");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The mesh drawn with its colours, at the exposure shown");
    if (ImGui::Button("Keep this view")) requests.add_bookmark = true;
    for (std::size_t i = 0; i < view.bookmarks.size(); ++i) {
        ImGui::SameLine();
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::SmallButton(std::to_string(i + 1).c_str())) requests.go_to_bookmark = i;
        ImGui::PopID();
    }
    if (!view.bookmarks.empty()) {
        if (ImGui::Button("Write the views as .cameras"))
            write_cameras(save_stem_ + ".cameras", view.bookmarks);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("One camera per line, for render --cameras FILE");
    }
}

void ViewerPanel::write_cameras(const std::string& path, const std::vector<Camera>& cameras) {
    try {
        write_file_atomically(path, cameras_file_text(cameras));
        message_ = "wrote " + path + " (render --cameras " + path + ")";
    } catch (const std::exception& e) {
        message_ = path + ": " + e.what();
    }
}

void ViewerPanel::draw_statistics(const ViewerStatistics& statistics, const FrameTimer& frames) {
    ImGui::TextWrapped("%zu patches (%s, size %.4g)", statistics.patches, statistics.subdivision.c_str(),
                       statistics.patch_size);
    if (statistics.prepared)
        ImGui::TextWrapped("%zu %s", statistics.interactions, statistics.interaction_name.c_str());
    ImGui::TextWrapped("seconds: mesh %.3f, form factors %.3f, solve %.3f", statistics.seconds.mesh,
                       statistics.seconds.form_factors, statistics.seconds.solve);
    ImGui::TextWrapped("frame %.1f ms (mean %.1f ms), longest while working %.1f ms", frames.latest() * 1e3,
                       frames.mean() * 1e3, frames.longest_while_busy() * 1e3);
    if (frames.inputs() > 0) {
        ImGui::TextWrapped("key to screen %.1f ms, longest %.1f ms (%.1f ms while working)",
                           frames.latest_input_latency() * 1e3, frames.longest_input_latency() * 1e3,
                           frames.longest_input_latency_while_busy() * 1e3);
    }
}

}  // namespace rad
