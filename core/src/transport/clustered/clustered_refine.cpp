#include "transport/clustered/clustered_refine.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <span>
#include <vector>

#include "ray/coverage.hpp"
#include "transport/clustered/cluster_geometry.hpp"
#include "util/luminance.hpp"

namespace rad {

namespace {

// Rays from a cluster end's base patches that test whether the link is seen in part, at most.
constexpr std::uint32_t kMaxPatchRays = 64;

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
        refine(stack, progress);
        // A link with a cluster at either end that its shadow rays find partly blocked is split: its light
        // would reach every surface of the cluster facing the right way, the hidden ones too (the inside of
        // a wall slab whose outside is lit), and carry the mean of all of a source's surfaces, the hidden
        // ones too. Its parts are linked and tested in turn, until each link is seen whole, hidden whole,
        // or joins two elements.
        while (!pending_.empty()) {
            std::vector<std::pair<std::uint32_t, std::uint32_t>> partly = evaluate_links(progress);
            if (partly.empty()) break;
            for (const auto& [r, s] : partly) split_link(r, s, stack);
            refine(stack, progress);
        }
    }

  private:
    void refine(std::vector<std::pair<std::uint32_t, std::uint32_t>>& stack, Progress* progress) {
        std::size_t visited = 0;
        while (!stack.empty()) {
            const auto [r, s] = stack.back();
            stack.pop_back();
            if ((++visited & 0xfff) == 0 && progress && progress->cancelled()) throw Cancelled{};
            consider(r, s, stack);
        }
    }

    // Replaces the link by links from its larger cluster's children.
    void split_link(std::uint32_t r, std::uint32_t s,
                    std::vector<std::pair<std::uint32_t, std::uint32_t>>& stack) {
        const bool receiver =
            ClusterNode::is_cluster(r) &&
            (!ClusterNode::is_cluster(s) || node_shape(h_, r).radius >= node_shape(h_, s).radius);
        children(receiver ? r : s, scratch_);
        for (std::uint32_t c : scratch_) stack.emplace_back(receiver ? c : r, receiver ? s : c);
    }

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
        const bool memory = within_memory();
        const bool budget = pending_.size() + h_.links.size() < options_.max_links && memory;
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

    bool within_memory() const {
        return report_.memory_budget == 0 || (pending_.size() + h_.links.size()) * kClusteredLinkBytes +
                                                     h_.tree.size() * kClusteredElementBytes <
                                                 report_.memory_budget;
    }
    bool within_budget() const {
        return pending_.size() + h_.links.size() < options_.max_links && within_memory();
    }

