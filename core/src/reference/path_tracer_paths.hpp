#pragma once

// The path tracer's inside: what paths need to know about the scene, and the tracing of a batch of paths
// from given start points (a wavefront: every live path adds one shadow ray and one bounce ray to the batch,
// and the batch goes through RayScene in two stream calls per bounce).

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "rad/ray/ray_scene.hpp"
#include "rad/reference/path_tracer.hpp"
#include "sampling/sampling.hpp"

namespace rad::path_tracing {

inline constexpr std::uint32_t kNoPatch = 0xffffffffu;

// Emitter patches, picked with probability proportional to their power (area × luminance of Le), and a
// uniform point on the one picked.
class EmitterSampler {
  public:
    EmitterSampler(const PatchMesh& patches, std::span<const glm::dvec3> emitted_radiance);

    struct Sample {
        glm::dvec3 point{0.0};
        std::uint32_t patch = kNoPatch;
        double pdf_area = 0.0;  // probability density of the point, per unit area
    };

    bool empty() const { return patch_.empty(); }
    Sample sample(RandomStream& random) const;
    // The density per unit area with which sample() picks a point of this patch (0 off the emitters).
    double pdf_area(std::uint32_t patch) const { return pdf_area_[patch]; }

  private:
    const PatchMesh* patches_;
    std::vector<std::uint32_t> patch_;  // the emitter patches
    std::vector<double> cdf_;           // over patch_, normalized, last = 1
    std::vector<double> pdf_area_;      // per patch of the mesh: its probability / its area
};

// A uniform random point on a patch (a triangle, or a planar convex quad).
glm::dvec3 point_on_patch(const PatchMesh& patches, std::uint32_t patch, glm::dvec2 u);

// p moved along the patch's normal onto its plane, so offsets from it are measured from the surface.
glm::dvec3 onto_patch_plane(const PatchMesh& patches, std::uint32_t patch, const glm::dvec3& p);

// Where a path begins: a point on the front of `patch`, or no surface at all (the estimate is then 0).
struct PathStart {
    glm::dvec3 point{0.0};
    std::uint32_t patch = kNoPatch;
};

struct PathState {
    glm::dvec3 point{0.0};
    glm::dvec3 throughput{0.0};  // the product of ρ along the path, over the roulette survival
    std::uint32_t patch = kNoPatch;
    int depth = 0;  // bounces taken
};

// Per-thread working memory, reused from batch to batch so tracing allocates nothing once warm.
struct PathScratch {
    std::vector<PathState> paths;
    std::vector<std::uint32_t> live;         // paths still going
    std::vector<std::uint32_t> shadowed;     // paths with a shadow ray in flight, in shadow-ray order
    std::vector<glm::dvec3> shadowed_light;  // what each shadow ray adds to its path if it is not blocked
    std::vector<Ray> shadow_rays;
    std::vector<std::uint8_t> blocked;
    std::vector<Ray> rays;  // bounce (or camera) rays, one per live path
    std::vector<RayHit> hits;
};

// What a path needs to know of the scene.
class PathContext {
  public:
    PathContext(const Scene& scene, const PatchMesh& patches, const PathTracerOptions& options);

    const PatchMesh& patches() const { return patches_; }
    const RayScene& rays() const { return ray_scene_; }
    const PathTracerOptions& options() const { return options_; }
    double offset() const { return offset_; }

    // Traces one path from each start with its own random stream; values[k] = the estimate of B at
    // starts[k]. Returns the number of rays traced.
    std::uint64_t trace(std::span<const PathStart> starts, std::span<RandomStream> random,
                        std::span<glm::dvec3> values, PathScratch& scratch) const;

  private:
    void start_paths(std::span<const PathStart> starts, std::span<glm::dvec3> values, PathScratch& s) const;
    void sample_direct(std::uint32_t k, RandomStream& random, PathScratch& s) const;
    void sample_sun(std::uint32_t k, PathScratch& s) const;
    Ray bounce_ray(const PathState& path, RandomStream& random) const;
    void add_reached_emission(const PathState& path, const glm::dvec3& point, std::uint32_t patch,
                              glm::dvec3& value) const;
    bool continue_path(PathState& path, const Ray& ray, const RayHit& hit, RandomStream& random,
                       glm::dvec3& value) const;

    const PatchMesh& patches_;
    PathTracerOptions options_;
    RayScene ray_scene_;
    std::vector<glm::dvec3> reflectance_;       // ρ per patch
    std::vector<glm::dvec3> emitted_radiance_;  // Le per patch
    EmitterSampler emitters_;
    Sky sky_;
    Sun sun_;
    double offset_;  // how far rays start off a surface: a share of the scene's size
};

}  // namespace rad::path_tracing
