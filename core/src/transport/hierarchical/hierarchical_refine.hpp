#pragma once

// Link refinement for hierarchical radiosity: the oracle that decides whether a link is good enough, and the
// passes that estimate candidate links and split elements until every link is. Private to the library.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rad/transport/hierarchical/hierarchical_radiosity.hpp"
#include "transport/hierarchical/hierarchical_links.hpp"

namespace rad {

struct LinkCandidate {
    std::uint32_t receiver;
    std::uint32_t source;
};

struct FirstLinks;

// Candidates listed and estimated at a time in refine_first: a few MB, and enough to time the first block.
inline constexpr std::size_t kFirstLinkBlock = std::size_t{1} << 18;

class LinkRefiner {
  public:
    // `memory_budget`: refinement splits no further once hierarchical_memory_estimate of the elements and
    // the links it holds (made, or still to weigh) would exceed it (0: no budget).
    LinkRefiner(HierarchicalSystem& system, const LinkEstimator& estimator,
                const HierarchicalOptions& options, double min_edge, std::size_t memory_budget,
                HierarchicalReport& report, Progress* progress);

    // Estimates the candidates and refines them (and the candidates they spawn) into links.
    void refine(std::vector<LinkCandidate> candidates);
    // refine() of the first links, every pair of base patches that may face each other (from
    // count_first_links), listed and estimated a block of receivers at a time so that the n² pairs and their
    // estimates never exist at once; the links and elements come out as refine() of the whole list would
    // make them. `block_pairs`: the candidates of a block (at least one receiver's).
    void refine_first(const PatchMesh& base, const FirstLinks& first,
                      std::size_t block_pairs = kFirstLinkBlock);
    // Weighs every link again with the radiosity as it now stands and refines those that fall short;
    // returns whether any did.
    bool refine_again();

    void set_epsilon(double epsilon) { epsilon_ = epsilon; }
    // B per element: what the oracle weighs links by. Children start with their parent's value.
    std::vector<glm::dvec3>& radiosity() { return radiosity_; }

  private:
    enum class Decision { accept, split_receiver, split_source, source_children };

    // `held`: the links held besides this one (made, or still to weigh), for the memory budget.
    Decision decide(const HierarchicalLink& link, std::uint64_t held) const;
    // Whether `elements` elements and `links` links fit the memory budget.
    bool fits(std::size_t elements, std::uint64_t links) const;
    // The error in the receiver's radiosity the link's uncertainty allows, at the source's radiosity.
    double kernel_error(const HierarchicalLink& link) const;
    // Would the oracle split an element for this link, were there room?
    bool wants_split(const HierarchicalLink& link) const;
    bool splittable(std::uint32_t element) const;
    std::uint32_t split(std::uint32_t element);
    void follow(const HierarchicalLink& link, Decision decision, std::vector<LinkCandidate>& next);
    // Measures the exposed_share of elements split since the last pass.
    void measure_exposed_share();

  public:
    // Per element, its form factor to the whole scene times its exposed_share, measured for every leaf
    // (negative: not measured).
    const std::vector<float>& measure_reaching();

  private:
    std::vector<float> reaching_;
    std::vector<LinkEstimate> estimate(std::span<const LinkCandidate> candidates, int draw);
    // Decides on each estimated candidate, in order: into `next` what it spawns, into `finished` what it
    // stopped at. `pending`: candidates of this wave after these, still to weigh.
    void weigh(std::span<const LinkCandidate> candidates, std::span<const LinkEstimate> estimates,
               std::uint64_t pending, std::vector<LinkCandidate>& next, std::vector<LinkCandidate>& finished);
    // Links for the candidates refinement stopped at, from a fresh draw of shadow rays.
    void add_final_links(const std::vector<LinkCandidate>& finished);

    HierarchicalSystem& system_;
    const LinkEstimator& estimator_;
    const HierarchicalOptions& options_;
    double min_edge_;
    std::size_t memory_budget_;
    double epsilon_ = 0.0;
    HierarchicalReport& report_;
    Progress* progress_;
    std::vector<glm::dvec3> radiosity_;
};

}  // namespace rad
