#include "transport/clustered/clustered_refine.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <vector>

#include "transport/clustered/cluster_geometry.hpp"
#include "util/luminance.hpp"

namespace rad {

namespace {

double max_channel(const glm::dvec3& v) {
    return std::max({v.x, v.y, v.z});
}

class Refiner {
  public:
    Refiner(ClusterHierarchy& h, const RayScene& rays, double offset, const ClusteredOptions& options,
            ClusteredReport& report, const RadiosityEstimate* estimate)
        : h_(h), rays_(rays), offset_(offset), options_(options), report_(report), estimate_(estimate) {
        prepare_estimates();
        if (estimate_) epsilon_ = options_.tolerance * estimate_->mean;
    }

    void run(Progress* progress) {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{
            {ClusterNode::cluster(0), ClusterNode::cluster(0)}};
        std::size_t visited = 0;
        while (!stack.empty()) {
            const auto [r, s] = stack.back();
            stack.pop_back();
            if ((++visited & 0xfff) == 0 && progress && progress->cancelled()) throw Cancelled{};
            consider(r, s, stack);
        }
        evaluate_links(progress);
    }

  private:
    // Per cluster: the largest reflectance of its contents and its mean emitted luminance; and the scene's
    // mean radiosity, estimated before any solve as its mean emission over (1 − its mean reflectance): exact
    // for a closed furnace.
    void prepare_estimates() {
        area_prefix_.assign(h_.patch_order.size() + 1, 0.0);
        double area = 0.0, emitted = 0.0, reflected = 0.0;
        for (std::size_t k = 0; k < h_.patch_order.size(); ++k) {
            const std::uint32_t p = h_.patch_order[k];
            const double a = h_.tree[p].shape.area;
            area_prefix_[k + 1] = area_prefix_[k] + a;
            area += a;
            emitted += a * luminance(h_.emission[p]);
            reflected += a * luminance(h_.reflectance[p]);
        }
        const double rho = area > 0.0 ? reflected / area : 0.0;
        const double mean_emission = area > 0.0 ? emitted / area : 0.0;
        ambient_ = mean_emission * rho / std::max(1e-3, 1.0 - rho);
        epsilon_ = options_.tolerance * mean_emission / std::max(1e-3, 1.0 - rho);
        cluster_rho_.assign(h_.clusters.size(), 0.0);
        cluster_emission_.assign(h_.clusters.size(), 0.0);
        for (std::size_t c = h_.clusters.size(); c-- > 0;) {
            const ClusterHierarchy::Cluster& cluster = h_.clusters[c];
            double e = 0.0, rho_max = 0.0;
            for (std::uint32_t k = cluster.patch_begin; k < cluster.patch_end; ++k) {
                const std::uint32_t p = h_.patch_order[k];
                e += h_.tree[p].shape.area * luminance(h_.emission[p]);
                rho_max = std::max(rho_max, max_channel(h_.reflectance[p]));
            }
            cluster_rho_[c] = rho_max;
            cluster_emission_[c] = cluster.area > 0.0 ? e / cluster.area : 0.0;
        }
    }

    double reflectance_of(std::uint32_t node) const {
        const std::uint32_t i = ClusterNode::index(node);
        return ClusterNode::is_cluster(node) ? cluster_rho_[i] : max_channel(h_.reflectance[i]);
    }
    double radiosity_estimate(std::uint32_t node) const {
        std::uint32_t i = ClusterNode::index(node);
        if (estimate_) {
            if (ClusterNode::is_cluster(node)) return estimate_->cluster[i];
            while (i >= estimate_->element.size()) i = h_.tree[i].parent;
            return estimate_->element[i];
        }
        return (ClusterNode::is_cluster(node) ? cluster_emission_[i] : luminance(h_.emission[i])) + ambient_;
    }

    bool can_split(std::uint32_t node) const {
        if (ClusterNode::is_cluster(node)) return true;
        const std::uint32_t e = ClusterNode::index(node);
        return !h_.tree[e].is_leaf() || h_.tree.longest_edge(e) > 2.0 * report_.min_patch_size;
    }

    // The node's children: a cluster's child clusters, a leaf cluster's base patches, an element's quarters
    // (splitting it first).
    void children(std::uint32_t node, std::vector<std::uint32_t>& out) {
        out.clear();
        const std::uint32_t i = ClusterNode::index(node);
        if (ClusterNode::is_cluster(node)) {
            const ClusterHierarchy::Cluster& c = h_.clusters[i];
            if (c.child_count > 0) {
                for (std::uint32_t k = 0; k < c.child_count; ++k)
                    out.push_back(ClusterNode::cluster(c.first_child + k));
            } else {
                for (std::uint32_t k = c.patch_begin; k < c.patch_end; ++k) out.push_back(h_.patch_order[k]);
            }
            return;
        }
        if (h_.tree[i].is_leaf()) {
            h_.tree.split(i);
            for (int k = 0; k < 4; ++k) {
                h_.reflectance.push_back(h_.reflectance[i]);
                h_.emission.push_back(h_.emission[i]);
            }
        }
        const std::uint32_t first = h_.tree[i].first_child;
        for (std::uint32_t k = 0; k < 4; ++k) out.push_back(first + k);
    }

