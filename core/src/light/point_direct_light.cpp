#include "light/point_direct_light.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <stdexcept>
#include <vector>

#include "ray/ray_offset.hpp"
#include "sampling/patch_shapes.hpp"
#include "sampling/power_draws.hpp"
#include "sampling/sampling.hpp"

namespace rad {

namespace {

// A key of the points' random streams, apart from every other pass's.
constexpr std::uint64_t kPointKey = 0x7e47'd1ec'0000'0001ull;
// Of kDirectShadowRays, how many tell first whether a point sees all of the light, or none.
constexpr int kFirstRays = 16;

struct Candidate {
    glm::dvec3 light{0.0};  // E_j U times what each open ray adds, as a share
    std::size_t first_ray = 0, rays = 0;
};

struct Scratch {
    std::vector<double> weight;  // per chunk
    std::vector<PowerDraw> draws;
    std::vector<double> member_weight;  // per patch of a drawn chunk
    std::vector<PowerDraw> member_draws;
    std::vector<Candidate> candidates;
    std::vector<Ray> rays;
    std::vector<std::uint8_t> blocked;
    std::vector<glm::dvec2> strata;
};

struct Estimate {
    glm::dvec3 irradiance{0.0};
    bool uniform = true;  // every ray open, or every ray blocked
};

// One estimate of H_d from `rays` shadow rays drawn over the emitters by power (s.weight, summing to
// `total`): each drawn emitter's unoccluded factor times the share of its rays that reach it.
Estimate estimate_direct(const glm::dvec3& origin, const glm::dvec3& n, int rays, double total,
                         const Emitters& emitters, std::span<const glm::dvec3> emitted, const RayScene& scene,
                         double offset, RandomStream& random, Scratch& s) {
    const bool every = draw_by_power(s.weight, total, rays, random.uniform(), s.draws);
    s.candidates.clear();
    s.rays.clear();
    const glm::dvec3 start = origin + offset * n;
    const auto aim = [&](std::uint32_t k, std::uint32_t count, double chance) {
        const PatchShape& shape = emitters.shapes[k];
        const ConvexPolygon source = clip_to_front(shape.polygon, origin, n);
        if (source.empty()) return;
        const double unoccluded = point_polygon_factor(origin, n, source.span());
        if (!(unoccluded > 0.0)) return;
        const double scale = 1.0 / (static_cast<double>(count) * chance);
        s.candidates.push_back({emitted[emitters.patches[k]] * (unoccluded * scale), s.rays.size(), count});
        s.strata.resize(count);
        stratified_square(random, s.strata);
        for (const glm::dvec2& u : s.strata) {
            const glm::dvec3 end = point_on_convex_polygon(source.span(), u) + offset * shape.normal;
            s.rays.push_back(Ray{start, 0.0f, end - start, 1.0f});
        }
    };
    for (const PowerDraw& d : s.draws) {
        const EmitterChunk& chunk = emitters.chunks[d.source];
        // The chance that a draw of `rays` lands on this chunk at least once; 1 where every chunk was drawn.
        const double chunk_chance = every ? 1.0 : std::min(1.0, rays * s.weight[d.source] / total);
        if (chunk.end - chunk.begin == 1) {
            aim(chunk.begin, d.count, chunk_chance);
            continue;
        }
        // The chunk's own draws go over its patches, by their weights.
        s.member_weight.resize(chunk.end - chunk.begin);
        double members = 0.0;
        for (std::uint32_t k = chunk.begin; k < chunk.end; ++k) {
            s.member_weight[k - chunk.begin] =
                emitters.luminance[k] * factor_weight(origin, n, 0.0, emitters.shapes[k]);
            members += s.member_weight[k - chunk.begin];
        }
        if (!(members > 0.0)) continue;
        const auto draws = static_cast<int>(d.count);
        const bool every_member =
            draw_by_power(s.member_weight, members, draws, random.uniform(), s.member_draws);
        for (const PowerDraw& m : s.member_draws) {
            const double member_chance =
                every_member ? 1.0 : std::min(1.0, draws * s.member_weight[m.source] / members);
            aim(chunk.begin + m.source, m.count, chunk_chance * member_chance);
        }
    }
    s.blocked.resize(s.rays.size());
    scene.occluded(s.rays, s.blocked);
    Estimate estimate;
    const auto open_rays = std::count(s.blocked.begin(), s.blocked.end(), std::uint8_t{0});
    estimate.uniform = open_rays == 0 || static_cast<std::size_t>(open_rays) == s.blocked.size();
    for (const Candidate& c : s.candidates) {
        const auto first = s.blocked.begin() + static_cast<std::ptrdiff_t>(c.first_ray);
        const auto open = std::count(first, first + static_cast<std::ptrdiff_t>(c.rays), std::uint8_t{0});
        estimate.irradiance += static_cast<double>(open) * c.light;
    }
    return estimate;
}

// H_d at a point with unit normal n, and how much of the light it sees. A first few rays tell whether the
// point sees all of the light or none of it (most points); only where they disagree (a penumbra) are the
// rest traced.
// Σ E_k F_k over every emitter patch k, unoccluded.
glm::dvec3 unoccluded_irradiance(const glm::dvec3& origin, const glm::dvec3& n, const Emitters& emitters,
                                 std::span<const glm::dvec3> emitted) {
    glm::dvec3 sum(0.0);
    for (std::size_t k = 0; k < emitters.patches.size(); ++k) {
        const ConvexPolygon source = clip_to_front(emitters.shapes[k].polygon, origin, n);
        if (!source.empty())
            sum += emitted[emitters.patches[k]] * point_polygon_factor(origin, n, source.span());
    }
    return sum;
}

PointLight direct_irradiance(const glm::dvec3& origin, const glm::dvec3& n, const Emitters& emitters,
                             std::span<const glm::dvec3> emitted, const RayScene& scene, double offset,
                             bool exact_when_open, RandomStream& random, Scratch& s) {
    const double total = emitter_weights(origin, n, emitters, s.weight);
    if (!(total > 0.0)) return {};
    const Estimate first =
        estimate_direct(origin, n, kFirstRays, total, emitters, emitted, scene, offset, random, s);
    if (first.uniform) {
        if (first.irradiance == glm::dvec3(0.0)) return {first.irradiance, Visibility::none};
        return {exact_when_open ? unoccluded_irradiance(origin, n, emitters, emitted) : first.irradiance,
                Visibility::whole};
    }
    const Estimate rest = estimate_direct(origin, n, kDirectShadowRays - kFirstRays, total, emitters, emitted,
                                          scene, offset, random, s);
    const double share = static_cast<double>(kFirstRays) / kDirectShadowRays;
    return {share * first.irradiance + (1.0 - share) * rest.irradiance, Visibility::partial};
}

}  // namespace

bool exact_when_open(std::size_t points, const Emitters& emitters, double exact_factor_budget) {
    return static_cast<double>(points) * static_cast<double>(emitters.patches.size()) <= exact_factor_budget;
}

std::vector<PointLight> lights_at(const PatchMesh& patches, const RayScene& rays,
                                  std::span<const glm::dvec3> emitted, const Emitters& emitters,
                                  std::span<const glm::dvec3> points, std::span<const glm::dvec3> normals,
                                  std::uint64_t seed, bool exact_when_open, std::size_t first_index) {
    const double offset = ray_offset(patches);
    std::vector<PointLight> light(points.size());
    tbb::enumerable_thread_specific<Scratch> scratch;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 64),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          Scratch& s = scratch.local();
                          for (std::size_t v = range.begin(); v != range.end(); ++v) {
                              RandomStream random(seed ^ kPointKey, first_index + v);
                              light[v] = direct_irradiance(points[v], normals[v], emitters, emitted, rays,
                                                           offset, exact_when_open, random, s);
                          }
                      });
    return light;
}

