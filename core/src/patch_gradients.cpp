#include "patch_gradients.hpp"

#include <algorithm>
#include <glm/geometric.hpp>

namespace rad {

namespace {

// The patches sharing a corner with q that a smooth surface joins to it, q excluded.
std::vector<std::uint32_t> neighbours(const PatchMesh& mesh,
                                      const std::vector<std::vector<std::uint32_t>>& at, std::uint32_t q,
                                      double cos_crease) {
    std::vector<std::uint32_t> found;
    const Patch& patch = mesh.patches[q];
    for (int k = 0; k < mesh.corner_count(q); ++k) {
        for (std::uint32_t r : at[mesh.corners[q][k]]) {
            const Patch& other = mesh.patches[r];
            if (r != q && other.surface == patch.surface &&
                glm::dot(other.normal, patch.normal) >= cos_crease)
                found.push_back(r);
        }
    }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
}

PatchGradient gradient(const PatchMesh& mesh, std::uint32_t q, std::vector<std::uint32_t> near) {
    const Patch& patch = mesh.patches[q];
    // Offsets of the neighbours' centroids, projected onto the patch's plane.
    std::vector<glm::dvec3> offset;
    double m00 = 0, m01 = 0, m11 = 0;
    const glm::dvec3 edge = mesh.points[mesh.corners[q][1]] - mesh.points[mesh.corners[q][0]];
    const glm::dvec3 u = glm::normalize(edge - glm::dot(edge, patch.normal) * patch.normal);
    const glm::dvec3 v = glm::cross(patch.normal, u);
    for (std::uint32_t r : near) {
        const glm::dvec3 d = mesh.patches[r].centroid - patch.centroid;
        const double du = glm::dot(d, u), dv = glm::dot(d, v);
        offset.emplace_back(du, dv, 0.0);
        m00 += du * du, m01 += du * dv, m11 += dv * dv;
    }
    const double det = m00 * m11 - m01 * m01;
    PatchGradient g;
    if (near.size() < 2 || !(det > 1e-9 * (m00 + m11) * (m00 + m11))) return g;
    for (std::size_t k = 0; k < near.size(); ++k) {
        // M⁻¹ d, back in world coordinates.
        const double cu = (m11 * offset[k].x - m01 * offset[k].y) / det;
        const double cv = (m00 * offset[k].y - m01 * offset[k].x) / det;
        g.neighbour.push_back(near[k]);
        g.coefficient.push_back(cu * u + cv * v);
    }
    return g;
}

}  // namespace

std::vector<PatchGradient> patch_gradients(const PatchMesh& mesh, double cos_crease) {
    std::vector<std::vector<std::uint32_t>> at(mesh.points.size());
    for (std::uint32_t q = 0; q < mesh.size(); ++q) {
        for (int k = 0; k < mesh.corner_count(q); ++k) at[mesh.corners[q][k]].push_back(q);
    }
    std::vector<PatchGradient> gradients(mesh.size());
    for (std::uint32_t q = 0; q < mesh.size(); ++q) {
        gradients[q] = gradient(mesh, q, neighbours(mesh, at, q, cos_crease));
    }
    return gradients;
}

}  // namespace rad