    // Two elements exchange light only if some corner of each lies strictly in front of the other's plane:
    // not coplanar neighbours, nor the faces of a convex object. (Their bounds, with the cosines lifted for
    // the elements' extent, would otherwise split them down to the smallest size.)
    bool faces_each_other(std::uint32_t a, std::uint32_t b) const {
        auto in_front = [&](std::uint32_t of, std::uint32_t seen) {
            const Element& e = h_.tree[ClusterNode::index(of)];
            const ConvexPolygon corners = element_polygon(h_.tree, ClusterNode::index(seen));
            const double tiny = 1e-9 * std::sqrt(e.shape.area);
            for (std::size_t k = 0; k < corners.count; ++k)
                if (glm::dot(e.shape.normal, corners.corners[k] - e.shape.centroid) > tiny) return true;
            return false;
        };
        return in_front(a, b) && in_front(b, a);
    }

    // The larger side of a link splits; a cluster counts twice its radius, as splitting it makes no new
    // elements (an element beside a cluster of smaller faces would otherwise be cut down to their size).
    static double size_for_split(const NodeShape& node) {
        return node.cluster ? 2.0 * node.radius : node.radius;
    }

    // Planar elements see nothing behind their plane.
    static bool behind(const NodeShape& element, const NodeShape& other) {
        if (element.cluster) return false;
        if (other.cluster) return cosine_to_box(element, other) <= 0.0;
        return glm::dot(element.normal, other.centre - element.centre) <= -other.radius;
    }

    void consider(std::uint32_t r, std::uint32_t s,
                  std::vector<std::pair<std::uint32_t, std::uint32_t>>& stack) {
        if (r == s) {
            if (!ClusterNode::is_cluster(r)) return;  // a planar element does not light itself
            children(r, scratch_);
            for (std::uint32_t a : scratch_)
                for (std::uint32_t b : scratch_) stack.emplace_back(a, b);
            return;
        }
        const NodeShape receiver = node_shape(h_, r), source = node_shape(h_, s);
        if (behind(receiver, source) || behind(source, receiver)) return;
        if (!receiver.cluster && !source.cluster && !faces_each_other(r, s)) return;
        const double bound = link_factor(receiver, source, true);
        if (!(bound > 0.0)) return;
        // A cluster's transfer holds only to what lies outside it.
        const double distance = glm::length(source.centre - receiver.centre);
        const bool close = (receiver.cluster || source.cluster) && distance < receiver.radius + source.radius;
        const double error = reflectance_of(r) * radiosity_estimate(s) * bound;
        const bool wanted = close || error > epsilon_;
        const bool memory = pending_.size() * kClusteredLinkBytes + h_.tree.size() * kClusteredElementBytes <
                                report_.memory_budget ||
                            report_.memory_budget == 0;
        const bool budget = pending_.size() < options_.max_links && memory;
        if (wanted && budget) {
            // Closeness splits the cluster, never the element: a face beside a cluster of the faces next
            // to it (which it cannot see, but the cluster's bound cannot tell) would otherwise split down to
            // the smallest size.
            const bool split_receiver =
                close ? receiver.cluster && (!source.cluster || receiver.radius >= source.radius)
                      : (size_for_split(receiver) >= size_for_split(source) ? can_split(r) : !can_split(s));
            if (split_receiver && can_split(r)) {
                children(r, scratch_);
                for (std::uint32_t c : scratch_) stack.emplace_back(c, s);
                return;
            }
            if (can_split(s)) {
                children(s, scratch_);
                for (std::uint32_t c : scratch_) stack.emplace_back(r, c);
                return;
            }
        }
        if (wanted && !budget) (memory ? report_.limited : report_.memory_limited) = true;
        pending_.emplace_back(r, s);
    }