    // The links' factors and visibility, on all cores: the tree does not change meanwhile. Keeps the links
    // found whole and returns those with a cluster at either end that their rays find partly blocked.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> evaluate_links(Progress* progress) {
        std::vector<ClusterLink> links(pending_.size());
        std::vector<std::uint8_t> partly(pending_.size(), 0);
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
                                  links[k] = evaluate(pending_[k].first, pending_[k].second, buffer, blocked,
                                                      partly[k]);
                                  traced += buffer.size();
                              }
                              rays += traced;
                              if (progress) progress->advance(range.size());
                          });
        report_.rays += rays.load();
        std::vector<std::pair<std::uint32_t, std::uint32_t>> split;
        for (std::size_t k = 0; k < links.size(); ++k) {
            const ClusterLink& link = links[k];
            if (partly[k] && within_budget()) {
                split.push_back(pending_[k]);
                continue;
            }
            if (!(link.factor > 0.0f)) continue;
            h_.links.push_back(link);
            if (ClusterNode::is_cluster(link.receiver) || ClusterNode::is_cluster(link.source))
                ++report_.cluster_links;
        }
        pending_.clear();
        return split;
    }

    ClusterLink evaluate(std::uint32_t r, std::uint32_t s, std::vector<Ray>& buffer,
                         std::vector<std::uint8_t>& blocked, std::uint8_t& partly) const {
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
        partly = cluster && seen_in_part(r, s, towards, open, buffer, blocked);
        link.factor = static_cast<float>(factor * kernel * open);
        return link;
    }

    // Whether a surface of normal n faces along d: strictly, as two coplanar surfaces (a floor slab's side
    // and the wall slab's outside above it) exchange no light, whatever the rounding of their points.
    static bool faces(const glm::dvec3& n, const glm::dvec3& d) {
        return glm::dot(n, d) > 1e-9 * glm::length(d);
    }

    // Whether a link with a cluster at an end is seen in part: its shadow rays, and a ray from each base
    // patch of a cluster end that faces the other end (up to kMaxPatchRays, else as many drawn by area) to a
    // point of the other end, are neither all open nor all blocked. Four rays between random points would
    // often miss the inside of a wall slab whose outside they meet.
    bool seen_in_part(std::uint32_t r, std::uint32_t s, const glm::dvec3& towards, double open,
                      std::vector<Ray>& buffer, std::vector<std::uint8_t>& blocked) const {
        if (open > 0.0 && open < 1.0) return true;
        const std::size_t first = buffer.size();
        RandomStream random(options_.seed ^ 0x9e3779b97f4a7c15ull, r, s);
        // Whether a patch the link counts as facing the other end faces away from the point drawn there.
        bool away = false;
        add_patch_rays(r, s, towards, random, buffer, away);
        add_patch_rays(s, r, -towards, random, buffer, away);
        if (away && open > 0.0) return true;
        if (buffer.size() == first) return false;
        blocked.resize(buffer.size());
        const std::span<const Ray> added = std::span<const Ray>(buffer).subspan(first);
        rays_.occluded(added, std::span<std::uint8_t>(blocked).subspan(first));
        const bool seen = open > 0.0;
        for (std::size_t k = first; k < buffer.size(); ++k)
            if ((blocked[k] == 0) != seen) return true;
        return false;
    }

    void add_patch_rays(std::uint32_t node, std::uint32_t other, const glm::dvec3& towards,
                        RandomStream& random, std::vector<Ray>& out, bool& away) const {
        if (!ClusterNode::is_cluster(node)) return;
        const ClusterHierarchy::Cluster& c = h_.clusters[ClusterNode::index(node)];
        const auto ray_from = [&](std::uint32_t patch) {
            const ConvexPolygon polygon = element_polygon(h_.tree, patch);
            glm::dvec3 from =
                point_on_convex_polygon(polygon.span(), glm::dvec2(random.uniform(), random.uniform()));
            glm::dvec3 to, to_normal;
            sample_node(h_, area_prefix_, other, -towards, random, to, to_normal);
            const glm::dvec3& n = h_.tree[patch].shape.normal;
            if (!faces(n, to - from)) {  // hidden from that point, as if blocked
                away = true;
                return;
            }
            from += offset_ * n;
            to += offset_ * (glm::dot(to_normal, from - to) >= 0.0 ? to_normal : -to_normal);
            out.push_back(Ray{from, 0.0f, to - from, 1.0f});
        };
        if (c.patch_end - c.patch_begin <= kMaxPatchRays) {
            for (std::uint32_t k = c.patch_begin; k < c.patch_end; ++k)
                if (glm::dot(h_.tree[h_.patch_order[k]].shape.normal, towards) > 0.0)
                    ray_from(h_.patch_order[k]);
            return;
        }
        for (std::uint32_t k = 0; k < kMaxPatchRays; ++k) ray_from(facing_patch(c, towards, random));
    }

    // A base patch of the cluster by its area, one facing `towards` if 8 tries find one.
    std::uint32_t facing_patch(const ClusterHierarchy::Cluster& c, const glm::dvec3& towards,
                               RandomStream& random) const {
        std::uint32_t patch = h_.patch_order[c.patch_begin];
        const double low = area_prefix_[c.patch_begin], high = area_prefix_[c.patch_end];
        for (int attempt = 0; attempt < 8; ++attempt) {
            const auto it =
                std::upper_bound(area_prefix_.begin() + c.patch_begin + 1, area_prefix_.begin() + c.patch_end,
                                 low + random.uniform() * (high - low));
            const auto slot = static_cast<std::size_t>(it - area_prefix_.begin()) - 1;
            patch = h_.patch_order[std::min<std::size_t>(slot, c.patch_end - 1)];
            if (glm::dot(h_.tree[patch].shape.normal, towards) > 0.0) break;
        }
        return patch;
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
        // Rays from a cluster's surface that faces away from the other end's point, and per ray the sides
        // its two ends leave their surfaces on.
        std::vector<std::size_t> away;
        std::vector<glm::dvec3> lifts;
        for (int k = 0; k < n; ++k) {
            glm::dvec3 from, from_normal, to, to_normal;
            sample_node(h_, area_prefix_, r, towards, random, from, from_normal);
            sample_node(h_, area_prefix_, s, -towards, random, to, to_normal);
            const bool from_faces = faces(from_normal, to - from);
            const bool to_faces = faces(to_normal, from - to);
            if ((ClusterNode::is_cluster(r) && !from_faces) || (ClusterNode::is_cluster(s) && !to_faces))
                away.push_back(buffer.size());
            // Each end leaves its surface on the side that faces the other.
            // An end lifted behind its surface is not tested for cover (open_share).
            lifts.push_back(from_faces ? from_normal : glm::dvec3(0.0));
            lifts.push_back(to_faces ? to_normal : glm::dvec3(0.0));
            from += offset_ * (from_faces ? from_normal : -from_normal);
            to += offset_ * (to_faces ? to_normal : -to_normal);
            buffer.push_back(Ray{from, 0.0f, to - from, 1.0f});
        }
        blocked.resize(buffer.size());
        rays_.occluded(buffer, blocked);
        // Such a surface sends nothing to that point: behind it the ray would start inside a solid whose
        // inner faces were cut away and cross it unblocked.
        for (std::size_t k : away) {
            blocked[k] = 1;
            lifts[2 * k] = lifts[2 * k + 1] = glm::dvec3(0.0);
        }
        return open_share(buffer, blocked, lifts);
    }

    // The share of open rays, leaving out blocked rays with an end covered by another object (a floor under
    // a block standing on it): a link is for the exposed parts, as the balance counts the covered part apart
    // (ClusterHierarchy::exposed). `lifts` holds the two ends' normals per ray, zero for an end not to test.
    double open_share(std::span<const Ray> rays, std::span<const std::uint8_t> blocked,
                      std::span<const glm::dvec3> lifts) const {
        std::size_t open = 0, counted = 0;
        std::vector<std::uint8_t> covered;
        for (std::size_t k = 0; k < rays.size(); ++k) {
            if (!blocked[k]) {
                ++open;
                ++counted;
                continue;
            }
            const glm::dvec3 ends[2] = {rays[k].origin, rays[k].origin + rays[k].direction};
            bool hidden = false;
            for (int e = 0; e < 2 && !hidden; ++e) {
                if (lifts[2 * k + e] == glm::dvec3(0.0)) continue;
                covered_points(std::span<const glm::dvec3>(&ends[e], 1), lifts[2 * k + e], rays_, covered);
                hidden = covered[0] != 0;
            }
            if (!hidden) ++counted;
        }
        return counted > 0 ? static_cast<double>(open) / static_cast<double>(counted) : 0.0;
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
