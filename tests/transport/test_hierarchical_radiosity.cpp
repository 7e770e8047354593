// Hierarchical radiosity: closed forms (furnace, two plates), agreement with a fine uniform solve on the
// Cornell box at a fraction of the links, the bounds, and link counts that grow about linearly.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <numbers>
#include <numeric>

#include "form_factor_test_scenes.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/hierarchical/hierarchical_radiosity.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"
#include "rad/util/error.hpp"
#include "solver_test_systems.hpp"

namespace rad {
namespace {

struct Solved {
    std::unique_ptr<HierarchicalTransport> transport;
    HierarchicalReport report;
    std::vector<glm::dvec3> radiosity;  // per leaf
};

Solved solve_hierarchical(const Scene& scene, double base_size, const HierarchicalOptions& options) {
    Solved out;
    const PatchMesh base = build_patches(scene, MeshingOptions{base_size});
    out.transport = make_hierarchical_transport(scene, base, options);
    out.report = out.transport->hierarchical_report();
    SolverOptions solver_options;
    solver_options.tolerance = 1e-7;
    const auto solver = make_solver(SolverMethod::jacobi, *out.transport, solver_options);
    test::run_to_end(*solver);
    out.radiosity.assign(solver->solution().begin(), solver->solution().end());
    return out;
}

// Power A·B per surface, summed over the patches of each surface.
std::vector<glm::dvec3> surface_power(const PatchMesh& mesh, std::span<const glm::dvec3> radiosity) {
    std::vector<glm::dvec3> power(mesh.surface_begin.size() - 1, glm::dvec3(0.0));
    for (std::size_t q = 0; q < mesh.size(); ++q)
        power[mesh.patches[q].surface] += mesh.patches[q].area * radiosity[q];
    return power;
}

// A closed cube whose every face emits E and reflects ρ: B = E / (1 − ρ) everywhere. Unrefined, the links
// between whole faces give it to 1e-4. Refined, a small leaf inherits the interpolated factors of all its
// ancestors' links, which near a corner add up to more than the hemisphere (16 % more at the corners before
// each leaf's factors were scaled to its measured form factor to the scene, 1 in a closed room); now every
// leaf is within 0.1 %.
TEST(Hierarchical, FurnaceGivesEOverOneMinusRho) {
    Scene scene = make_cube();
    for (Surface& s : scene.surfaces) {
        s.material.reflectance = glm::dvec3(0.5);
        s.material.emission = glm::dvec3(1.0 / std::numbers::pi);
    }
    for (double tolerance : {0.03, 0.003}) {
        HierarchicalOptions options;
        options.tolerance = tolerance;
        const Solved h = solve_hierarchical(scene, 10.0, options);
        double lo = 1e300, hi = 0.0, sum = 0.0, area = 0.0;
        for (std::size_t k = 0; k < h.radiosity.size(); ++k) {
            lo = std::min(lo, h.radiosity[k].x);
            hi = std::max(hi, h.radiosity[k].x);
            sum += h.transport->area[k] * h.radiosity[k].x;
            area += h.transport->area[k];
        }
        std::printf("furnace, tolerance %.3g: %zu leaves, %zu links: B in [%.5f, %.5f], mean %.5f\n",
                    tolerance, h.report.leaves, h.report.links, lo, hi, sum / area);
        const bool refined = h.report.leaves > 6;
        EXPECT_EQ(refined, tolerance < 0.01);
        EXPECT_NEAR(sum / area, 2.0, refined ? 2e-3 : 1e-4);
        EXPECT_NEAR(lo, 2.0, refined ? 2e-3 : 1e-4);
        EXPECT_NEAR(hi, 2.0, refined ? 2e-3 : 1e-4);
    }
}

TEST(Hierarchical, CornellAgainstAFineUniformSolve) {
    const Scene scene = make_builtin_scene("cornell");
    const double extent = default_patch_size(scene) * 16.0;
    // The reference: uniform patches of extent / 48 with analytic form factors, solved directly.
    const PatchMesh fine = build_patches(scene, MeshingOptions{extent / 32.0});
    FormFactorOptions ff;
    UniformTransport reference_system = make_uniform_transport(scene, fine, compute_form_factors(fine, ff));
    SolverOptions so;
    so.tolerance = 1e-8;
    auto reference_solver = make_solver(SolverMethod::gauss_seidel, reference_system, so);
    test::run_to_end(*reference_solver);
    const std::vector<glm::dvec3> reference =
        surface_power(fine, whole_patch_radiosity(reference_system, fine, reference_solver->solution()));

    for (double tolerance : {0.03, 0.01}) {
        HierarchicalOptions options;
        options.tolerance = tolerance;
        const auto start = std::chrono::steady_clock::now();
        const Solved h = solve_hierarchical(scene, extent / 4.0, options);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::vector<glm::dvec3> power = surface_power(
            h.transport->system().leaf_patches,
            whole_patch_radiosity(*h.transport, h.transport->system().leaf_patches, h.radiosity));
        double worst = 0.0;
        for (std::size_t s = 0; s < power.size(); ++s) {
            const double ref = reference[s].x + reference[s].y + reference[s].z;
            const double got = power[s].x + power[s].y + power[s].z;
            worst = std::max(worst, std::abs(got - ref) / ref);
        }
        std::printf(
            "tolerance %.3g: %zu base, %zu elements, %zu leaves, %zu links, %zu rounds, %.3g s "
            "(refine %.3g, solve %.3g), %.1f MB, worst surface power error %.2f %%\n",
            tolerance, h.report.base_patches, h.report.elements, h.report.leaves, h.report.links,
            h.report.rounds, seconds, h.report.refine_seconds, h.report.solve_seconds,
            h.report.memory_bytes / 1e6, 100.0 * worst);
        // 2.8 % and 2.1 % measured, the floor too bright (the light's links to it), every other surface
        // within 0.9 %; before the leaves were balanced, 1.9 % and 1.1 %, every surface too bright while the
        // energy account lost 5 % of the light.
        EXPECT_LT(worst, 0.03);
        EXPECT_LT(h.report.links, 40'000u) << "links, against " << fine.size() << "² pairs of the reference";
    }
}

// More refinement makes more leaves and links, the links growing about as the leaves do (a bounded number
// per leaf), never as their square; and the bounds on elements are kept.
TEST(Hierarchical, LinksGrowAboutLinearlyAndBoundsHold) {
    const Scene scene = make_builtin_scene("cornell");
    const double base = 4.0 * default_patch_size(scene);
    std::size_t last_leaves = 0;
    for (double tolerance : {0.01, 0.003, 0.001}) {
        HierarchicalOptions options;
        options.tolerance = tolerance;
        const Solved h = solve_hierarchical(scene, base, options);
        const double per_leaf = static_cast<double>(h.report.links) / static_cast<double>(h.report.leaves);
        std::printf("tolerance %.3g: %zu leaves, %zu links, %.1f links per leaf, %.2f s\n", tolerance,
                    h.report.leaves, h.report.links, per_leaf,
                    h.report.refine_seconds + h.report.solve_seconds);
        EXPECT_GT(h.report.leaves, last_leaves);
        // The 197 base patches alone make 21,000 first links; beyond them a few tens per leaf.
        EXPECT_LT(static_cast<double>(h.report.links),
                  25'000.0 + 40.0 * static_cast<double>(h.report.leaves));
        last_leaves = h.report.leaves;
    }
    HierarchicalOptions bounded;
    bounded.tolerance = 0.001;
    bounded.max_elements = 2000;
    const Solved h = solve_hierarchical(scene, base, bounded);
    EXPECT_LE(h.report.elements, 2000u);
    EXPECT_TRUE(h.report.limited);
}

// The white room: the Cornell box closed, ρ = 0.95, where light bounces about 20 times and any excess or
// shortfall of the leaves' form factors is multiplied as often. Nearly nothing escapes, and the power
// absorbed matches the power emitted to within 3 % (2.2 % measured at --refine-tol 0.01).
TEST(Hierarchical, AHighAlbedoClosedRoomKeepsItsEnergy) {
    const Scene scene = make_builtin_scene("white-room");
    HierarchicalOptions options;
    options.tolerance = 0.01;
    const Solved h = solve_hierarchical(scene, 4.0 * default_patch_size(scene), options);
    const EnergyBalance balance = energy_balance(*h.transport, h.radiosity);
    const double emitted = balance.emitted.x + balance.emitted.y + balance.emitted.z;
    const double absorbed = balance.absorbed.x + balance.absorbed.y + balance.absorbed.z;
    const double escaped = balance.escaped.x + balance.escaped.y + balance.escaped.z;
    std::printf("white room: %zu leaves, emitted %.6g, absorbed %.6g, escaped %.6g\n", h.report.leaves,
                emitted, absorbed, escaped);
    EXPECT_LT(escaped, 1e-3 * emitted);
    EXPECT_NEAR(absorbed / emitted, 1.0, 0.03);
}

TEST(Hierarchical, BadOptionsAreInputErrors) {
    const Scene scene = make_builtin_scene("cornell");
    const PatchMesh base = build_patches(scene, MeshingOptions{4.0 * default_patch_size(scene)});
    HierarchicalOptions options;
    options.tolerance = -1.0;
    EXPECT_THROW(build_hierarchical_system(scene, base, options), InputError);
    options = HierarchicalOptions{};
    options.visibility_rays = 100000;
    EXPECT_THROW(build_hierarchical_system(scene, base, options), InputError);
    // A base mesh too fine is refused by the memory budget of its first links, not by a fixed count:
    // test_hierarchical_memory_budget.cpp.
}

}  // namespace
}  // namespace rad
