#include "transport/clustered/cluster_flow.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace rad {

namespace {

int slot(int axis, float component) {
    return 2 * axis + (component >= 0.0f ? 0 : 1);
}

void add_directional(DirectionalIrradiance& into, const glm::vec3& direction, const glm::dvec3& value) {
    for (int a = 0; a < 3; ++a)
        into[slot(a, direction[a])] += std::abs(static_cast<double>(direction[a])) * value;
}

// The mean of max(0, cos) over all directions: what a surface of random orientation takes.
constexpr double kIsotropicShare = 0.25;

// What a surface of normal n inside the cluster takes of it.
glm::dvec3 taken_by(const DirectionalIrradiance& h, const glm::dvec3& n) {
    glm::dvec3 sum = kIsotropicShare * h[kIsotropicSlot];
    for (int a = 0; a < 3; ++a) sum += std::max(0.0, n[a]) * h[2 * a] + std::max(0.0, -n[a]) * h[2 * a + 1];
    return sum;
}

const glm::dvec3& value_of(const NodeValues& v, std::uint32_t node) {
    return ClusterNode::is_cluster(node) ? v.cluster[ClusterNode::index(node)]
                                         : v.element[ClusterNode::index(node)];
}

// The area the pull divides an inner element's children by.
double children_area(const ElementTree& tree, const Element& element) {
    double area = 0.0;
    for (std::uint32_t c = element.first_child; c < element.first_child + 4; ++c) area += tree[c].shape.area;
    return area;
}

}  // namespace

void pull(const ClusterHierarchy& h, std::span<const glm::dvec3> leaf_values, NodeValues& b) {
    b.element.assign(h.tree.size(), glm::dvec3(0.0));
    for (std::size_t k = 0; k < h.leaves.size(); ++k) b.element[h.leaves[k]] = leaf_values[k];
    for (std::size_t e = h.tree.size(); e-- > 0;) {
        const Element& element = h.tree[e];
        if (element.is_leaf()) continue;
        glm::dvec3 sum(0.0);
        for (std::uint32_t c = element.first_child; c < element.first_child + 4; ++c)
            sum += h.tree[c].shape.area * b.element[c];
        const double area = children_area(h.tree, element);
        b.element[e] = area > 0.0 ? sum / area : glm::dvec3(0.0);
    }
    b.cluster.assign(h.clusters.size(), glm::dvec3(0.0));
    for (std::size_t c = h.clusters.size(); c-- > 0;) {
        const ClusterHierarchy::Cluster& cluster = h.clusters[c];
        glm::dvec3 sum(0.0);
        if (cluster.child_count > 0) {
            for (std::uint32_t k = 0; k < cluster.child_count; ++k)
                sum += h.clusters[cluster.first_child + k].area * b.cluster[cluster.first_child + k];
        } else {
            for (std::uint32_t k = cluster.patch_begin; k < cluster.patch_end; ++k)
                sum += h.tree[h.patch_order[k]].shape.area * b.element[h.patch_order[k]];
        }
        b.cluster[c] = cluster.area > 0.0 ? sum / cluster.area : glm::dvec3(0.0);
    }
}

void gather_push(const ClusterHierarchy& h, const NodeValues& b, Irradiance& irradiance) {
    irradiance.element.assign(h.tree.size(), glm::dvec3(0.0));
    irradiance.cluster.assign(h.clusters.size(), DirectionalIrradiance{});
    const std::size_t runs = h.receiver_runs.empty() ? 0 : h.receiver_runs.size() - 1;
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, runs, 256), [&](const tbb::blocked_range<std::size_t>& range) {
            for (std::size_t k = range.begin(); k < range.end(); ++k) {
                const std::uint32_t receiver = h.links[h.receiver_runs[k]].receiver;
                if (ClusterNode::is_cluster(receiver)) {
                    DirectionalIrradiance sum{};
                    for (std::uint32_t l = h.receiver_runs[k]; l < h.receiver_runs[k + 1]; ++l) {
                        const glm::dvec3 value =
                            static_cast<double>(h.links[l].factor) * value_of(b, h.links[l].source);
                        if (h.isotropic) {
                            sum[kIsotropicSlot] += value;
                        } else {
                            add_directional(sum, h.links[l].direction, value);
                        }
                    }
                    irradiance.cluster[ClusterNode::index(receiver)] = sum;
                } else {
                    glm::dvec3 sum(0.0);
                    for (std::uint32_t l = h.receiver_runs[k]; l < h.receiver_runs[k + 1]; ++l)
                        sum += static_cast<double>(h.links[l].factor) * value_of(b, h.links[l].source);
                    irradiance.element[receiver] = sum;
                }
            }
        });
    for (std::size_t c = 0; c < h.clusters.size(); ++c) {
        const ClusterHierarchy::Cluster& cluster = h.clusters[c];
        const DirectionalIrradiance above = irradiance.cluster[c];
        if (cluster.child_count > 0) {
            for (std::uint32_t k = 0; k < cluster.child_count; ++k)
                for (std::size_t d = 0; d < above.size(); ++d)
                    irradiance.cluster[cluster.first_child + k][d] += above[d];
        } else {
            for (std::uint32_t k = cluster.patch_begin; k < cluster.patch_end; ++k) {
                const std::uint32_t p = h.patch_order[k];
                irradiance.element[p] += taken_by(above, h.tree[p].shape.normal);
            }
        }
    }
    for (std::size_t e = 0; e < h.tree.size(); ++e) {
        const Element& element = h.tree[e];
        if (element.is_leaf()) continue;
        for (std::uint32_t c = element.first_child; c < element.first_child + 4; ++c)
            irradiance.element[c] += irradiance.element[e];
    }
}

