#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <memory>
#include <span>
#include <vector>

#include "rad/mesh/element_tree.hpp"
#include "rad/scene/scene.hpp"
#include "rad/transport/transport.hpp"
#include "rad/util/progress.hpp"

namespace rad {

// Hierarchical radiosity (Hanrahan, Salzman and Aupperle 1991): the base patches are split into a quadtree of
// elements, and light moves along links between elements of whatever size keeps each link's error small.
// Memory and time grow with elements plus links instead of patches².
struct HierarchicalOptions {
    // A link is refined while the error it may put into its receiver's radiosity (reflectance × the
    // source's radiosity × the link's uncertainty) exceeds tolerance × the scene's mean radiosity.
    double tolerance = 0.02;
    // Elements are not split when their longest edge is at most this (scene units); 0 picks the base
    // patches' largest edge / 64.
    double min_patch_size = 0.0;
    int visibility_rays = 16;  // shadow rays per link; 0 picks 16
    // Refinement rounds: refine the links with the radiosity known so far, solve, and refine again.
    int rounds = 4;
    // Bounds on the work: refinement stops splitting (and says so in the report) rather than exceed them.
    std::size_t max_elements = 4'000'000;
    std::size_t max_links = 60'000'000;
    std::uint64_t seed = 1;
    // The memory budget (0: half the machine's or container's memory, as for form factors). Every pair of
    // base patches that may face each other is a first link, whatever the refinement: when those alone
    // would not fit, the build is refused with MemoryBudgetError before any link is made; past them,
    // refinement stops splitting at the budget as at max_elements and max_links (the estimates:
    // core/src/transport/hierarchical/hierarchical_first_links.hpp).
    std::size_t max_memory_bytes = 0;
    // Only for naming a coarser patch size when the first links do not fit, as in FormFactorOptions: the
    // size the base patches were made with (0: their longest edge stands in for it), and how many base
    // patches the scene makes at a size.
    double patch_size = 0.0;
    std::function<std::size_t(double patch_size)> count_patches_at;
};

// Light from `source` gathered by `receiver`. The irradiance it brings varies over the receiver: at the
// receiver's corner k it is factor[k] × B_source, and in between it is interpolated (bilinearly on quads,
// linearly on triangles), so a large receiver beside a wall gets its light falling off towards the wall
// instead of one mean value pushed to all its parts.
struct HierarchicalLink {
    std::uint32_t receiver = 0;
    std::uint32_t source = 0;
    // The form factor from receiver to source, times their visibility, at each corner (a triangle repeats its
    // last); their mean is the receiver's mean form factor.
    float factor[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    // How far the interpolated factor may be off somewhere on the receiver, as a share of the source's
    // radiosity: the kernel's departure from the interpolation plus the error a partly blocked pair may
    // hide. What refinement weighs.
    float uncertainty = 0.0f;

    float mean_factor() const { return 0.25f * (factor[0] + factor[1] + factor[2] + factor[3]); }
};

struct HierarchicalReport {
    std::size_t base_patches = 0;
    std::size_t elements = 0;
    std::size_t leaves = 0;
    std::size_t links = 0;
    std::size_t rounds = 0;         // rounds that changed the links
    std::uint64_t rays = 0;         // visibility rays cast
    double refine_seconds = 0.0;    // estimating and refining links
    double solve_seconds = 0.0;     // the solves between rounds
    std::size_t memory_bytes = 0;   // elements, points and links
    std::uint64_t first_links = 0;  // pairs of base patches that may face each other (each way)
    bool limited = false;           // max_elements, max_links or the memory budget stopped a split
    double min_patch_size = 0.0;    // the bound used
};

// The elements, their links, and the leaves as patches: what a solver steps.
struct HierarchicalSystem {
    ElementTree tree;
    std::vector<HierarchicalLink> links;       // sorted by receiver
    std::vector<std::uint32_t> receiver_runs;  // links of one receiver are [runs[k], runs[k + 1])
    std::vector<glm::dvec3> reflectance;       // per element
    std::vector<glm::dvec3> emission;          // per element, E = π Le
    // Per element, the share of its area that other geometry does not cover (a box on a floor covers part
    // of the floor); negative until measured. Light leaves only from the exposed part.
    std::vector<float> exposed_share;
    // Per element (read at the leaves only), what scales the irradiance a leaf gathers so that its form
    // factors sum to its form factor to the whole scene, measured by rays (1 in a closed room). Each
    // link's factor is right on average over its receiver, but interpolated to a small leaf, the links of
    // all its ancestors can add up to a few per cent more or less than the whole scene (most in corners
    // where three surfaces meet); at high albedo that error would be multiplied bounce after bounce.
    // Empty: no scaling.
    std::vector<float> leaf_scale;
    // Per element (read at the leaves only), what scales the light a leaf sends into the links, set with
    // leaf_scale by balance_leaf_form_factors so that each leaf sends what it gathers. Empty: no scaling.
    std::vector<float> send_scale;
    // Per element: the measured share of the rays from its exposed part that meet nothing (negative: not
    // measured).
    std::vector<float> escaping_share;
    // Per element: the measured share of the rays from its exposed part that meet a front, times its
    // exposed share (negative: not measured); what the balance scaled the leaves towards.
    std::vector<float> reaching_share;
    std::vector<std::uint32_t> leaves;  // leaf elements; patch k of leaf_patches is leaves[k]
    PatchMesh leaf_patches;

