#include "solved_scene.hpp"

#include "rad/solve/solver.hpp"

namespace rad::test {

std::unique_ptr<SolvedScene> solve_scene(Scene scene, Subdivision subdivision, double patch_size,
                                         std::uint64_t seed) {
    TransportSettings settings;
    settings.subdivision = subdivision;
    settings.form_factors.seed = seed;
    return solve_scene(std::move(scene), settings, patch_size);
}

std::unique_ptr<SolvedScene> solve_scene(Scene scene, const TransportSettings& settings, double patch_size) {
    auto s = std::make_unique<SolvedScene>();
    s->scene = std::move(scene);
    s->patches = build_patches(s->scene, MeshingOptions{.patch_size = patch_size});
    s->system = build_scene_transport(s->scene, s->patches, settings);
    SolverOptions options;
    options.tolerance = 1e-7;
    auto solver = make_solver(SolverMethod::jacobi, *s->system.transport, options);
    run_to_end(*solver);
    s->radiosity.assign(solver->solution().begin(), solver->solution().end());
    return s;
}

}  // namespace rad::test