bool draws_vertex_direct_light(const PatchMesh& patches, std::span<const glm::dvec3> emitted) {
    if (emitted.size() != patches.size())
        throw std::invalid_argument(
            "draws_vertex_direct_light: the emission does not have one entry per patch");
    return find_emitters(patches, emitted).has_value();
}

std::vector<glm::dvec3> direct_irradiance_at(const PatchMesh& patches, const RayScene& rays,
                                             std::span<const glm::dvec3> emitted,
                                             std::span<const glm::dvec3> points,
                                             std::span<const glm::dvec3> normals, std::uint64_t seed,
                                             double exact_factor_budget) {
    if (emitted.size() != patches.size() || normals.size() != points.size()) {
        throw std::invalid_argument("direct_irradiance_at: the arrays' sizes do not match");
    }
    std::vector<glm::dvec3> irradiance(points.size(), glm::dvec3(0.0));
    const std::optional<Emitters> emitters = find_emitters(patches, emitted);
    if (!emitters) return irradiance;
    const std::vector<PointLight> light =
        lights_at(patches, rays, emitted, *emitters, points, normals, seed,
                  exact_when_open(points.size(), *emitters, exact_factor_budget));
    for (std::size_t k = 0; k < points.size(); ++k) irradiance[k] = light[k].irradiance;
    return irradiance;
}

}  // namespace rad
