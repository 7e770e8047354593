#pragma once

// The three stages of a gather through the cluster hierarchy (pull, links, push), and their transpose,
// which follows each leaf's radiosity to where it arrives. Private to the library.

#include <array>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "rad/transport/clustered/clustered_transport.hpp"

namespace rad {

// Per element and per cluster, the mean radiosity over its area, from the leaves' (children come after
// their parents in both trees).
struct NodeValues {
    std::vector<glm::dvec3> element;
    std::vector<glm::dvec3> cluster;
};

// What a cluster receives, by the direction it comes from: per axis direction (+x, −x, +y, −y, +z, −z),
// the irradiance a surface facing that way takes (ClusterLink); and, for isotropic clusters, in the seventh
// slot, the irradiance at a surface facing each source, summed.
inline constexpr int kIsotropicSlot = 6;
using DirectionalIrradiance = std::array<glm::dvec3, 7>;

struct Irradiance {
    std::vector<glm::dvec3> element;
    std::vector<DirectionalIrradiance> cluster;
};

// Leaf values (in h.leaves order) averaged up both trees.
void pull(const ClusterHierarchy& h, std::span<const glm::dvec3> leaf_values, NodeValues& b);

// Irradiance gathered along the links into each receiver, then pushed down: a cluster's to its children
// (each surface taking it by its orientation), an element's to its quarters. Leaves' values are final.
void gather_push(const ClusterHierarchy& h, const NodeValues& b, Irradiance& irradiance);

// What a gather through the hierarchy works in, kept between calls to save allocations.
struct FlowBuffers {
    std::vector<glm::dvec3> sent;
    NodeValues values;
    Irradiance irradiance;
};

// The leaves' gather, irradiance[k] = Σ_j T_kj radiosity[j] over pull, links and push; `scaled`, with each
// leaf's send and receive scales (balance_leaves) applied, as ClusteredTransport gathers.
void gather_leaves(const ClusterHierarchy& h, std::span<const glm::dvec3> radiosity,
                   std::span<glm::dvec3> irradiance, bool scaled, FlowBuffers& buffers);

// The transpose of pull, links and push: for weights w per leaf (h.leaves order), out[k] = Σ_r w_r T_rk,
// where T is the leaves' gather (irradiance at leaf r per unit radiosity of leaf k). With w = A the area,
// out[k] / A_k is the share of leaf k's light that arrives somewhere.
void spread(const ClusterHierarchy& h, std::span<const double> weights, std::span<double> out);

}  // namespace rad
