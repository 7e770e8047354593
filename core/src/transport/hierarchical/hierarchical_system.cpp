// Building a HierarchicalSystem: the first links between base patches, rounds of refinement and solving,
// and the leaves as patches.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "rad/transport/hierarchical/hierarchical_radiosity.hpp"
#include "rad/util/error.hpp"
#include "rad/util/stopwatch.hpp"
#include "ray/coverage.hpp"
#include "ray/ray_offset.hpp"
#include "transport/external/outside_light.hpp"
#include "transport/hierarchical/hierarchical_first_links.hpp"
#include "transport/hierarchical/hierarchical_refine.hpp"
#include "transport/patch_materials.hpp"
#include "transport/refinement_settings.hpp"
#include "transport/uniform/form_factors_memory.hpp"
#include "util/luminance.hpp"

namespace rad {

namespace {

// Jacobi steps between rounds: the oracle needs the radiosity roughly, not converged.
constexpr int kRoundSteps = 64;
constexpr double kRoundTolerance = 1e-3;

void index_links(HierarchicalSystem& system) {
    std::sort(system.links.begin(), system.links.end(),
              [](const HierarchicalLink& a, const HierarchicalLink& b) {
                  return a.receiver != b.receiver ? a.receiver < b.receiver : a.source < b.source;
              });
    system.receiver_runs.clear();
    for (std::size_t l = 0; l < system.links.size(); ++l) {
        if (l == 0 || system.links[l].receiver != system.links[l - 1].receiver)
            system.receiver_runs.push_back(static_cast<std::uint32_t>(l));
    }
    system.receiver_runs.push_back(static_cast<std::uint32_t>(system.links.size()));
}

// Jacobi steps from `radiosity` until the update's power falls below kRoundTolerance of the emitted power.
void solve_roughly(const HierarchicalSystem& system, std::vector<glm::dvec3>& radiosity) {
    std::vector<glm::dvec3> next(radiosity.size());
    double emitted = 0.0;
    for (std::uint32_t e = 0; e < system.tree.base_size(); ++e)
        emitted += system.tree[e].shape.area * luminance(system.emission[e]);
    for (int step = 0; step < kRoundSteps; ++step) {
        gather_push_pull(system, radiosity, next);
        double change = 0.0;
        for (std::uint32_t e = 0; e < system.tree.base_size(); ++e)
            change += system.tree[e].shape.area * std::abs(luminance(next[e] - radiosity[e]));
        radiosity.swap(next);
        if (!(change > kRoundTolerance * emitted)) break;
    }
}

// The error a link may leave, as an absolute radiosity: tolerance × the mean radiosity over the base patches,
// estimated before any solve as the mean emission / (1 − mean reflectance) (exact for a closed furnace).
double link_epsilon(const HierarchicalSystem& system, std::span<const glm::dvec3> radiosity, double tolerance,
                    bool solved) {
    double area = 0.0, b = 0.0, rho = 0.0;
    for (std::uint32_t e = 0; e < system.tree.base_size(); ++e) {
        const double a = system.tree[e].shape.area;
        area += a;
        b += a * luminance(radiosity[e]);
        rho += a * luminance(system.reflectance[e]);
    }
    if (!(area > 0.0)) return 0.0;
    const double mean = solved ? b / area : b / area / std::max(1e-3, 1.0 - rho / area);
    return tolerance * mean;
}

void finish_leaves(HierarchicalSystem& system) {
    system.leaves = system.tree.leaves();
    system.leaf_patches = system.tree.leaf_mesh(system.leaves);
}

// "197 base patches, 25484 first links (1.75 MB), up to 4 rounds of 16 rays per link, refined within
// 60000000 links and 11.8 GB": the work and what bounds its memory, told before the links are built.
std::string linking_note(const PatchMesh& base, std::uint64_t first_links, std::size_t budget,
                         const HierarchicalOptions& o) {
    const std::string first =
        format_bytes(static_cast<double>(first_links_memory_estimate(base.size(), first_links)));
    return std::to_string(base.size()) + " base patches, " + std::to_string(first_links) + " first links (" +
           first + "), up to " + std::to_string(std::max(1, o.rounds)) + " rounds of " +
           std::to_string(o.visibility_rays) + " rays per link, refined within " +
           std::to_string(o.max_links) + " links" +
           (budget > 0 ? " and " + format_bytes(static_cast<double>(budget)) : std::string());
}

}  // namespace

std::size_t HierarchicalSystem::memory_bytes() const {
    return tree.memory_bytes() + links.capacity() * sizeof(HierarchicalLink) +
           receiver_runs.capacity() * sizeof(std::uint32_t) +
           (reflectance.capacity() + emission.capacity()) * sizeof(glm::dvec3) +
           leaves.capacity() * sizeof(std::uint32_t) +
           (exposed_share.capacity() + leaf_scale.capacity() + send_scale.capacity() +
            escaping_share.capacity() + reaching_share.capacity()) *
               sizeof(float);
}

std::unique_ptr<HierarchicalSystem> build_hierarchical_system(const Scene& scene, const PatchMesh& base,
                                                              const HierarchicalOptions& options,
                                                              HierarchicalReport* report_out,
                                                              Progress* progress) {
    HierarchicalOptions o = options;
    if (o.visibility_rays == 0) o.visibility_rays = 16;
    check_refinement_settings(o.tolerance, o.min_patch_size, o.visibility_rays);
    // Every pair of base patches that may face each other is a first link: counted, and checked against
    // the budget, before anything is built.
    const std::size_t budget = memory_budget_bytes(o.max_memory_bytes);
    const FirstLinks first_links = count_first_links(base, o, budget, progress);
    auto system = std::make_unique<HierarchicalSystem>(base);
    append_patch_materials(scene, base, system->reflectance, system->emission);
    HierarchicalReport report;
    report.base_patches = base.size();
    report.first_links = first_links.total;
    double longest = 0.0;
    for (std::uint32_t e = 0; e < base.size(); ++e) longest = std::max(longest, system->tree.longest_edge(e));
    report.min_patch_size = o.min_patch_size > 0.0 ? o.min_patch_size : longest / 64.0;

    const RayScene rays(base);
    std::vector<double> covered(base.size());
    measure_coverage(base, rays, o.seed, covered);
    for (double c : covered) system->exposed_share.push_back(static_cast<float>(1.0 - c));
    add_outside_light(scene, base, rays, o.seed, system->exposed_share, system->reflectance, system->emission,
                      progress);
    const LinkEstimator estimator(system->tree, system->exposed_share, rays, ray_offset(base),
                                  o.visibility_rays, o.seed);
    LinkRefiner refiner(*system, estimator, o, report.min_patch_size, budget, report, progress);
    for (int round = 0; round < std::max(1, o.rounds); ++round) {
        const Stopwatch refine_clock;
        refiner.set_epsilon(link_epsilon(*system, refiner.radiosity(), o.tolerance, round > 0));
        // The links are refined as they are estimated, so their count, and the share done, is not known
        // in advance: the stage has no total, but for the first estimates of the first links.
        if (progress && round == 0) {
            progress->begin("linking elements, the first links", report.first_links);
            progress->note(linking_note(base, report.first_links, budget, o));
        } else if (progress) {
            progress->begin("linking elements, round " + std::to_string(round + 1), 0);
        }
        const bool changed =
            round == 0 ? (refiner.refine_first(base, first_links), true) : refiner.refine_again();
        report.refine_seconds += refine_clock.seconds();
        if (!changed) break;
        ++report.rounds;
        index_links(*system);
        normalize_leaf_form_factors(*system, refiner.measure_reaching());
        const Stopwatch solve_clock;
        if (progress) progress->begin("solving between rounds", 0);
        solve_roughly(*system, refiner.radiosity());
        report.solve_seconds += solve_clock.seconds();
    }
    if (progress) progress->begin("balancing the leaves' energy", 0);
    system->reaching_share = refiner.measure_reaching();
    balance_leaf_form_factors(*system, system->reaching_share);
    finish_leaves(*system);
    report.elements = system->tree.size();
    report.leaves = system->leaves.size();
    report.links = system->links.size();
    report.memory_bytes = system->memory_bytes();
    if (report_out) *report_out = report;
    return system;
}

}  // namespace rad
