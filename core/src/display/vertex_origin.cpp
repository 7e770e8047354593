#include "display/vertex_origin.hpp"

#include <glm/geometric.hpp>

namespace rad {

namespace {

// How far a vertex moves towards its patches' centroid, as a share of the way.
constexpr double kTowardsCentroid = 1e-3;

}  // namespace

glm::dvec3 vertex_origin(const DisplayMesh& display, const PatchMesh& patches, std::size_t v) {
    const glm::dvec3 position(display.positions[v]);
    glm::dvec3 centre(0.0);
    double total = 0.0;
    for (std::uint32_t k = display.weight_begin[v]; k < display.weight_begin[v + 1]; ++k) {
        if (!(display.weight[k] > 0.0f)) continue;
        centre += static_cast<double>(display.weight[k]) * patches.patches[display.weight_patch[k]].centroid;
        total += display.weight[k];
    }
    if (!(total > 0.0)) return position;
    // Along the surface only: on a curved surface the centroid lies beneath it (inside a ball), and a
    // vertex moved there would see the surface's back.
    const glm::dvec3 n(display.normals[v]);
    const double length = glm::length(n);
    glm::dvec3 towards = centre / total - position;
    if (length > 0.0) towards -= glm::dot(towards, n / length) * (n / length);
    return position + kTowardsCentroid * towards;
}

}  // namespace rad
