#include "transport/hierarchical/hierarchical_refine.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <string>

#include "rad/util/stopwatch.hpp"
#include "transport/hierarchical/hierarchical_first_links.hpp"
#include "util/luminance.hpp"

namespace rad {

namespace {

// The first links' time is told when it would be longer than this.
constexpr double kLongSeconds = 600.0;

}  // namespace

LinkRefiner::LinkRefiner(HierarchicalSystem& system, const LinkEstimator& estimator,
                         const HierarchicalOptions& options, double min_edge, std::size_t memory_budget,
                         HierarchicalReport& report, Progress* progress)
    : system_(system),
      estimator_(estimator),
      options_(options),
      min_edge_(min_edge),
      memory_budget_(memory_budget),
      report_(report),
      progress_(progress),
      radiosity_(system.emission) {
    for (std::size_t e = 0; e < radiosity_.size(); ++e)
        radiosity_[e] *= std::max(0.0f, system.exposed_share[e]);
}

bool LinkRefiner::splittable(std::uint32_t e) const {
    return system_.tree.longest_edge(e) > min_edge_;
}

std::uint32_t LinkRefiner::split(std::uint32_t e) {
    const bool was_leaf = system_.tree[e].is_leaf();
    const std::uint32_t first = system_.tree.split(e);
    if (was_leaf) {
        for (int k = 0; k < 4; ++k) {
            system_.reflectance.push_back(system_.reflectance[e]);
            system_.emission.push_back(system_.emission[e]);
            // Wholly exposed or wholly covered parents have children alike; the others are measured.
            const float exposed_share = system_.exposed_share[e];
            system_.exposed_share.push_back(exposed_share >= 1.0f || exposed_share <= 0.0f ? exposed_share
                                                                                           : -1.0f);
            radiosity_.push_back(radiosity_[e]);
        }
    }
    return first;
}

double LinkRefiner::kernel_error(const HierarchicalLink& link) const {
    return luminance(system_.reflectance[link.receiver] * radiosity_[link.source]) * link.uncertainty;
}

bool LinkRefiner::wants_split(const HierarchicalLink& link) const {
    return kernel_error(link) > epsilon_ && (splittable(link.receiver) || splittable(link.source));
}

bool LinkRefiner::fits(std::size_t elements, std::uint64_t links) const {
    return memory_budget_ == 0 || hierarchical_memory_estimate(elements, links) <= memory_budget_;
}

LinkRefiner::Decision LinkRefiner::decide(const HierarchicalLink& link, std::uint64_t held) const {
    // Anything but accepting makes four candidates of this link, and a split four elements too.
    const std::size_t elements = system_.tree.size();
    if (!fits(elements, held + 4)) return Decision::accept;
    const glm::dvec3& rho = system_.reflectance[link.receiver];
    const bool room = elements + 4 <= options_.max_elements && fits(elements + 4, held + 4);
    if (room && kernel_error(link) > epsilon_) {
        const bool receiver = splittable(link.receiver), source = splittable(link.source);
        const double receiver_area = system_.tree[link.receiver].shape.area;
        if (receiver && (!source || receiver_area >= system_.tree[link.source].shape.area))
            return Decision::split_receiver;
        if (source) return Decision::split_source;
    }
    const Element& source = system_.tree[link.source];
    if (!source.is_leaf()) {
        // Gathering the mean of a source whose parts differ spreads their difference over the receiver.
        double lo = 1e300, hi = 0.0;
        for (std::uint32_t c = source.first_child; c < source.first_child + 4; ++c) {
            const double b = luminance(rho * radiosity_[c]);
            lo = std::min(lo, b);
            hi = std::max(hi, b);
        }
        if (static_cast<double>(link.mean_factor()) * (hi - lo) > epsilon_) return Decision::source_children;
    }
    return Decision::accept;
}

void LinkRefiner::follow(const HierarchicalLink& link, Decision decision, std::vector<LinkCandidate>& next) {
    switch (decision) {
        case Decision::accept:
            system_.links.push_back(link);
            return;
        case Decision::split_receiver: {
            const std::uint32_t first = split(link.receiver);
            for (std::uint32_t c = first; c < first + 4; ++c) next.push_back({c, link.source});
            return;
        }
        case Decision::split_source: {
            const std::uint32_t first = split(link.source);
            for (std::uint32_t c = first; c < first + 4; ++c) next.push_back({link.receiver, c});
            return;
        }
        case Decision::source_children: {
            const std::uint32_t first = system_.tree[link.source].first_child;
            for (std::uint32_t c = first; c < first + 4; ++c) next.push_back({link.receiver, c});
            return;
        }
    }
}

std::vector<LinkEstimate> LinkRefiner::estimate(std::span<const LinkCandidate> candidates, int draw) {
    report_.rays += candidates.size() * static_cast<std::uint64_t>(options_.visibility_rays);
    std::vector<LinkEstimate> estimates(candidates.size());
    tbb::enumerable_thread_specific<LinkEstimator::Scratch> scratch;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), 64),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          if (progress_ && progress_->cancelled()) return;
                          LinkEstimator::Scratch& s = scratch.local();
                          for (std::size_t k = range.begin(); k < range.end(); ++k)
                              estimates[k] =
                                  estimator_(candidates[k].receiver, candidates[k].source, s, draw);
                          if (progress_) progress_->advance(range.size());
                      });
    if (progress_ && progress_->cancelled()) throw Cancelled{};
    return estimates;
}

void LinkRefiner::measure_exposed_share() {
    std::vector<float>& exposed_share = system_.exposed_share;
    tbb::parallel_for(std::size_t(0), exposed_share.size(), [&](std::size_t e) {
        if (exposed_share[e] < 0.0f)
            exposed_share[e] = static_cast<float>(estimator_.exposed_share(static_cast<std::uint32_t>(e)));
    });
}

