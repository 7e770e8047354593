#include "solved_scene.hpp"

#include <string>

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

Solution solution_of(const SolvedScene& solved, double patch_size, std::uint64_t seed) {
    const Transport& t = *solved.system.transport;
    Solution solution;
    solution.settings.patch_size = patch_size;
    solution.settings.subdivision = std::string(solved.system.method->name);
    solution.settings.seed = seed;
    solution.elements = std::make_shared<const PatchMesh>(*solved.system.patches);
    solution.area = t.area;
    solution.reflectance = t.reflectance;
    solution.emission = t.emission;
    solution.outside = t.outside;
    std::vector<glm::dvec3> emitted(solution.size());
    for (std::size_t q = 0; q < emitted.size(); ++q)
        emitted[q] =
            solved.scene.surfaces[solution.elements->patches[q].surface].material.emitted_radiosity();
    std::vector<glm::dvec3> gathered(solution.size());
    t.gather(emitted, gathered);
    solution.direct.resize(solution.size());
    for (std::size_t q = 0; q < solution.size(); ++q) solution.direct[q] = t.reflectance[q] * gathered[q];
    solution.radiosity = solved.radiosity;
    solution.shown_radiosity = solved.radiosity;
    return solution;
}

}  // namespace rad::test
