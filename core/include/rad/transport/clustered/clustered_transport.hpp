#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <span>
#include <vector>

#include "rad/mesh/element_tree.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"
#include "rad/transport/transport.hpp"
#include "rad/transport/uniform/form_factor_matrix.hpp"
#include "rad/util/progress.hpp"

namespace rad {

// Hierarchical radiosity with clusters (Smits, Arvo and Greenberg 1994; Sillion 1995): a tree of volume
// clusters over the base patches (Embree's BVH of their boxes) above the element quadtrees of the patches.
// Refinement starts from the root cluster's link to itself; a link is split on its larger side (a cluster
// into its children, an element into quarters) while the error it may leave in its receiver exceeds the
// tolerance. Clusters send and receive by the orientations of their contents, summarized as the area their
// surfaces present along each of the six axis directions (exact for axis-aligned surfaces, a smooth
// approximation otherwise); an isotropic cluster (projected area A / 4 in every direction) is the
// alternative (isotropic_clusters), and for flat clusters such as a tessellated wall it is four times off.
// A quarter of the uniform patch size (a sixteenth of the extent): the display draws a hierarchy on patches
// of that size, each gathering its own last bounce, so finer leaves cost links without showing
// (docs/measurements.md, "Hierarchies drawn on patches of their own").
inline constexpr double kClusteredMinPatchFraction = 64.0;

struct ClusteredOptions {
    // A link is refined while reflectance × the source's radiosity × the link's form-factor bound exceeds
    // tolerance × the scene's mean radiosity.
    double tolerance = 0.05;
    // Elements are not split when their longest edge is at most this; 0 picks the scene's largest extent /
    // kClusteredMinPatchFraction.
    double min_patch_size = 0.0;
    int visibility_rays = 4;  // shadow rays per link
    // Shadow rays per leaf for the emitters' direct light (at most 64 per emitter base patch), where it is
    // aimed at them rather than linked (few and small emitters).
    int direct_light_rays = 256;
    unsigned max_cluster_patches = 4;  // base patches in a leaf cluster
    std::size_t max_links = 50'000'000;
    // Refinement stops where the elements and links would take more (0: half the machine's memory); a
    // scene whose base patches alone would is refused up front (MemoryBudgetError).
    std::size_t max_memory_bytes = 0;
    // Clusters send and receive isotropically (each surface inside takes a quarter of the irradiance at a
    // surface facing the source, and a cluster's projected share is a quarter in every direction) instead of
    // by the orientations of their contents: the alternative, kept to measure the difference.
    bool isotropic_clusters = false;
    std::uint64_t seed = 1;
};

// What refinement counts per element and per link, for the memory budget: the element with its
// reflectance, emission and per-leaf state (its leaf patch included); the link while pending, then made,
// sorted and indexed.
inline constexpr std::size_t kClusteredElementBytes = 512;
inline constexpr std::size_t kClusteredLinkBytes = 72;

struct ClusteredReport {
    std::size_t base_patches = 0;
    std::size_t clusters = 0;
    std::size_t elements = 0;  // nodes of the element trees, base patches included
    std::size_t leaves = 0;
    std::size_t links = 0;
    std::size_t cluster_links = 0;  // links with a cluster at one end or both
    std::uint64_t rays = 0;
    double seconds = 0.0;
    std::size_t memory_bytes = 0;
    bool limited = false;         // max_links stopped refinement
    bool memory_limited = false;  // the memory budget stopped refinement
    std::size_t memory_budget = 0;
    double balance_error = 0.0;  // the largest row error the energy balancing of the leaves left
    double min_patch_size = 0.0;
};

// A node of the hierarchy: a cluster, or an element of the element trees.
struct ClusterNode {
    static constexpr std::uint32_t kClusterBit = 0x80000000u;
    static std::uint32_t cluster(std::uint32_t c) { return c | kClusterBit; }
    static bool is_cluster(std::uint32_t node) { return (node & kClusterBit) != 0; }
    static std::uint32_t index(std::uint32_t node) { return node & ~kClusterBit; }
};

struct ClusterLink {
    std::uint32_t receiver = 0;  // ClusterNode encoding
    std::uint32_t source = 0;
    // Irradiance at an element receiver per unit radiosity of the source, visibility included; for a cluster
    // receiver, the same at a surface facing the source, which each surface inside takes by its cosine
    // towards `direction` (unit, from the receiver to the source).
    float factor = 0.0f;
    glm::vec3 direction{0.0f};
};

// Clusters, elements and links; the leaves of the element trees are what the solution is indexed by.
struct ClusterHierarchy {
    struct Cluster {
        glm::dvec3 centre{0.0};
        double radius = 0.0;
        glm::dvec3 lower{0.0}, upper{0.0};  // its box
        double area = 0.0;
        std::uint32_t first_child = 0;  // inner: children [first_child, first_child + child_count)
        std::uint32_t child_count = 0;  // 0: a leaf cluster, holding base patches [patch_begin, patch_end)
        std::uint32_t patch_begin = 0;  // into patch_order, for every cluster
        std::uint32_t patch_end = 0;
        // Σ A max(0, ±n·axis) over its surfaces, for +x, −x, +y, −y, +z, −z.
        std::array<double, 6> facing{};
    };
    std::vector<Cluster> clusters;           // 0 is the root; children after their parents
    std::vector<std::uint32_t> patch_order;  // base patches, cluster by cluster
    ElementTree tree;
    std::vector<glm::dvec3> reflectance;  // per element
    std::vector<glm::dvec3> emission;     // per element, E = π Le
    bool isotropic = false;               // ClusteredOptions::isotropic_clusters
    std::vector<ClusterLink> links;       // sorted by receiver
    std::vector<std::uint32_t> receiver_runs;
    // Per leaf (in `leaves` order): the measured shares of rays that meet a front and that are not covered
    // (another surface face to face), and the scales of what it gathers and what it sends that make the
    // links conserve energy (balance_leaves). Its radiosity is that of its exposed part.
    std::vector<float> reach;
    std::vector<float> exposed;
    std::vector<float> escape;  // per leaf: the measured share of its exposed part's rays that meet nothing
    std::vector<float> receive_scale;
    std::vector<float> send_scale;
    std::vector<std::uint32_t> leaves;
    PatchMesh leaf_patches;
    // The emitters' light aimed at each leaf by shadow rays (as the uniform transport's light columns are),
    // where the emitters are few and small enough: the links then carry each leaf's radiosity less what it
    // emits, and the leaves gather the emission by these factors instead.
    struct DirectLight {
        static constexpr std::uint32_t kNone = 0xffffffffu;
        std::vector<std::uint32_t> emitters;     // base patches, ascending
        std::vector<std::uint32_t> leaf_column;  // per leaf: its base patch's index in `emitters`, or kNone
        FormFactorMatrix factors;                // rows: leaves, per unit exposed area; columns: `emitters`
        // Per column, what the leaves receive of its light per unit of its leaves' exposed area: the
        // emitter's reach for what it emits (the links carry the rest of its radiosity).
        std::vector<float> share;
        std::uint64_t rays = 0;
        bool empty() const { return emitters.empty(); }
    };
    DirectLight direct;

    explicit ClusterHierarchy(const PatchMesh& base) : tree(base) {}
    std::size_t memory_bytes() const;
};

class ClusteredTransport final : public Transport {
  public:
    ClusteredTransport(std::unique_ptr<ClusterHierarchy> hierarchy, const ClusteredReport& report);

    void gather(std::span<const glm::dvec3> radiosity, std::span<glm::dvec3> irradiance) const override;
    std::vector<double> reach() const override;
    std::vector<double> escape() const override;  // the leaves' measured escape
    TransportReport report() const override;

    const ClusterHierarchy& hierarchy() const { return *hierarchy_; }
    const ClusteredReport& clustered_report() const { return report_; }

  private:
    std::unique_ptr<ClusterHierarchy> hierarchy_;
    ClusteredReport report_;
};

// Builds the clusters over `base` (build_patches of `scene`), refines the links from the root's link to
// itself and normalizes each leaf's gathered factors to its measured reach. Throws SettingError for bad
// options and Cancelled when `progress` is cancelled.
std::unique_ptr<ClusteredTransport> make_clustered_transport(const Scene& scene, const PatchMesh& base,
                                                             const ClusteredOptions& options,
                                                             Progress* progress = nullptr);

}  // namespace rad
