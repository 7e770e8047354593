// The tracing of a batch of paths: next-event estimation, cosine-weighted bounces, Russian roulette.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>

#include "rad/mesh/patch_albedo.hpp"
#include "ray/ray_offset.hpp"
#include "reference/path_tracer_paths.hpp"

namespace rad::path_tracing {

namespace {

std::vector<glm::dvec3> per_patch(const Scene& scene, const PatchMesh& patches,
                                  glm::dvec3 (*property)(const Material&)) {
    std::vector<glm::dvec3> values(patches.size());
    for (std::size_t i = 0; i < patches.size(); ++i) {
        values[i] = property(scene.surfaces[patches.patches[i].surface].material);
    }
    return values;
}

double max_channel(const glm::dvec3& c) {
    return std::max({c.x, c.y, c.z});
}

// The power heuristic (Veach 1997): the weight of the strategy that drew a sample with density `drawn`
// against the other's density `other` for the same direction (both per unit solid angle).
double power_heuristic(double drawn, double other) {
    const double a = drawn * drawn, b = other * other;
    return a + b > 0.0 ? a / (a + b) : 0.0;
}

}  // namespace

PathContext::PathContext(const Scene& scene, const PatchMesh& patches, const PathTracerOptions& options)
    : patches_(patches),
      options_(options),
      ray_scene_(patches),
      reflectance_(patch_albedo(scene, patches)),
      emitted_radiance_(per_patch(scene, patches, [](const Material& m) { return m.emission; })),
      emitters_(patches, emitted_radiance_),
      sky_(scene.sky),
      sun_(scene.sun),
      offset_(ray_offset(patches)) {}

void PathContext::start_paths(std::span<const PathStart> starts, std::span<glm::dvec3> values,
                              PathScratch& s) const {
    s.paths.resize(starts.size());
    s.live.clear();
    for (std::uint32_t k = 0; k < starts.size(); ++k) {
        values[k] = glm::dvec3(0.0);
        const PathStart& start = starts[k];
        if (start.patch == kNoPatch) continue;
        PathState& path = s.paths[k];
        path.point = onto_patch_plane(patches_, start.patch, start.point);
        path.patch = start.patch;
        path.throughput = reflectance_[start.patch];
        path.depth = 0;
        values[k] = std::numbers::pi * emitted_radiance_[start.patch];  // the start's own E, counted once
        if (max_channel(path.throughput) > 0.0) s.live.push_back(k);
    }
}

// Emitted light arriving at the path's point from one point picked on the emitters: Le cos θx cos θy / r²
// over the point's density, times the path's throughput; it counts if the shadow ray is not blocked.
void PathContext::sample_direct(std::uint32_t k, RandomStream& random, PathScratch& s) const {
    if (emitters_.empty()) return;
    PathState& path = s.paths[k];
    const EmitterSampler::Sample light = emitters_.sample(random);
    const glm::dvec3& n_x = patches_.patches[path.patch].normal;
    const glm::dvec3& n_y = patches_.patches[light.patch].normal;
    const glm::dvec3 d = light.point - path.point;
    const double distance2 = glm::dot(d, d);
    if (!(distance2 > 0.0)) return;
    const double inverse = 1.0 / std::sqrt(distance2);
    const double cos_x = glm::dot(n_x, d) * inverse;
    const double cos_y = -glm::dot(n_y, d) * inverse;
    if (cos_x <= 0.0 || cos_y <= 0.0) return;
    const double weight =
        options_.mis ? power_heuristic(light.pdf_area * distance2 / cos_y, cos_x / std::numbers::pi) : 1.0;
    const glm::dvec3 origin = path.point + offset_ * n_x;
    const glm::dvec3 target = light.point + offset_ * n_y;
    s.shadowed.push_back(k);
    s.shadowed_light.push_back(path.throughput * emitted_radiance_[light.patch] *
                               (weight * cos_x * cos_y / (distance2 * light.pdf_area)));
    s.shadow_rays.push_back(Ray{origin, 0.0f, target - origin, 1.0f});
}

// The sun's irradiance E cos θx at the path's point, times the path's throughput, if its shadow ray to
// infinity is clear.
void PathContext::sample_sun(std::uint32_t k, PathScratch& s) const {
    if (!sun_.present()) return;
    const PathState& path = s.paths[k];
    const glm::dvec3& n = patches_.patches[path.patch].normal;
    const double cos_x = glm::dot(n, sun_.direction);
    if (cos_x <= 0.0) return;
    s.shadowed.push_back(k);
    s.shadowed_light.push_back(path.throughput * sun_.irradiance * cos_x);
    s.shadow_rays.push_back(
        Ray{path.point + offset_ * n, 0.0f, sun_.direction, std::numeric_limits<float>::infinity()});
}

Ray PathContext::bounce_ray(const PathState& path, RandomStream& random) const {
    const glm::dvec3& n = patches_.patches[path.patch].normal;
    const glm::dvec2 u(random.uniform(), random.uniform());
    const glm::dvec3 direction = frame_around(n).to_world(cosine_direction(u));
    return Ray{path.point + offset_ * n, 0.0f, direction, std::numeric_limits<float>::infinity()};
}

// The emission at `point` of `patch`, which the path's bounce reached, times the path's throughput and the
// weight of cosine sampling against next-event estimation for that point.
void PathContext::add_reached_emission(const PathState& path, const glm::dvec3& point, std::uint32_t patch,
                                       glm::dvec3& value) const {
    const glm::dvec3& le = emitted_radiance_[patch];
    if (!(max_channel(le) > 0.0)) return;
    // The same geometry as sample_direct() measures, so the two weights of a point sum to 1.
    const glm::dvec3 d = point - path.point;
    const double distance2 = glm::dot(d, d);
    if (!(distance2 > 0.0)) return;
    const double inverse = 1.0 / std::sqrt(distance2);
    const double cos_x = glm::dot(patches_.patches[path.patch].normal, d) * inverse;
    const double cos_y = -glm::dot(patches_.patches[patch].normal, d) * inverse;
    if (cos_x <= 0.0 || cos_y <= 0.0) return;
    const double light_pdf = emitters_.pdf_area(patch) * distance2 / cos_y;
    // Cosine sampling estimates the irradiance from radiance Le as π Le.
    value += path.throughput * (std::numbers::pi * power_heuristic(cos_x / std::numbers::pi, light_pdf)) * le;
}

// Moves the path to what its bounce ray hit, adding to `value` the emission the bounce found, weighted
// against next-event estimation (if mis). False when the path ends: it left the scene, met a back face or a
// black surface, reached max_depth, or lost at roulette.
bool PathContext::continue_path(PathState& path, const Ray& ray, const RayHit& hit, RandomStream& random,
                                glm::dvec3& value) const {
    // A bounce that leaves the scene meets the sky; cosine sampling estimates its irradiance as π L.
    if (hit.patch == RayHit::kMissed && sky_.present())
        value += path.throughput * std::numbers::pi * sky_.radiance_from(glm::normalize(ray.direction));
    if (hit.patch >= patches_.size()) return false;
    const glm::dvec3 reached =
        glm::dvec3(ray.origin) + static_cast<double>(hit.t) * glm::dvec3(ray.direction);
    const glm::dvec3 point = onto_patch_plane(patches_, hit.patch, reached);
    if (options_.mis) add_reached_emission(path, point, hit.patch, value);
    if (path.depth >= options_.max_depth) return false;
    path.point = point;
    path.patch = hit.patch;
    const glm::dvec3& rho = reflectance_[hit.patch];
    path.throughput *= rho;
    ++path.depth;
    if (path.depth > options_.roulette_start) {
        const double survival = std::min(options_.max_survival, max_channel(rho));
        if (!(random.uniform() < survival)) return false;
        path.throughput /= survival;
    }
    return max_channel(path.throughput) > 0.0;
}

std::uint64_t PathContext::trace(std::span<const PathStart> starts, std::span<RandomStream> random,
                                 std::span<glm::dvec3> values, PathScratch& s) const {
    start_paths(starts, values, s);
    std::uint64_t traced = 0;
    while (!s.live.empty()) {
        s.shadowed.clear();
        s.shadowed_light.clear();
        s.shadow_rays.clear();
        s.rays.clear();
        for (const std::uint32_t k : s.live) {
            sample_direct(k, random[k], s);
            sample_sun(k, s);
            s.rays.push_back(bounce_ray(s.paths[k], random[k]));
        }
        if (!s.shadow_rays.empty()) {
            s.blocked.resize(s.shadow_rays.size());
            ray_scene_.occluded(s.shadow_rays, s.blocked);
            for (std::size_t j = 0; j < s.shadowed.size(); ++j) {
                if (!s.blocked[j]) values[s.shadowed[j]] += s.shadowed_light[j];
            }
        }
        s.hits.resize(s.rays.size());
        ray_scene_.intersect(s.rays, s.hits);
        traced += s.shadow_rays.size() + s.rays.size();
        std::size_t kept = 0;
        for (std::size_t j = 0; j < s.live.size(); ++j) {
            const std::uint32_t k = s.live[j];
            if (continue_path(s.paths[k], s.rays[j], s.hits[j], random[k], values[k])) s.live[kept++] = k;
        }
        s.live.resize(kept);
    }
    return traced;
}

}  // namespace rad::path_tracing