    // The links' factors and visibility, on all cores: the tree no longer changes.
    void evaluate_links(Progress* progress) {
        std::vector<ClusterLink> links(pending_.size());
        std::atomic<std::uint64_t> rays{0};
        if (progress) progress->begin("shadow rays of the links", pending_.size());
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pending_.size(), 256),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                              if (progress && progress->cancelled()) throw Cancelled{};
                              std::vector<Ray> buffer;
                              std::vector<std::uint8_t> blocked;
                              std::uint64_t traced = 0;
                              for (std::size_t k = range.begin(); k < range.end(); ++k) {
                                  buffer.clear();
                                  links[k] = evaluate(pending_[k].first, pending_[k].second, buffer, blocked);
                                  traced += buffer.size();
                              }
                              rays += traced;
                              if (progress) progress->advance(range.size());
                          });
        report_.rays += rays.load();
        for (const ClusterLink& link : links) {
            if (!(link.factor > 0.0f)) continue;
            h_.links.push_back(link);
            if (ClusterNode::is_cluster(link.receiver) || ClusterNode::is_cluster(link.source))
                ++report_.cluster_links;
        }
    }

    ClusterLink evaluate(std::uint32_t r, std::uint32_t s, std::vector<Ray>& buffer,
                         std::vector<std::uint8_t>& blocked) const {
        const NodeShape receiver = node_shape(h_, r), source = node_shape(h_, s);
        const double distance = glm::length(source.centre - receiver.centre);
        const glm::dvec3 towards =
            distance > 0.0 ? (source.centre - receiver.centre) / distance : glm::dvec3(0.0);
        ClusterLink link{r, s, 0.0f, glm::vec3(towards)};
        const double factor = receiver.cluster || source.cluster
                                  ? transfer_factor(receiver, source)
                                  : element_factor(h_.tree, ClusterNode::index(r), ClusterNode::index(s));
        if (!(factor > 0.0)) return link;
        const double open = visibility(r, s, towards, buffer, blocked);
        const bool cluster = receiver.cluster || source.cluster;
        const double kernel = cluster ? kernel_ratio(buffer, distance, source.area) : 1.0;
        link.factor = static_cast<float>(factor * kernel * open);
        return link;
    }

    // A cluster's transfer takes the kernel 1 / (π d² + A_s) at the centres' distance; its mean over the
    // two nodes' points is larger (1 / d² is convex), the more so the nearer the two. The
    // shadow rays' end points give that mean: this is its ratio to the centres' value.
    static double kernel_ratio(std::span<const Ray> rays, double distance, double source_area) {
        if (rays.empty()) return 1.0;
        const double centre = std::numbers::pi * distance * distance + source_area;
        double sum = 0.0;
        for (const Ray& ray : rays)
            sum += centre / (std::numbers::pi * glm::dot(ray.direction, ray.direction) + source_area);
        return sum / static_cast<double>(rays.size());
    }

    // The share of shadow rays between random points of the two that nothing blocks (the rays are left in
    // `buffer`, which must come empty).
    double visibility(std::uint32_t r, std::uint32_t s, const glm::dvec3& towards, std::vector<Ray>& buffer,
                      std::vector<std::uint8_t>& blocked) const {
        const int n = std::max(1, options_.visibility_rays);
        RandomStream random(options_.seed, r, s);
        for (int k = 0; k < n; ++k) {
            glm::dvec3 from, from_normal, to, to_normal;
            sample_node(h_, area_prefix_, r, towards, random, from, from_normal);
            sample_node(h_, area_prefix_, s, -towards, random, to, to_normal);
            // Each end leaves its surface on the side that faces the other.
            from += offset_ * (glm::dot(from_normal, to - from) >= 0.0 ? from_normal : -from_normal);
            to += offset_ * (glm::dot(to_normal, from - to) >= 0.0 ? to_normal : -to_normal);
            buffer.push_back(Ray{from, 0.0f, to - from, 1.0f});
        }
        blocked.resize(buffer.size());
        rays_.occluded(buffer, blocked);
        const auto open = std::count(blocked.begin(), blocked.end(), std::uint8_t{0});
        return static_cast<double>(open) / static_cast<double>(buffer.size());
    }

    ClusterHierarchy& h_;
    const RayScene& rays_;
    const double offset_;
    const ClusteredOptions& options_;
    ClusteredReport& report_;
    const RadiosityEstimate* estimate_;
    std::vector<double> area_prefix_;
    std::vector<double> cluster_rho_, cluster_emission_;
    double ambient_ = 0.0, epsilon_ = 0.0;
    std::vector<std::uint32_t> scratch_;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pending_;  // links found, not yet evaluated
};

}  // namespace

void refine_cluster_links(ClusterHierarchy& h, const RayScene& rays, double ray_offset,
                          const ClusteredOptions& options, ClusteredReport& report, Progress* progress,
                          const RadiosityEstimate* estimate) {
    Refiner(h, rays, ray_offset, options, report, estimate).run(progress);
}

}  // namespace rad
