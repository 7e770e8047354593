#include "transport/external/outside_light.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <utility>

#include "sampling/bilinear_quad.hpp"
#include "sampling/edge_strata.hpp"
#include "sampling/sampling.hpp"
#include "transport/uniform/form_factors_hemisphere.hpp"

namespace rad {

namespace {

constexpr std::uint64_t kSkySalt = 0x736b792d6c696768ull;
// Below this exposed share a patch is taken as all covered: its few exposed points would carry the
// whole patch's estimate.
constexpr double kMinExposedShare = 1e-3;
// A split stratum is traced again as kSplit x kSplit sub-strata.
constexpr int kSplit = 4;

// Area-uniform points on one patch's front, lifted off it by the ray offset, with the weight (bilinear
// Jacobian over the area) that keeps the mean exact for any quad.
class PatchPoints {
  public:
    PatchPoints(const PatchMesh& patches, std::uint32_t patch, double offset)
        : quad_{patches.points[patches.corners[patch][0]], patches.points[patches.corners[patch][1]],
                patches.points[patches.corners[patch][2]], patches.points[patches.corners[patch][3]]},
          triangle_(patches.is_triangle(patch)),
          area_(patches.patches[patch].area),
          lift_(offset * patches.patches[patch].normal) {}

    Ray ray(const glm::dvec2& u, const glm::dvec3& direction, double& weight) const {
        glm::dvec3 origin;
        if (triangle_) {
            origin = point_on_triangle(quad_.a, quad_.b, quad_.c, u);
            weight = 1.0;
        } else {
            origin = quad_.point(u);
            weight = quad_.jacobian(u) / area_;
        }
        Ray r;
        r.origin = origin + lift_;
        r.direction = direction;
        r.tnear = 0.0f;
        r.tfar = std::numeric_limits<float>::infinity();
        return r;
    }

