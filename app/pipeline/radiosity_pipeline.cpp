#include "pipeline/radiosity_pipeline.hpp"

#include <algorithm>
#include <string>

#include "pipeline/form_factor_options.hpp"
#include "pipeline/outside_light_options.hpp"
#include "rad/display/solution_display.hpp"
#include "rad/mesh/patch_albedo.hpp"
#include "rad/transport/scene_transport.hpp"
#include "rad/transport/source_update.hpp"
#include "rad/util/error.hpp"
#include "rad/util/stopwatch.hpp"

namespace rad {

RadiosityPipeline::RadiosityPipeline(const PipelineOptions& options) : options_(options) {
    subdivision_ = parse_subdivision(options.subdivision.method);
    method_ = solver_method(options.solver);
    // Bad options fail before the long work.
    const bool automatic = subdivision_ == Subdivision::automatic;
    if (!automatic_method(options.solver) && !automatic)
        check_solver_supported(method_, has_matrix(subdivision_));
    check_solver_options(rad::solver_options(options.solver, 1));
    const Stopwatch clock;
    if (automatic) {
        loaded_ = load_scene_only(options.scene);
        choose_automatic_subdivision();
    } else {
        loaded_ = load_and_mesh(options.scene, transport_method(subdivision_).base_patch_scale);
    }
    seconds_.mesh = clock.seconds();
    solver_options_ = rad::solver_options(options.solver, loaded_.patches->size());
    opened_sky_ = loaded_.scene.sky;
    opened_sun_ = loaded_.scene.sun;
}

void RadiosityPipeline::choose_automatic_subdivision() {
    // Every face is at least one patch: where the face count alone decides (it is past every limit but the
    // last method's), the scene is not meshed at the uniform size first.
    std::size_t faces = 0;
    for (const Surface& surface : loaded_.scene.surfaces) faces += surface.mesh.n_faces();
    const TransportMethod* method = &automatic_transport_method(faces);
    const bool meshed = method->automatic_up_to != kAnySize;
    if (meshed) {
        mesh_loaded(loaded_, options_.scene, 1.0);
        method = &automatic_transport_method(loaded_.patches->size());
    }
    subdivision_ = method->id;
    options_.subdivision.method = std::string(method->name);
    if (!automatic_method(options_.solver)) check_solver_supported(method_, method->has_matrix);
    // A method of larger base patches meshes again, unless the command line gave their size.
    if (!meshed || (method->base_patch_scale != 1.0 && options_.scene.patch_size <= 0.0))
        mesh_loaded(loaded_, options_.scene, method->base_patch_scale);
}

PipelineOptions options_from_solution(const SolutionSettings& s, const PipelineOptions& base) {
    PipelineOptions options = base;
    options.scene.scene = s.scene_source;
    options.scene.patch_size = s.patch_size;
    options.form_factors.method =
        s.form_factor_method == "analytic" ? FormFactorMethod::analytic : FormFactorMethod::hemisphere;
    options.form_factors.rays = static_cast<int>(s.rays);
    options.form_factors.seed = s.seed;
    options.form_factors.enforce_reciprocity = s.reciprocity;
    options.form_factors.normalize_rows = s.normalize_rows;
    options.subdivision.method = s.subdivision;
    options.subdivision.tolerance = s.refine_tolerance;
    options.subdivision.min_patch_size = s.min_patch_size;
    options.solver.method = s.solver;
    options.solver.tolerance = s.tolerance;
    options.solver.bounces = s.bounces;
    options.solver.initial = s.initial;
    options.solver.relaxation = s.relaxation;
    return options;
}

RadiosityPipeline::RadiosityPipeline(SavedSolution saved, const std::string& path,
                                     const DisplayOptions& display)
    : opened_path_(path) {
    const SolutionSettings& s = saved.solution.settings;
    options_ = options_from_solution(s, options_);
    options_.display = display;
    try {
        subdivision_ = parse_subdivision(s.subdivision);
        method_ = solver_method(options_.solver);
        solver_options_ = rad::solver_options(options_.solver, saved.solution.size());
        check_solver_options(solver_options_);
    } catch (const InputError& e) {
        throw InputError(path + ": the saved settings are unusable: " + e.what());
    }
    loaded_.scene = std::move(saved.scene);
    loaded_.patch_size = s.patch_size;
    opened_sky_ = loaded_.scene.sky;
    opened_sun_ = loaded_.scene.sun;
    // The base patches are made again only when the transport is rebuilt.
    solution_ = std::move(saved.solution);
    traced_display_gather_ = std::move(saved.display_gather);
    continues_solution_ = true;
}

SolutionSettings RadiosityPipeline::solution_settings() const {
    SolutionSettings s;
    s.scene_source = loaded_.scene.source;
    s.patch_size = loaded_.patch_size;
    s.subdivision = subdivision_name(subdivision_);
    s.refine_tolerance = options_.subdivision.tolerance;
    s.min_patch_size = options_.subdivision.min_patch_size;
    s.form_factor_method =
        options_.form_factors.method == FormFactorMethod::analytic ? "analytic" : "hemisphere";
    s.rays = options_.form_factors.rays;
    s.seed = options_.form_factors.seed;
    s.reciprocity = options_.form_factors.enforce_reciprocity;
    s.normalize_rows = options_.form_factors.normalize_rows;
    s.solver = solver_method_name(method_);
    s.tolerance = solver_options_.tolerance;
    s.bounces = options_.solver.bounces;
    s.initial = options_.solver.initial;
    s.relaxation = options_.solver.relaxation;
    return s;
}

SavedSolution RadiosityPipeline::saved_solution() const {
    SavedSolution saved{.scene = loaded_.scene, .solution = solution(), .display_gather = {}};
    saved.scene.warnings.clear();
    // The display patches' own gather is the display's longest part; kept, opening the file skips it.
    saved.display_gather = display_ && !display_->traced.patch_gather.empty()
                               ? display_->traced.patch_gather
                               : display_patch_gather_table(loaded_.scene, saved.solution);
    return saved;
}

const Solution& RadiosityPipeline::solution() const {
    if (!elements_current_ && solver_) {
        const Transport& t = *built_->transport;
        solution_.area = t.area;
        solution_.reflectance = t.reflectance;
        solution_.emission = t.emission;
        solution_.direct = element_direct();
        solution_.outside = t.outside;
        elements_current_ = true;
    }
    if (!radiosity_current_ && solver_) {
        solution_.settings = solution_settings();
        solution_.radiosity.assign(solver_->solution().begin(), solver_->solution().end());
        solution_.shown_radiosity = solver_->display_solution();
        const StepReport& report = solver_->report();
        solution_.report = {.steps = report.step,
                            .residual = report.residual,
                            .status = std::string(solver_status_name(report.status)),
                            .status_message = solver_->status_message()};
        radiosity_current_ = true;
    }
    return solution_;
}

void RadiosityPipeline::solver_changed() {
    radiosity_current_ = false;
}

void RadiosityPipeline::take_elements() {
    // The elements are the base patches (uniform transport) or owned by the transport built over them.
    solution_.elements = built_->patches == loaded_.patches.get()
                             ? loaded_.patches
                             : std::shared_ptr<const PatchMesh>(built_, built_->patches);
    // Their arrays are copied when the solution is asked for, so a solve that is not shown never pays.
    elements_current_ = false;
    solver_changed();
}

TransportSettings RadiosityPipeline::transport_settings() const {
    TransportSettings settings;
    settings.subdivision = subdivision_;
    settings.form_factors = form_factor_options_for(options_.form_factors, loaded_);
    settings.refine_tolerance = options_.subdivision.tolerance;
    settings.min_patch_size = options_.subdivision.min_patch_size;
    // An automatic choice solves the passes by bounces; the final solver is chosen once the transport is
    // known.
    settings.pass_method = method_;
    settings.pass_solver = solver_options_;
    return settings;
}

void RadiosityPipeline::prepare(Progress* progress) {
    if (solver_) return;
    const Stopwatch clock;
    if (!loaded_.patches) {
        MeshingOptions meshing;
        meshing.patch_size = loaded_.patch_size;
        loaded_.patches = std::make_shared<const PatchMesh>(build_patches(loaded_.scene, meshing));
    }
    built_ = std::make_shared<SceneTransport>(
        build_scene_transport(loaded_.scene, *loaded_.patches, transport_settings(), progress));
    seconds_.form_factors = clock.seconds();
    work_.form_factor_passes += built_->transport->report().form_factor_passes;
    display_.reset();
    solver_options_ = rad::solver_options(options_.solver, built_->patches->size());
    if (automatic_method(options_.solver)) method_ = recommended_method(*built_->transport, solver_options_);
    if (continues_solution_) continue_from_solution();
    traced_display_gather_ = {};
    // Adaptive subdivision's last pass was solved already, but a fresh solver from B = E is what stepping
    // bounces shows.
    solver_ = make_solver(method_, *built_->transport, solver_options_);
    take_elements();
}

void RadiosityPipeline::continue_from_solution() {
    // The rebuilt transport must be the one the solution was solved on: same elements, same corners.
    const PatchMesh& rebuilt = *built_->patches;
    if (rebuilt.size() != solution_.size() || rebuilt.points != solution_.elements->points) {
        throw InputError(opened_path_ + ": the transport rebuilt from the saved scene and settings has " +
                         std::to_string(rebuilt.size()) + " elements, not the saved " +
                         std::to_string(solution_.size()) + " (saved by another version of the program?)");
    }
    solver_options_.initial = InitialGuess::given;
    solver_options_.given = solution_.radiosity;
    // Southwell's unshot radiosity is not saved, so it cannot continue; jacobi can, from any radiosity.
    if (method_ == SolverMethod::southwell) {
        method_ = SolverMethod::jacobi;
        solver_options_.max_steps = options_.solver.bounces;
    }
    continues_solution_ = false;
}

StepReport RadiosityPipeline::step() {
    prepare();
    const Stopwatch clock;
    const StepReport report = solver_->step();
    solver_changed();
    ++work_.solver_steps;
    seconds_.solve += clock.seconds();
    return report;
}

const StepReport& RadiosityPipeline::solve(Progress* progress) {
    prepare(progress);
    // The step limit bounds the steps; how many the solver needs is not known.
    if (progress) progress->begin("solving", solver_options_.max_steps, ProgressTotal::at_most);
    const Stopwatch clock;
    const std::size_t steps_before = solver_->report().step;
    run_to_end(*solver_, progress);
    solver_changed();
    work_.solver_steps += solver_->report().step - steps_before;
    seconds_.solve += clock.seconds();
    return solver_->report();
}

void RadiosityPipeline::restart_solver(SolverMethod method, const SolverOptions& options) {
    prepare();
    solver_ = make_solver(method, *built_->transport, options);
    method_ = method;
    solver_options_ = options;
    solver_changed();
}

void RadiosityPipeline::edit_material(const std::string& name, const glm::dvec3& reflectance,
                                      const glm::dvec3& emitted_radiance) {
    prepare();
    std::vector<Surface*> edited;
    for (Surface& surface : loaded_.scene.surfaces)
        if (surface.material.name == name) edited.push_back(&surface);
    if (edited.empty()) throw InputError("material " + name + ": no surface has it");
    Material material = edited.front()->material;
    if (!material.texture) material.reflectance = reflectance;
    material.emission = emitted_radiance;
    validate_material(material, "material " + name);
    for (Surface* surface : edited) {
        surface->material.reflectance = material.reflectance;
        surface->material.emission = material.emission;
    }
    update_element_materials(*built_->transport, patches(), loaded_.scene);
    take_elements();
    restart_from_solution();
}

void RadiosityPipeline::edit_outside_light(const std::string& sky, const std::string& sun,
                                           Progress* progress) {
    prepare();
    // Read first, so a bad value changes nothing.
    const Sky new_sky = sky.empty() ? opened_sky_ : parse_sky(sky);
    const Sun new_sun = sun.empty() ? opened_sun_ : parse_sun(sun);
    Scene& scene = loaded_.scene;
    const Sky old_sky = scene.sky;
    const Sun old_sun = scene.sun;
    scene.sky = new_sky;
    scene.sun = new_sun;
    try {
        update_outside_light(*built_->transport, patches(), element_rays(), scene, options_.form_factors.seed,
                             progress);
    } catch (...) {
        scene.sky = old_sky;
        scene.sun = old_sun;
        throw;
    }
    options_.scene.sky = sky;
    options_.scene.sun = sun;
    take_elements();
    restart_from_solution();
}

void RadiosityPipeline::restart_from_solution() {
    // The light as it stands is where the new solution starts: a small edit converges in a few steps.
    SolverOptions options = solver_options_;
    options.initial = InitialGuess::given;
    options.given.assign(solver_->solution().begin(), solver_->solution().end());
    if (method_ == SolverMethod::southwell) {
        method_ = SolverMethod::jacobi;
        options.max_steps = options_.solver.bounces;
    }
    solver_ = make_solver(method_, *built_->transport, options);
    solver_options_ = std::move(options);
    solver_changed();
    display_.reset();
}

const DisplayMesh& RadiosityPipeline::display() const {
    prepare_display(nullptr);
    return *display_;
}

std::vector<glm::dvec3> RadiosityPipeline::element_direct() const {
    const Transport& t = *built_->transport;
    const std::vector<glm::dvec3> emitted = emitted_radiosity(loaded_.scene, *built_->patches);
    std::vector<glm::dvec3> direct(t.size());
    t.gather(emitted, direct);
    for (std::size_t q = 0; q < direct.size(); ++q) direct[q] *= t.reflectance[q];
    return direct;
}

void RadiosityPipeline::prepare_display(Progress* progress) const {
    if (!display_) display_.emplace(build_display(options_.display, progress));
}

const RayScene& RadiosityPipeline::element_rays() const {
    if (!element_rays_ || element_rays_of_ != solution_.elements) {
        const bool built_them = built_ && built_->element_rays && built_->patches == solution_.elements.get();
        element_rays_ =
            built_them ? built_->element_rays : std::make_shared<const RayScene>(*solution_.elements);
        element_rays_of_ = solution_.elements;
    }
    return *element_rays_;
}

DisplayMesh RadiosityPipeline::build_display(const DisplayOptions& options, Progress* progress) const {
    if (has_solution()) {
        const GatherTable* traced = traced_display_gather_.empty() ? nullptr : &traced_display_gather_;
        return build_solution_display(loaded_.scene, solution(), options, traced, progress, &element_rays());
    }
    if (loaded_albedo_.size() != loaded_.patches->size())
        loaded_albedo_ = patch_albedo(loaded_.scene, *loaded_.patches);
    return build_preview_display(loaded_.scene, *loaded_.patches, options, loaded_albedo_,
                                 options_.form_factors.seed);
}

bool RadiosityPipeline::redraw_display(DisplayMesh& display, const DisplayOptions& options,
                                       Progress* progress) const {
    if (has_solution() && display_traces_fit(display, loaded_.scene, solution())) {
        relight_display(display, loaded_.scene, solution());
        return false;
    }
    display = build_display(options, progress);
    return true;
}

std::vector<glm::dvec3> RadiosityPipeline::preview_radiosity() const {
    return emitted_radiosity(loaded_.scene, patches());
}

const Transport& RadiosityPipeline::transport() const {
    return *built_->transport;
}

EnergyBalance RadiosityPipeline::energy_balance() const {
    return rad::energy_balance(*built_->transport, solver_->solution());
}

std::vector<glm::vec3> RadiosityPipeline::vertex_radiance() const {
    if (!has_solution()) return std::vector<glm::vec3>(display().vertex_count(), glm::vec3(0.0f));
    return rad::vertex_radiance(display(), solution().shown_radiosity);
}

}  // namespace rad
