#pragma once

// A path-traced reference for the radiosity at points spread over a scene (one at random in each patch of a
// uniform mesh, so that no mesh compared is favoured by having its centroids there),
// and the error of a solution on any mesh sampled at those points: each point reads the radiosity of the
// patch that contains it. Unlike a per-patch comparison, it sees the variation inside large patches, which is
// what adaptive subdivision is for.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <limits>
#include <span>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/reference/path_tracer.hpp"
#include "rad/scene/scene.hpp"
#include "sampling/sampling.hpp"

namespace rad::test {

struct PointReference {
    std::vector<glm::dvec3> position;
    std::vector<std::uint32_t> surface;
    std::vector<double> weight;  // the area each point stands for
    std::vector<Estimate> radiosity;
};

// B at a uniform random point of each patch `patch_size` makes, from `paths` paths each.
inline PointReference path_traced_reference(const Scene& scene, double patch_size, int paths) {
    const PatchMesh mesh = build_patches(scene, MeshingOptions{patch_size});
    PointReference reference;
    std::vector<SurfacePoint> points;
    for (std::uint32_t q = 0; q < mesh.size(); ++q) {
        RandomStream random(12345, q);
        std::array<glm::dvec3, 4> corners{};
        for (int c = 0; c < mesh.corner_count(q); ++c) corners[c] = mesh.points[mesh.corners[q][c]];
        const glm::dvec3 p =
            point_on_convex_polygon(std::span(corners.data(), static_cast<std::size_t>(mesh.corner_count(q))),
                                    {random.uniform(), random.uniform()});
        points.push_back({p, q});
        reference.position.push_back(p);
        reference.surface.push_back(mesh.patches[q].surface);
        reference.weight.push_back(mesh.patches[q].area);
    }
    const PathTracer tracer(scene, mesh);
    reference.radiosity = tracer.radiosity_at(points, paths);
    return reference;
}

// How far p lies from patch q: off its plane, or outside its edges (0 inside; a little inside counts 0 too).
inline double outside_distance(const PatchMesh& mesh, std::uint32_t q, const glm::dvec3& p) {
    const int n = mesh.corner_count(q);
    double outside = std::abs(glm::dot(p - mesh.patches[q].centroid, mesh.patches[q].normal));
    for (int k = 0; k < n; ++k) {
        const glm::dvec3 a = mesh.points[mesh.corners[q][k]], b = mesh.points[mesh.corners[q][(k + 1) % n]];
        const glm::dvec3 inward = glm::normalize(glm::cross(mesh.patches[q].normal, b - a));
        outside = std::max(outside, -glm::dot(p - a, inward));
    }
    return outside;
}

// The patch of the same surface that contains each reference point, or the nearest (a non-planar polygon's
// triangles differ from mesh to mesh).
inline std::vector<std::uint32_t> locate(const PatchMesh& mesh, const PointReference& reference) {
    std::vector<std::uint32_t> found(reference.position.size(), 0);
    for (std::size_t k = 0; k < found.size(); ++k) {
        const std::uint32_t s = reference.surface[k];
        double best = std::numeric_limits<double>::infinity();
        for (std::uint32_t q = mesh.surface_begin[s]; q < mesh.surface_begin[s + 1]; ++q) {
            const double d = outside_distance(mesh, q, reference.position[k]);
            if (d < best) {
                best = d;
                found[k] = q;
            }
        }
    }
    return found;
}

// Over the points of surfaces that do not emit and that the reference sees at all (under a box every path is
// blocked and R is exactly 0), with the reference's own noise, whose square adds to the squared difference on
// average, taken out:
//   absolute: sqrt(Σ w (|B − R|² − se²) / Σ w |R|²), the relative RMS error, ruled by the bright surfaces;
//   relative: sqrt(Σ w (|B − R|² − se²) / |R|² / Σ w), the RMS of each point's relative error, where a dim
//             corner counts as much as a lit wall, as it does to the eye.
struct PointError {
    double absolute = 0.0;
    double relative = 0.0;
};

inline PointError point_error(const Scene& scene, const PatchMesh& mesh,
                              std::span<const glm::dvec3> radiosity, const PointReference& reference) {
    const std::vector<std::uint32_t> patch = locate(mesh, reference);
    double difference = 0.0, norm = 0.0, relative = 0.0, weight = 0.0;
    for (std::size_t k = 0; k < patch.size(); ++k) {
        const Estimate& r = reference.radiosity[k];
        if (scene.surfaces[reference.surface[k]].material.emits() || r.mean == glm::dvec3(0.0)) continue;
        const glm::dvec3 d = radiosity[patch[k]] - r.mean;
        const double squared = glm::dot(d, d) - glm::dot(r.standard_error, r.standard_error);
        difference += reference.weight[k] * squared;
        norm += reference.weight[k] * glm::dot(r.mean, r.mean);
        relative += reference.weight[k] * squared / glm::dot(r.mean, r.mean);
        weight += reference.weight[k];
    }
    if (!(norm > 0.0)) return {};
    return {std::sqrt(std::max(0.0, difference) / norm), std::sqrt(std::max(0.0, relative) / weight)};
}

// The reference's own relative RMS noise over the same points.
inline double reference_noise(const Scene& scene, const PointReference& reference) {
    double noise = 0.0, norm = 0.0;
    for (std::size_t k = 0; k < reference.position.size(); ++k) {
        const Estimate& r = reference.radiosity[k];
        if (scene.surfaces[reference.surface[k]].material.emits() || r.mean == glm::dvec3(0.0)) continue;
        noise += reference.weight[k] * glm::dot(r.standard_error, r.standard_error);
        norm += reference.weight[k] * glm::dot(r.mean, r.mean);
    }
    return norm > 0.0 ? std::sqrt(noise / norm) : 0.0;
}

}  // namespace rad::test