void gather_leaves(const ClusterHierarchy& h, std::span<const glm::dvec3> radiosity,
                   std::span<glm::dvec3> irradiance, bool scaled, FlowBuffers& buffers) {
    std::span<const glm::dvec3> sent = radiosity;
    if (scaled) {
        buffers.sent.resize(radiosity.size());
        for (std::size_t k = 0; k < radiosity.size(); ++k)
            buffers.sent[k] = static_cast<double>(h.send_scale[k]) * radiosity[k];
        sent = buffers.sent;
    }
    pull(h, sent, buffers.values);
    gather_push(h, buffers.values, buffers.irradiance);
    for (std::size_t k = 0; k < h.leaves.size(); ++k) {
        const double scale = scaled ? static_cast<double>(h.receive_scale[k]) : 1.0;
        irradiance[k] = scale * buffers.irradiance.element[h.leaves[k]];
    }
}

void spread(const ClusterHierarchy& h, std::span<const double> weights, std::span<double> out) {
    // Push, transposed: each node collects the weights of the leaves below it; a cluster by direction, as
    // its surfaces take light by their normals.
    std::vector<double> received(h.tree.size(), 0.0);
    for (std::size_t k = 0; k < h.leaves.size(); ++k) received[h.leaves[k]] = weights[k];
    for (std::size_t e = h.tree.size(); e-- > 0;) {
        const Element& element = h.tree[e];
        if (element.is_leaf()) continue;
        for (std::uint32_t c = element.first_child; c < element.first_child + 4; ++c)
            received[e] += received[c];
    }
    std::vector<std::array<double, 7>> directional(h.clusters.size(), std::array<double, 7>{});
    for (std::size_t c = h.clusters.size(); c-- > 0;) {
        const ClusterHierarchy::Cluster& cluster = h.clusters[c];
        std::array<double, 7>& sum = directional[c];
        if (cluster.child_count > 0) {
            for (std::uint32_t k = 0; k < cluster.child_count; ++k)
                for (std::size_t d = 0; d < sum.size(); ++d)
                    sum[d] += directional[cluster.first_child + k][d];
            continue;
        }
        for (std::uint32_t k = cluster.patch_begin; k < cluster.patch_end; ++k) {
            const std::uint32_t p = h.patch_order[k];
            const glm::dvec3& n = h.tree[p].shape.normal;
            for (int a = 0; a < 3; ++a) {
                sum[2 * a] += std::max(0.0, n[a]) * received[p];
                sum[2 * a + 1] += std::max(0.0, -n[a]) * received[p];
            }
            sum[kIsotropicSlot] += kIsotropicShare * received[p];
        }
    }
    // The links, transposed: each source collects what its receivers take of it.
    std::vector<double> sent_element(h.tree.size(), 0.0), sent_cluster(h.clusters.size(), 0.0);
    for (const ClusterLink& link : h.links) {
        const std::uint32_t r = ClusterNode::index(link.receiver);
        double taken = 0.0;
        if (ClusterNode::is_cluster(link.receiver) && h.isotropic) {
            taken = directional[r][kIsotropicSlot];
        } else if (ClusterNode::is_cluster(link.receiver)) {
            for (int a = 0; a < 3; ++a)
                taken += std::abs(static_cast<double>(link.direction[a])) *
                         directional[r][slot(a, link.direction[a])];
        } else {
            taken = received[r];
        }
        const std::uint32_t s = ClusterNode::index(link.source);
        (ClusterNode::is_cluster(link.source) ? sent_cluster[s] : sent_element[s]) +=
            static_cast<double>(link.factor) * taken;
    }
    // Pull, transposed: a node's share goes down to its parts by their areas.
    for (std::size_t c = 0; c < h.clusters.size(); ++c) {
        const ClusterHierarchy::Cluster& cluster = h.clusters[c];
        if (!(cluster.area > 0.0)) continue;
        const double per_area = sent_cluster[c] / cluster.area;
        if (cluster.child_count > 0) {
            for (std::uint32_t k = 0; k < cluster.child_count; ++k)
                sent_cluster[cluster.first_child + k] += per_area * h.clusters[cluster.first_child + k].area;
        } else {
            for (std::uint32_t k = cluster.patch_begin; k < cluster.patch_end; ++k)
                sent_element[h.patch_order[k]] += per_area * h.tree[h.patch_order[k]].shape.area;
        }
    }
    for (std::size_t e = 0; e < h.tree.size(); ++e) {
        const Element& element = h.tree[e];
        if (element.is_leaf()) continue;
        const double area = children_area(h.tree, element);
        if (!(area > 0.0)) continue;
        for (std::uint32_t c = element.first_child; c < element.first_child + 4; ++c)
            sent_element[c] += sent_element[e] * h.tree[c].shape.area / area;
    }
    for (std::size_t k = 0; k < h.leaves.size(); ++k) out[k] = sent_element[h.leaves[k]];
}

}  // namespace rad
