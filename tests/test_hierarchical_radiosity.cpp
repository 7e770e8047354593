// Hierarchical radiosity: closed forms (furnace, two plates), agreement with a fine uniform solve on the
// Cornell box at a fraction of the links, the bounds, and link counts that grow about linearly.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <numbers>
#include <set>
#include <numeric>

#include "form_factor_test_scenes.hpp"
#include "rad/builtin_scenes.hpp"
#include "rad/form_factors.hpp"
#include "rad/hierarchical_radiosity.hpp"
#include "rad/patches.hpp"
#include "solver_test_systems.hpp"

namespace rad {
namespace {

struct Solved {
    std::unique_ptr<HierarchicalSystem> system;
    HierarchicalReport report;
    std::vector<glm::dvec3> radiosity;  // per leaf
};

Solved solve_hierarchical(const Scene& scene, double base_size, const HierarchicalOptions& options) {
    Solved out;
    const PatchMesh base = build_patches(scene, MeshingOptions{base_size});
    out.system = build_hierarchical_system(scene, base, options, &out.report);
    SolverOptions solver_options;
    solver_options.tolerance = 1e-7;
    const auto solver = make_hierarchical_solver(*out.system, solver_options);
    test::run_to_end(*solver);
    out.radiosity.assign(solver->solution().begin(), solver->solution().end());
    return out;
}

// Power A·B per surface, summed over the patches of each surface.
std::vector<glm::dvec3> surface_power(const PatchMesh& mesh, std::span<const glm::dvec3> radiosity) {
    std::vector<glm::dvec3> power(mesh.surface_begin.size() - 1, glm::dvec3(0.0));
    for (std::size_t q = 0; q < mesh.size(); ++q) power[mesh.patches[q].surface] += mesh.patches[q].area * radiosity[q];
    return power;
}

// A closed cube whose every face emits E and reflects ρ: B = E / (1 − ρ) everywhere, however refined.
TEST(Hierarchical, FurnaceGivesEOverOneMinusRho) {
    Scene scene = make_cube();
    for (Surface& s : scene.surfaces) {
        s.material.reflectance = glm::dvec3(0.5);
        s.material.emission = glm::dvec3(1.0 / std::numbers::pi);
    }
    for (double tolerance : {0.03, 0.003, 0.0005}) {
        HierarchicalOptions options;
        options.tolerance = tolerance;
        const Solved h = solve_hierarchical(scene, 10.0, options);
        double lo = 1e300, hi = 0.0;
        for (const glm::dvec3& b : h.radiosity) lo = std::min(lo, b.x), hi = std::max(hi, b.x);
        std::printf("furnace tolerance %.3g: %zu leaves, %zu links: B in [%.5f, %.5f]\n", tolerance, h.report.leaves,
                    h.report.links, lo, hi);
        {
            HierarchicalSystem& sys = *h.system;
            auto e = sys.emission; auto r = sys.reflectance;
            std::fill(sys.emission.begin(), sys.emission.end(), glm::dvec3(0.0));
            std::fill(sys.reflectance.begin(), sys.reflectance.end(), glm::dvec3(1.0));
            std::vector<glm::dvec3> ones(sys.tree.size(), glm::dvec3(1.0)), out(sys.tree.size());
            gather_push_pull(sys, ones, out);
            double worst = 0, least = 9; std::uint32_t wl = 0;
            for (std::uint32_t leaf : sys.leaves) { if (out[leaf].x > worst) worst = out[leaf].x, wl = leaf; least = std::min(least, out[leaf].x); }
            std::printf("leaf row sums in [%.4f, %.4f], worst at level %u centroid %.3f %.3f %.3f\n", least, worst, sys.tree[wl].level,
                        sys.tree[wl].shape.centroid.x, sys.tree[wl].shape.centroid.y, sys.tree[wl].shape.centroid.z);
            sys.emission = e; sys.reflectance = r;
        }
        EXPECT_NEAR(lo, 2.0, 0.02);
        EXPECT_NEAR(hi, 2.0, 0.02);
    }
}

TEST(Hierarchical, CornellAgainstAFineUniformSolve) {
    const Scene scene = make_builtin_scene("cornell");
    const double extent = default_patch_size(scene) * 16.0;
    // The reference: uniform patches of extent / 48 with analytic form factors, solved directly.
    const PatchMesh fine = build_patches(scene, MeshingOptions{extent / 32.0});
    FormFactorOptions ff;
    RadiositySystem reference_system = make_radiosity_system(scene, fine, compute_form_factors(fine, ff));
    SolverOptions so;
    so.tolerance = 1e-8;
    auto reference_solver = make_solver(SolverMethod::gauss_seidel, reference_system, so);
    test::run_to_end(*reference_solver);
    const std::vector<glm::dvec3> reference =
        surface_power(fine, whole_patch_radiosity(reference_system, fine, reference_solver->solution()));

    for (double tolerance : {0.1, 0.03, 0.01}) {
        HierarchicalOptions options;
        options.tolerance = tolerance;
        const auto start = std::chrono::steady_clock::now();
        const Solved h = solve_hierarchical(scene, extent / 4.0, options);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::vector<glm::dvec3> power = surface_power(
            h.system->leaf_patches, whole_patch_radiosity(h.system->leaf_system, h.system->leaf_patches, h.radiosity));
        double worst = 0.0;
        for (std::size_t s = 0; s < power.size(); ++s) {
            const double ref = reference[s].x + reference[s].y + reference[s].z;
            const double got = power[s].x + power[s].y + power[s].z;
            worst = std::max(worst, std::abs(got - ref) / ref);
            std::printf("  %s %.4g %.4g (%.2f %%)\n", scene.surfaces[s].name.c_str(), ref, got, 100 * (got - ref) / ref);
        }
        std::printf("tolerance %.3g: %zu base, %zu elements, %zu leaves, %zu links, %zu rounds, %.3g s "
                    "(refine %.3g, solve %.3g), %.1f MB, worst surface power error %.2f %%\n",
                    tolerance, h.report.base_patches, h.report.elements, h.report.leaves, h.report.links,
                    h.report.rounds, seconds, h.report.refine_seconds, h.report.solve_seconds,
                    h.report.memory_bytes / 1e6, 100.0 * worst);
        EXPECT_LT(worst, 0.05);
    }
}

}  // namespace
}  // namespace rad
