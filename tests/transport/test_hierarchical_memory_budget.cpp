// Hierarchical radiosity's memory budget: every pair of base patches that may face each other is a first
// link, so the first links are counted and their memory checked before any is made; no fixed cap on the
// base patches. The first links are made a block of receivers at a time, with the same result as all at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "form_factor_test_scenes.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/hierarchical/hierarchical_radiosity.hpp"
#include "rad/util/error.hpp"
#include "ray/coverage.hpp"
#include "transport/hierarchical/hierarchical_first_links.hpp"
#include "transport/hierarchical/hierarchical_links.hpp"
#include "transport/hierarchical/hierarchical_refine.hpp"
#include "transport/uniform/form_factors_hemisphere.hpp"
#include "util/luminance.hpp"

namespace rad {
namespace {

// The unit cube, k × k patches a face (k = 1 / size, rounded up), seen from inside: every patch faces
// every patch of the other five faces and none of its own, so 6k² patches have 6k² × 5k² first links.
std::uint64_t cube_first_links(std::uint64_t k) {
    return 6 * k * k * 5 * k * k;
}

HierarchicalOptions with_budget(std::size_t budget) {
    HierarchicalOptions options;
    options.max_memory_bytes = budget;
    return options;
}

TEST(HierarchicalMemory, TheFirstLinksOfACubeAreThePairsOnDifferentFaces) {
    const PatchMesh base = build_patches(make_cube(), MeshingOptions{0.25});
    ASSERT_EQ(base.size(), 96u);
    const FirstLinks first = count_first_links(base, HierarchicalOptions{}, 0, nullptr);
    std::uint64_t total = 0;
    for (std::uint32_t c : first.count) {
        EXPECT_EQ(c, 80u);  // 5 faces of 16
        total += c;
    }
    EXPECT_EQ(total, cube_first_links(4));
    EXPECT_EQ(first.total, total);
    // The first face's patches face none of their own, the last face's all those of the others.
    EXPECT_EQ(first.first[0], 16u);
    EXPECT_EQ(first.last[0], 95u);
    EXPECT_EQ(first.first[95], 0u);
    EXPECT_EQ(first.last[95], 79u);
    // Listed a block at a time: receivers ascending, then sources, never on the receiver's own surface.
    std::vector<LinkCandidate> listed, block;
    for (std::uint32_t begin = 0; begin < 96; begin += 10) {
        list_first_links(base, first, begin, std::min(96u, begin + 10), block);
        listed.insert(listed.end(), block.begin(), block.end());
    }
    ASSERT_EQ(listed.size(), 7680u);
    for (std::size_t k = 0; k < listed.size(); ++k) {
        const LinkCandidate c = listed[k];
        EXPECT_NE(base.patches[c.receiver].surface, base.patches[c.source].surface);
        if (k > 0) {
            const LinkCandidate p = listed[k - 1];
            EXPECT_TRUE(p.receiver < c.receiver || (p.receiver == c.receiver && p.source < c.source));
        }
    }
}

// The first links: 512 bytes a base patch, 36 a first link (a 28-byte link, an 8-byte candidate), 32 a
// candidate of the block being estimated (the candidate and its 24-byte estimate). Refinement beyond: 92 a
// link (the link three times over while its vector grows, and a candidate).
TEST(HierarchicalMemory, TheEstimatesAreTheElementsAndTheLinks) {
    EXPECT_EQ(kFirstLinkBytes, 36u);
    EXPECT_EQ(kFirstLinkBlockBytes, 32u);
    EXPECT_EQ(kHierarchicalLinkBytes, 92u);
    EXPECT_EQ(first_links_memory_estimate(96, 7680), 96u * 512u + 7680u * 36u + 7680u * 32u);
    EXPECT_EQ(first_links_memory_estimate(96, 7680), 571'392u);
    // The block holds 2^18 candidates at most.
    EXPECT_EQ(first_links_memory_estimate(0, 1'000'000), 1'000'000u * 36u + (1u << 18) * 32u);
    EXPECT_EQ(hierarchical_memory_estimate(96, 7680), 96u * 512u + 7680u * 92u);
    EXPECT_EQ(hierarchical_memory_estimate(std::size_t{1} << 62, 1), std::numeric_limits<std::size_t>::max());
    EXPECT_EQ(first_links_memory_estimate(1, std::uint64_t{1} << 62),
              std::numeric_limits<std::size_t>::max());
}

// One byte short of what the base patches and their first links need: refused before anything is built,
// with the figures, and a coarser patch size whose first links fit.
TEST(HierarchicalMemory, ABudgetOneByteShortIsRefusedWithTheFigures) {
    const Scene cube = make_cube();
    const PatchMesh base = build_patches(cube, MeshingOptions{0.25});
    HierarchicalOptions options = with_budget(571'391);
    options.patch_size = 0.25;
    options.count_patches_at = [&cube](double size) { return count_patches(cube, size); };
    Progress progress;
    try {
        build_hierarchical_system(cube, base, options, nullptr, &progress);
        FAIL() << "a budget one byte short was accepted";
    } catch (const MemoryBudgetError& e) {
        EXPECT_EQ(e.setting(), "max_memory");
        EXPECT_EQ(e.needed_bytes, 571'392u);
        EXPECT_EQ(e.budget_bytes, 571'391u);
        EXPECT_EQ(e.patches, 96u);
        const std::string message = e.what();
        EXPECT_NE(message.find("first links of 96 base patches (7680 pairs"), std::string::npos) << message;
        EXPECT_EQ(message.find("from a sample"), std::string::npos) << message;
        // 4 × 4 a face do not fit; 3 × 3 (54 patches, 54 × 45 first links) do.
        EXPECT_GT(e.coarser_patch_size, 1.0 / 3.0);
        EXPECT_LT(e.coarser_patch_size, 0.5);
        EXPECT_EQ(count_patches(cube, e.coarser_patch_size), 54u);
        EXPECT_LE(first_links_memory_estimate(54, cube_first_links(3)), 571'391u);
    }
    EXPECT_EQ(progress.state().stage, "counting the first links") << "refused before linking";
}

// Exactly the budget: the first links are made and nothing more, as no split fits; with the budget the
// machine gives, the same cube refines.
TEST(HierarchicalMemory, ExactlyTheBudgetMakesTheFirstLinksAndStopsSplitting) {
    const Scene cube = make_cube();
    const PatchMesh base = build_patches(cube, MeshingOptions{0.25});
    HierarchicalReport report;
    build_hierarchical_system(cube, base, with_budget(571'392), &report);
    EXPECT_EQ(report.first_links, 7680u);
    EXPECT_EQ(report.elements, 96u);
    EXPECT_EQ(report.links, 7680u);  // nothing blocks any pair in an empty cube
    EXPECT_TRUE(report.limited);
    EXPECT_LE(first_links_memory_estimate(report.elements, report.links), 571'392u);

    HierarchicalReport unbounded;
    build_hierarchical_system(cube, base, HierarchicalOptions{}, &unbounded);
    EXPECT_GT(unbounded.elements, 96u);
    EXPECT_GT(unbounded.links, 7680u);
    EXPECT_FALSE(unbounded.limited);
}

// A budget between the first links and what refinement wants: refinement stops at it.
TEST(HierarchicalMemory, RefinementKeepsToTheBudget) {
    const Scene cube = make_cube();
    const PatchMesh base = build_patches(cube, MeshingOptions{0.25});
    HierarchicalReport unbounded;
    build_hierarchical_system(cube, base, HierarchicalOptions{}, &unbounded);
    const std::size_t budget = (hierarchical_memory_estimate(96, 7680) +
                                hierarchical_memory_estimate(unbounded.elements, unbounded.links)) /
                               2;
    HierarchicalReport bounded;
    build_hierarchical_system(cube, base, with_budget(budget), &bounded);
    EXPECT_TRUE(bounded.limited);
    EXPECT_GT(bounded.elements, 96u);
    EXPECT_LT(bounded.elements, unbounded.elements);
    EXPECT_LE(hierarchical_memory_estimate(bounded.elements, bounded.links), budget);
}

// A floor of 142 × 142 base patches under a lamp of one: 20,165 base patches, over the 20,000 once refused
// whatever the budget, but only the lamp and the floor face each other, 2 × 20,164 first links. With
// exactly their budget it builds; one byte less and it is refused.
TEST(HierarchicalMemory, MoreThanTwentyThousandBasePatchesBuildWithinTheirBudget) {
    Scene scene =
        test::TestSceneBuilder()
            .add("floor", {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}})
            .add("lamp", {{0.5, 0.5, 0.5}, {0.505, 0.5, 0.5}, {0.505, 0.5, 0.505}, {0.5, 0.5, 0.505}})
            .build();
    scene.surfaces[1].material.emission = glm::dvec3(1.0);
    const PatchMesh base = build_patches(scene, MeshingOptions{1.0 / 141.5});
    ASSERT_EQ(base.size(), 20'165u);
    const std::size_t need = 20'165u * 512u + 40'328u * (36u + 32u);
    HierarchicalOptions options = with_budget(need);
    options.min_patch_size = 1.0;  // no splits: the count is the point here
    options.rounds = 1;
    HierarchicalReport report;
    const auto system = build_hierarchical_system(scene, base, options, &report);
    EXPECT_EQ(report.base_patches, 20'165u);
    EXPECT_EQ(report.first_links, 40'328u);
    EXPECT_EQ(report.links, 40'328u);
    EXPECT_EQ(system->leaves.size(), 20'165u);

    options.max_memory_bytes = need - 1;
    try {
        build_hierarchical_system(scene, base, options);
        FAIL() << "a budget one byte short was accepted";
    } catch (const MemoryBudgetError& e) {
        EXPECT_EQ(e.needed_bytes, need);
        EXPECT_EQ(e.patches, 20'165u);
    }
}

// 20,184 base patches in a closed cube, 58 × 58 a face, have 3.4e8 first links, 11.4 GB: refused at once
// from a sample of the pairs, before 2e8 pairs are tested, with figures within 1 % of the exact ones.
TEST(HierarchicalMemory, AMeshFarOverTheBudgetIsRefusedFromASample) {
    const Scene cube = make_cube();
    const PatchMesh base = build_patches(cube, MeshingOptions{1.0 / 57.5});
    ASSERT_EQ(base.size(), 20'184u);
    const std::size_t exact = first_links_memory_estimate(20'184, cube_first_links(58));
    EXPECT_EQ(exact, std::size_t{20'184} * 512 + std::size_t{339'494'880} * 36 + (std::size_t{1} << 18) * 32);
    HierarchicalOptions options = with_budget(std::size_t{1} << 30);
    options.count_patches_at = [&cube](double size) { return count_patches(cube, size); };
    try {
        build_hierarchical_system(cube, base, options);
        FAIL() << "11.4 GB of first links fit in 1 GB";
    } catch (const MemoryBudgetError& e) {
        EXPECT_NEAR(static_cast<double>(e.needed_bytes), static_cast<double>(exact), 0.01 * exact);
        EXPECT_EQ(e.budget_bytes, std::size_t{1} << 30);
        EXPECT_EQ(e.patches, 20'184u);
        const std::string message = e.what();
        EXPECT_NE(message.find("from a sample"), std::string::npos) << message;
        EXPECT_NE(message.find("over the budget of 1 GB"), std::string::npos) << message;
        // The suggestion fits: k × k a face at that size.
        ASSERT_GT(e.coarser_patch_size, 1.0 / 57.5);
        const auto k = static_cast<std::uint64_t>(std::ceil(1.0 / e.coarser_patch_size));
        EXPECT_LE(first_links_memory_estimate(6 * k * k, cube_first_links(k)), e.budget_bytes);
        EXPECT_GT(k, 20u) << "not needlessly coarse";
    }
}

TEST(HierarchicalMemory, CountingStopsWhenCancelled) {
    const PatchMesh base = build_patches(make_cube(), MeshingOptions{0.25});
    Progress progress;
    progress.cancel();
    EXPECT_THROW(build_hierarchical_system(make_cube(), base, HierarchicalOptions{}, nullptr, &progress),
                 Cancelled);
    EXPECT_EQ(progress.state().stage, "counting the first links");
}

// The links a refiner makes over the Cornell box's base patches, run by `run` from the same start.
struct Refined {
    std::vector<HierarchicalLink> links;
    std::size_t elements = 0;
    std::uint64_t rays = 0;
};

Refined refine_cornell(const std::function<void(LinkRefiner&, const PatchMesh&)>& run) {
    const Scene scene = make_builtin_scene("cornell");
    const PatchMesh base = build_patches(scene, MeshingOptions{4.0 * default_patch_size(scene)});
    const HierarchicalOptions options;
    HierarchicalSystem system(base);
    double area = 0.0, emitted = 0.0, reflected = 0.0;
    for (const Patch& p : base.patches) {
        const Material& material = scene.surfaces[p.surface].material;
        system.reflectance.push_back(material.reflectance);
        system.emission.push_back(material.emitted_radiosity());
        area += p.area;
        emitted += p.area * luminance(material.emitted_radiosity());
        reflected += p.area * luminance(material.reflectance);
    }
    const RayScene rays(base);
    std::vector<double> covered(base.size());
    measure_coverage(base, rays, options.seed, covered);
    for (double c : covered) system.exposed_share.push_back(static_cast<float>(1.0 - c));
    const LinkEstimator estimator(system.tree, system.exposed_share, rays, ray_offset(base),
                                  options.visibility_rays, options.seed);
    HierarchicalReport report;
    double longest = 0.0;
    for (std::uint32_t e = 0; e < base.size(); ++e) longest = std::max(longest, system.tree.longest_edge(e));
    LinkRefiner refiner(system, estimator, options, longest / 8.0, 0, report, nullptr);
    refiner.set_epsilon(0.02 * emitted / area / (1.0 - reflected / area));
    run(refiner, base);
    return {system.links, system.tree.size(), report.rays};
}

// The first links made in blocks of about 1,000 pairs give the links, elements and rays of all 21,000 at
// once, bit for bit.
TEST(HierarchicalMemory, BlocksOfFirstLinksRefineAsTheWholeList) {
    const Refined whole = refine_cornell([](LinkRefiner& refiner, const PatchMesh& base) {
        std::vector<LinkCandidate> all;
        list_first_links(base, count_first_links(base, HierarchicalOptions{}, 0, nullptr), 0,
                         static_cast<std::uint32_t>(base.size()), all);
        refiner.refine(std::move(all));
    });
    const Refined blocks = refine_cornell([](LinkRefiner& refiner, const PatchMesh& base) {
        refiner.refine_first(base, count_first_links(base, HierarchicalOptions{}, 0, nullptr), 1000);
    });
    EXPECT_GT(whole.elements, 197u) << "refinement split elements";
    EXPECT_EQ(blocks.elements, whole.elements);
    EXPECT_EQ(blocks.rays, whole.rays);
    ASSERT_EQ(blocks.links.size(), whole.links.size());
    for (std::size_t k = 0; k < whole.links.size(); ++k) {
        const HierarchicalLink& a = whole.links[k];
        const HierarchicalLink& b = blocks.links[k];
        ASSERT_EQ(a.receiver, b.receiver) << k;
        ASSERT_EQ(a.source, b.source) << k;
        for (int c = 0; c < 4; ++c) EXPECT_EQ(a.factor[c], b.factor[c]) << k;
        EXPECT_EQ(a.uncertainty, b.uncertainty) << k;
    }
}

}  // namespace
}  // namespace rad
