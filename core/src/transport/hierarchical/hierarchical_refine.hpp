#pragma once

// Link refinement for hierarchical radiosity: the oracle that decides whether a link is good enough, and the
// passes that estimate candidate links and split elements until every link is. Private to the library.

#include <cstdint>
#include <vector>

#include "rad/transport/hierarchical/hierarchical_radiosity.hpp"
#include "transport/hierarchical/hierarchical_links.hpp"

namespace rad {

struct LinkCandidate {
    std::uint32_t receiver;
    std::uint32_t source;
};

class LinkRefiner {
  public:
    // `epsilon`: the error in radiosity (luminance) a link may carry into its receiver.
    LinkRefiner(HierarchicalSystem& system, const LinkEstimator& estimator,
                const HierarchicalOptions& options, double min_edge, HierarchicalReport& report,
                Progress* progress);

    // Estimates the candidates and refines them (and the candidates they spawn) into links.
    void refine(std::vector<LinkCandidate> candidates);
    // Weighs every link again with the radiosity as it now stands and refines those that fall short;
    // returns whether any did.
    bool refine_again();

    void set_epsilon(double epsilon) { epsilon_ = epsilon; }
    // B per element: what the oracle weighs links by. Children start with their parent's value.
    std::vector<glm::dvec3>& radiosity() { return radiosity_; }

  private:
    enum class Decision { accept, split_receiver, split_source, source_children };

    Decision decide(const HierarchicalLink& link) const;
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
    std::vector<LinkEstimate> estimate(const std::vector<LinkCandidate>& candidates, int draw);
    // Links for the candidates refinement stopped at, from a fresh draw of shadow rays.
    void add_final_links(const std::vector<LinkCandidate>& finished);

    HierarchicalSystem& system_;
    const LinkEstimator& estimator_;
    const HierarchicalOptions& options_;
    double min_edge_;
    double epsilon_ = 0.0;
    HierarchicalReport& report_;
    Progress* progress_;
    std::vector<glm::dvec3> radiosity_;
};

}  // namespace rad