  private:
    BilinearQuad quad_;
    bool triangle_;
    double area_;
    glm::dvec3 lift_;
};

struct Scratch {
    std::vector<glm::dvec2> origins;
    std::vector<Ray> rays, split_rays;
    std::vector<double> weights, split_weights;
    std::vector<RayHit> hits, split_hits;
    std::vector<std::uint8_t> blocked;
    std::vector<std::uint32_t> split;  // the strata traced again
};

// The strata of the cosine-mapped square, side x side of them, one ray each, in stratum order (k = y side
// + x), from independent uniform points of the patch: a stratum's ray must not depend on the others', which
// decide whether it is traced again (choose_split_strata).
void sky_rays(const PatchPoints& points, const Frame& frame, int side, RandomStream& random, Scratch& s) {
    const auto n = static_cast<std::size_t>(side * side);
    s.rays.resize(n);
    s.weights.resize(n);
    const double cell = 1.0 / side;
    for (std::size_t k = 0; k < n; ++k) {
        const glm::dvec2 u{(static_cast<double>(k % side) + random.uniform()) * cell,
                           (static_cast<double>(k / side) + random.uniform()) * cell};
        const glm::dvec2 origin{random.uniform(), random.uniform()};
        s.rays[k] = points.ray(origin, frame.to_world(cosine_direction(u)), s.weights[k]);
    }
}

// Strata where the sky's edge passes (a window's frame, a roof's eave) carry the estimate's noise: a stratum
// whose neighbours' rays disagree (one escaped, one did not) is traced again, finely, up to `cap` strata.
// The choice for a stratum looks only at its neighbours' rays, never at its own, which are independent of
// it: so its own ray, where it is kept, is still an unbiased sample, and so are the fresh sub-rays.
void choose_split_strata(const Scratch& s, int side, std::size_t cap, std::vector<std::uint32_t>& split) {
    split.clear();
    const auto escaped = [&](int x, int y) { return s.hits[y * side + x].patch == RayHit::kMissed; };
    for (int y = 0; y < side && split.size() < cap; ++y) {
        for (int x = 0; x < side && split.size() < cap; ++x) {
            if (neighbours_disagree(x, y, side, escaped))
                split.push_back(static_cast<std::uint32_t>(y * side + x));
        }
    }
}

void split_rays(const PatchPoints& points, const Frame& frame, int side, RandomStream& random, Scratch& s) {
    constexpr std::size_t kSub = kSplit * kSplit;
    s.split_rays.resize(s.split.size() * kSub);
    s.split_weights.resize(s.split_rays.size());
    const double cell = 1.0 / side, sub = cell / kSplit;
    std::size_t r = 0;
    for (std::uint32_t k : s.split) {
        const glm::dvec2 corner{static_cast<double>(k % side) * cell, static_cast<double>(k / side) * cell};
        for (std::size_t j = 0; j < kSub; ++j, ++r) {
            const glm::dvec2 u =
                corner + glm::dvec2((static_cast<double>(j % kSplit) + random.uniform()) * sub,
                                    (static_cast<double>(j / kSplit) + random.uniform()) * sub);
            const glm::dvec2 origin{random.uniform(), random.uniform()};
            s.split_rays[r] = points.ray(origin, frame.to_world(cosine_direction(u)), s.split_weights[r]);
        }
    }
}

glm::dvec3 sky_seen(const Sky& sky, const Ray& ray, const RayHit& hit, double weight) {
    return hit.patch == RayHit::kMissed ? weight * sky.radiance_from(glm::normalize(ray.direction))
                                        : glm::dvec3(0.0);
}

// π × the mean sky radiance over the strata, each stratum the mean of its ray or of its sub-rays.
glm::dvec3 sky_irradiance(const Sky& sky, const Scratch& s) {
    glm::dvec3 sum(0.0);
    std::size_t next_split = 0;
    for (std::size_t k = 0; k < s.rays.size(); ++k) {
        if (next_split < s.split.size() && s.split[next_split] == k) {
            constexpr std::size_t kSub = kSplit * kSplit;
            glm::dvec3 stratum(0.0);
            for (std::size_t j = next_split * kSub; j < (next_split + 1) * kSub; ++j)
                stratum += sky_seen(sky, s.split_rays[j], s.split_hits[j], s.split_weights[j]);
            sum += stratum / static_cast<double>(kSub);
            ++next_split;
        } else {
            sum += sky_seen(sky, s.rays[k], s.hits[k], s.weights[k]);
        }
    }
    return std::numbers::pi * sum / static_cast<double>(s.rays.size());
}

// A shadow ray toward the sun from each of side x side stratified points.
glm::dvec3 sun_irradiance(const Sun& sun, const glm::dvec3& normal, const PatchPoints& points, int side,
                          const RayScene& scene, RandomStream& random, Scratch& s) {
    const double cosine = glm::dot(normal, sun.direction);
    if (!(cosine > 0.0)) return glm::dvec3(0.0);
    s.origins.resize(static_cast<std::size_t>(side * side));
    stratified_square(random, s.origins, false);
    s.rays.resize(s.origins.size());
    s.weights.resize(s.origins.size());
    for (std::size_t k = 0; k < s.origins.size(); ++k)
        s.rays[k] = points.ray(s.origins[k], sun.direction, s.weights[k]);
    s.blocked.resize(s.rays.size());
    scene.occluded(s.rays, s.blocked);
    double seen = 0.0;
    for (std::size_t k = 0; k < s.rays.size(); ++k)
        if (!s.blocked[k]) seen += s.weights[k];
    return sun.irradiance * (cosine * seen / static_cast<double>(s.rays.size()));
}

glm::dvec3 patch_outside_irradiance(const Scene& scene, const PatchMesh& patches, std::uint32_t i,
                                    const RayScene& rays, std::uint64_t seed, double offset, int side,
                                    Scratch& s) {
    RandomStream random(seed ^ kSkySalt, i);
    const PatchPoints points(patches, i, offset);
    const Frame frame = frame_around(patches.patches[i].normal);
    glm::dvec3 h(0.0);
    if (scene.sky.present()) {
        sky_rays(points, frame, side, random, s);
        s.hits.resize(s.rays.size());
        rays.intersect(s.rays, s.hits);
        choose_split_strata(s, side, kMaxSplitStrataPerSide * static_cast<std::size_t>(side), s.split);
        split_rays(points, frame, side, random, s);
        s.split_hits.resize(s.split_rays.size());
        if (!s.split_rays.empty()) rays.intersect(s.split_rays, s.split_hits);
        h += sky_irradiance(scene.sky, s);
    }
    if (scene.sun.present())
        h += sun_irradiance(scene.sun, patches.patches[i].normal, points, side, rays, random, s);
    return h;
}

}  // namespace

int outside_light_strata_side(std::size_t patches) {
    const double side = std::floor(std::sqrt(kOutsideLightRayBudget / std::max<double>(1.0, patches)));
    return static_cast<int>(std::clamp(side, 4.0, 32.0));
}

std::vector<glm::dvec3> outside_irradiance(const Scene& scene, const PatchMesh& patches, const RayScene& rays,
                                           std::uint64_t seed, std::span<const double> exposed_area,
                                           Progress* progress) {
    std::vector<glm::dvec3> irradiance(patches.size(), glm::dvec3(0.0));
    if (!has_outside_light(scene)) return irradiance;
    if (progress) progress->begin("sky and sun", patches.size());
    const double offset = ray_offset(patches);
    const int side = outside_light_strata_side(patches.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, patches.size(), 64), [&](const auto& range) {
        if (progress && progress->cancelled()) return;
        thread_local Scratch s;
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
            glm::dvec3 h = patch_outside_irradiance(scene, patches, static_cast<std::uint32_t>(i), rays, seed,
                                                    offset, side, s);
            if (!exposed_area.empty()) {
                const double share = exposed_area[i] / patches.patches[i].area;
                h = share > kMinExposedShare ? h / std::min(1.0, share) : glm::dvec3(0.0);
            }
            irradiance[i] = h;
        }
        if (progress) progress->advance(range.size());
    });
    if (progress && progress->cancelled()) throw Cancelled{};
    return irradiance;
}

void add_outside_light(const Scene& scene, const PatchMesh& base, const RayScene& rays, std::uint64_t seed,
                       std::span<const float> exposed_share, std::span<const glm::dvec3> reflectance,
                       std::span<glm::dvec3> emission, Progress* progress) {
    if (!has_outside_light(scene)) return;
    std::vector<double> exposed;
    if (!exposed_share.empty()) {
        exposed.resize(base.size());
        for (std::size_t i = 0; i < base.size(); ++i) exposed[i] = exposed_share[i] * base.patches[i].area;
    }
    const std::vector<glm::dvec3> h = outside_irradiance(scene, base, rays, seed, exposed, progress);
    for (std::size_t i = 0; i < base.size(); ++i) emission[i] += reflectance[i] * h[i];
}

}  // namespace rad