const std::vector<float>& LinkRefiner::measure_reaching() {
    reaching_.resize(system_.tree.size(), -1.0f);
    system_.escaping_share.resize(system_.tree.size(), -1.0f);
    tbb::parallel_for(std::size_t(0), reaching_.size(), [&](std::size_t e) {
        const auto element = static_cast<std::uint32_t>(e);
        if (reaching_[e] < 0.0f && system_.tree[element].is_leaf()) {
            double escaping = -1.0;
            reaching_[e] = static_cast<float>(estimator_.reaching_share(element, &escaping));
            system_.escaping_share[e] = static_cast<float>(escaping);
        }
    });
    return reaching_;
}

void LinkRefiner::weigh(std::span<const LinkCandidate> candidates, std::span<const LinkEstimate> estimates,
                        std::uint64_t pending, std::vector<LinkCandidate>& next,
                        std::vector<LinkCandidate>& finished) {
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        if (!estimates[k].facing) continue;
        if (!estimates[k].transports) {
            finished.push_back(candidates[k]);  // no ray arrived; a fresh draw may see what they missed
            continue;
        }
        HierarchicalLink link;
        link.receiver = candidates[k].receiver;
        link.source = candidates[k].source;
        std::copy(std::begin(estimates[k].factor), std::end(estimates[k].factor), link.factor);
        link.uncertainty = estimates[k].uncertainty;
        const std::size_t made = system_.links.size() + next.size() + finished.size();
        const bool full = made >= options_.max_links;
        const Decision decision =
            full ? Decision::accept : decide(link, made + pending + (candidates.size() - k - 1));
        if (decision == Decision::accept && wants_split(link)) report_.limited = true;
        if (decision == Decision::accept)
            finished.push_back(candidates[k]);
        else
            follow(link, decision, next);
    }
}

void LinkRefiner::refine(std::vector<LinkCandidate> candidates) {
    while (!candidates.empty()) {
        measure_exposed_share();
        std::vector<LinkCandidate> next, finished;
        weigh(candidates, estimate(candidates, 0), 0, next, finished);
        add_final_links(finished);
        candidates.swap(next);
    }
}

void LinkRefiner::refine_first(const PatchMesh& base, const FirstLinks& first, std::size_t block_pairs) {
    const std::span<const std::uint32_t> counts = first.count;
    const std::uint64_t total = first.total;
    measure_exposed_share();
    std::vector<LinkCandidate> block, next, finished;
    finished.reserve(total);  // at most one each, and counted so by first_links_memory_estimate
    std::uint64_t weighed = 0;
    const Stopwatch clock;
    const auto n = static_cast<std::uint32_t>(counts.size());
    for (std::uint32_t begin = 0; begin < n;) {
        std::uint32_t end = begin;
        std::uint64_t pairs = 0;
        while (end < n && (end == begin || pairs + counts[end] <= block_pairs)) pairs += counts[end++];
        list_first_links(base, first, begin, end, block);
        weighed += block.size();
        weigh(block, estimate(block, 0), total - weighed, next, finished);
        // A long first pass is told, not left to look like a hang: at the rate of its first block, twice
        // over for the fresh draw of the links kept.
        if (begin == 0 && progress_ && weighed < total) {
            const double projected =
                2.0 * clock.seconds() * static_cast<double>(total) / static_cast<double>(weighed);
            if (projected > kLongSeconds)
                progress_->note("the " + std::to_string(total) + " first links will take about " +
                                format_duration(projected) + " at the rate of the first " +
                                std::to_string(weighed));
        }
        begin = end;
    }
    block = {};
    // What follows (the fresh draw, the links spawned) has no total known in advance.
    if (progress_) progress_->begin("linking elements, round 1", 0);
    // Room for the first links and no more (first_links_memory_estimate): growing by doubling would
    // briefly hold them three times over.
    system_.links.reserve(system_.links.size() + finished.size());
    add_final_links(finished);
    std::vector<LinkCandidate>().swap(finished);  // not held through the refinement that follows
    refine(std::move(next));
}

void LinkRefiner::add_final_links(const std::vector<LinkCandidate>& finished) {
    // A block at a time, so that the estimates of the many first links never exist at once.
    for (std::size_t begin = 0; begin < finished.size(); begin += kFirstLinkBlock) {
        const std::span<const LinkCandidate> block =
            std::span(finished).subspan(begin, std::min(kFirstLinkBlock, finished.size() - begin));
        const std::vector<LinkEstimate> estimates = estimate(block, 1);
        for (std::size_t k = 0; k < block.size(); ++k) {
            if (!estimates[k].transports) continue;
            HierarchicalLink link;
            link.receiver = block[k].receiver;
            link.source = block[k].source;
            std::copy(std::begin(estimates[k].factor), std::end(estimates[k].factor), link.factor);
            link.uncertainty = estimates[k].uncertainty;
            system_.links.push_back(link);
        }
    }
}

bool LinkRefiner::refine_again() {
    std::vector<HierarchicalLink> links;
    links.swap(system_.links);
    std::vector<LinkCandidate> candidates;
    for (const HierarchicalLink& link : links) {
        // The old links are all held until the pass ends, besides the new ones.
        const Decision decision = decide(link, links.size() + system_.links.size() + candidates.size());
        if (decision == Decision::accept && wants_split(link)) report_.limited = true;
        follow(link, decision, candidates);
    }
    std::vector<HierarchicalLink>().swap(links);  // freed before the candidates are estimated
    const bool changed = !candidates.empty();
    refine(std::move(candidates));
    return changed;
}

}  // namespace rad
