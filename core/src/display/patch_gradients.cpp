#include "display/patch_gradients.hpp"

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <span>

namespace rad {

namespace {

// The patches sharing a boundary point with q that a smooth surface joins to it, q excluded, into `found`.
void find_neighbours(const PatchMesh& mesh, const PointPatches& at, std::uint32_t q, double cos_crease,
                     std::vector<std::uint32_t>& found) {
    found.clear();
    const Patch& patch = mesh.patches[q];
    for (std::uint32_t p : patch_boundary(mesh, q)) {
        for (std::uint32_t r : at.at(p)) {
            const Patch& other = mesh.patches[r];
            if (r != q && other.surface == patch.surface &&
                glm::dot(other.normal, patch.normal) >= cos_crease)
                found.push_back(r);
        }
    }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
}

// Appends q's terms to `out` (none where `near` cannot fix a plane). `offset` is scratch space.
void add_gradient(const PatchMesh& mesh, std::uint32_t q, std::span<const std::uint32_t> near,
                  std::vector<glm::dvec2>& offset, PatchGradients& out) {
    const Patch& patch = mesh.patches[q];
    // Offsets of the neighbours' centroids, projected onto the patch's plane.
    offset.clear();
    double m00 = 0, m01 = 0, m11 = 0;
    const glm::dvec3 edge = mesh.points[mesh.corners[q][1]] - mesh.points[mesh.corners[q][0]];
    const glm::dvec3 u = glm::normalize(edge - glm::dot(edge, patch.normal) * patch.normal);
    const glm::dvec3 v = glm::cross(patch.normal, u);
    for (std::uint32_t r : near) {
        const glm::dvec3 d = mesh.patches[r].centroid - patch.centroid;
        const double du = glm::dot(d, u), dv = glm::dot(d, v);
        offset.emplace_back(du, dv);
        m00 += du * du, m01 += du * dv, m11 += dv * dv;
    }
    const double det = m00 * m11 - m01 * m01;
    if (near.size() < 2 || !(det > 1e-9 * (m00 + m11) * (m00 + m11))) return;
    for (std::size_t k = 0; k < near.size(); ++k) {
        // M⁻¹ d, back in world coordinates.
        const double cu = (m11 * offset[k].x - m01 * offset[k].y) / det;
        const double cv = (m00 * offset[k].y - m01 * offset[k].x) / det;
        out.neighbour.push_back(near[k]);
        out.coefficient.push_back(cu * u + cv * v);
    }
}

}  // namespace

PatchGradients patch_gradients(const PatchMesh& mesh, const PointPatches& at, double cos_crease) {
    PatchGradients gradients;
    gradients.begin.reserve(mesh.size() + 1);
    gradients.begin.push_back(0);
    // Scratch space reused for every patch.
    std::vector<std::uint32_t> near;
    std::vector<glm::dvec2> offset;
    for (std::uint32_t q = 0; q < mesh.size(); ++q) {
        find_neighbours(mesh, at, q, cos_crease, near);
        add_gradient(mesh, q, near, offset, gradients);
        gradients.begin.push_back(static_cast<std::uint32_t>(gradients.neighbour.size()));
    }
    return gradients;
}

}  // namespace rad