    explicit HierarchicalSystem(const PatchMesh& base) : tree(base) {}
    std::size_t memory_bytes() const;
};

// Builds the hierarchy over `base` (build_patches of `scene`): links between all base patches that see each
// other, refined, solved and refined again for options.rounds rounds. The first links are counted before
// any is made, and made a block of receivers at a time, so the n² pairs are never listed at once. Throws
// InputError for bad options, MemoryBudgetError when the first links would not fit the budget, and
// Cancelled when progress is cancelled.
std::unique_ptr<HierarchicalSystem> build_hierarchical_system(const Scene& scene, const PatchMesh& base,
                                                              const HierarchicalOptions& options,
                                                              HierarchicalReport* report = nullptr,
                                                              Progress* progress = nullptr);

// One Jacobi step on the hierarchy: gather along the links, push irradiance down to the leaves and pull
// radiosity up. `radiosity` and `out` hold one value per element, the mean over the whole element. When
// given (one per element), leaf_irradiance receives each leaf's mean irradiance.
void gather_push_pull(const HierarchicalSystem& system, std::span<const glm::dvec3> radiosity,
                      std::span<glm::dvec3> out, std::span<glm::dvec3> leaf_irradiance = {});

// Rays per leaf that measure its form factor to the whole scene.
inline constexpr int kReachingRays = 64;

// Sets leaf_scale from the links as they stand and, per element, its measured form factor to the whole
// scene times its exposed_share (negative: not measured, no scaling).
void normalize_leaf_form_factors(HierarchicalSystem& system, std::span<const float> reaching);

// Sets leaf_scale and send_scale so that the leaves' gather T' = diag(leaf_scale) T diag(send_scale) has,
// for every leaf, the row sum (what it gathers of a uniform radiosity) and the column share (what arrives
// somewhere of its own light, per unit of exposed area) both at the row target normalize_leaf_form_factors
// scales to: light then leaves each leaf in the amount it arrives, and emitted = absorbed + escaped holds
// for any radiosity (the links alone are not reciprocal). Sinkhorn's alternation, as clustering's balance;
// both scales at most 64. Returns the largest row error left.
double balance_leaf_form_factors(HierarchicalSystem& system, std::span<const float> reaching);

// The transpose of the leaves' gather with leaf_scale as it stands, send_scale left out: per leaf s,
// Σ_k weights[k] × (the mean irradiance over leaf k when s's exposed part alone shines with radiosity 1).
// One entry per element in both spans; the leaves' are read and written.
void spread_leaves(const HierarchicalSystem& system, std::span<const double> weights, std::span<double> out);

// Hierarchical radiosity as a Transport: its elements are the leaves (patch k of leaf_patches is leaf k), and
// gather pulls the leaves' radiosity up the trees, gathers along the links and pushes the irradiance down to
// the leaves. As with uniform patches, a leaf's area is its exposed area and its radiosity that of the
// exposed part (whole_patch_radiosity gives the mean over the whole leaf).
class HierarchicalTransport final : public Transport {
  public:
    HierarchicalTransport(std::unique_ptr<HierarchicalSystem> system, const HierarchicalReport& report);

    void gather(std::span<const glm::dvec3> radiosity, std::span<glm::dvec3> irradiance) const override;
    // What reaches other elements when every element shines with radiosity 1, per unit of exposed area.
    std::vector<double> reach() const override;
    std::vector<double> escape() const override;  // the leaves' measured escape
    TransportReport report() const override;

    const HierarchicalSystem& system() const { return *system_; }
    const HierarchicalReport& hierarchical_report() const { return report_; }

  private:
    std::unique_ptr<HierarchicalSystem> system_;
    HierarchicalReport report_;
};

// build_hierarchical_system as a transport.
std::unique_ptr<HierarchicalTransport> make_hierarchical_transport(const Scene& scene, const PatchMesh& base,
                                                                   const HierarchicalOptions& options,
                                                                   Progress* progress = nullptr);

}  // namespace rad
