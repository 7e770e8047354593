#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <span>
#include <vector>

#include "rad/io/image.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"
#include "rad/util/progress.hpp"

namespace rad {

// An independent reference for the radiosity solution: Monte Carlo path tracing of the same diffuse scene,
// traced against the patches' geometry (the same surfaces) with no form factors, so its difference from a
// solution measures the discretization and form-factor error as well as the solver's.
//
// A path starts at a point x0 on the front of a patch and estimates its radiosity
//   B(x0) = E(x0) + ρ(x0) ∫ L(y → x0) cos θ dω,
// gathering emitted light by next-event estimation at every vertex (an emitter patch picked by power, area
// × luminance of Le; a uniform point on it; one shadow ray) and continuing by a cosine-weighted bounce. A
// bounce that reaches an emitter counts its emission only with the weight multiple importance sampling
// gives it against the shadow ray (`mis`; without it, not at all), so no light is counted twice; the start's
// own emission E(x0) is added once. After `roulette_start` bounces a path survives each further bounce with
// probability min(max_survival, max channel of ρ) and is reweighted, so the estimate stays unbiased. Back
// faces block and neither emit nor reflect, as in the form factors. The scene's sky is met by bounces that
// leave the scene (counted at full weight: no shadow ray samples it); its sun gets a shadow ray at every
// vertex.
//
// Each path's random stream depends only on (seed, item, sample), where the item is the point, patch or
// pixel, and sums are reduced in a fixed order, so the results are the same for any number of threads.
// Work runs on all cores (TBB), in batches of rays through RayScene's stream queries; sums are in double.
struct PathTracerOptions {
    std::uint64_t seed = 1;
    // Bounces taken before Russian roulette starts.
    int roulette_start = 3;
    // A safety cap: direct light is gathered at the start and at most this many bounces after it; light
    // that needs more is dropped (0 gives E + ρ × direct light only). Roulette ends paths long before.
    int max_depth = 1000;
    // The largest survival probability of roulette: even at ρ → 1 a path ends after ~20 roulette steps.
    double max_survival = 0.95;
    // Also count the emission that bounces reach, weighting it and next-event estimation by the power
    // heuristic (Veach 1997); each light path is still counted once. Without it, where an emitter meets
    // another surface at an edge, cos θx cos θy / r² makes shadow-ray estimates heavy-tailed (for a patch at
    // the edge the second moment diverges, logarithmically) and standard errors unreliable: the perpendicular
    // squares' receiver needed 16x the paths for the same standard error without it.
    bool mis = true;
};

// A Monte Carlo estimate per RGB channel: the sample mean and its standard error (the sample standard
// deviation over √n), so |mean − truth| < 4–5 standard errors with overwhelming probability.
struct Estimate {
    glm::dvec3 mean{0.0};
    glm::dvec3 standard_error{0.0};
};

// A point on the front of a patch (projected onto the patch's plane before paths leave it).
struct SurfacePoint {
    glm::dvec3 position{0.0};
    std::uint32_t patch = 0;
};

struct PathTracerStats {
    double seconds = 0.0;
    std::uint64_t paths = 0;
    std::uint64_t rays = 0;  // camera, bounce and shadow rays, counting each trip of a ray through Embree
};

// Radiance L = B / π per pixel, linear RGB in the scene's units, top row first, as the renderer's images
// and image files (rad::Image). The camera is the renderer's pinhole (glm::lookAt and glm::perspective with
// the vertical fov and aspect = width / height); each sample is a uniform point in its pixel (a box filter).
// Back faces are invisible to the camera, as in the renderer, which culls them: camera rays pass through
// them. Where a ray meets nothing the radiance is 0.
struct ReferenceImage {
    Image image;
    Image standard_error;  // of each pixel's radiance; an Image of image's size, so it can be written too
    PathTracerStats stats;
};

namespace path_tracing {
class PathContext;
}

// Holds a RayScene over `patches` and the per-patch materials of `scene`; both must outlive it unchanged.
// The queries are const and may run from several threads at once. Long runs report to `progress` (in
// paths) and throw Cancelled when it is cancelled.
class PathTracer {
  public:
    PathTracer(const Scene& scene, const PatchMesh& patches, PathTracerOptions options = {});
    ~PathTracer();
    PathTracer(const PathTracer&) = delete;
    PathTracer& operator=(const PathTracer&) = delete;

    const PathTracerOptions& options() const { return options_; }

    // The radiosity B at each point, from `paths_per_point` paths each.
    std::vector<Estimate> radiosity_at(std::span<const SurfacePoint> points, int paths_per_point,
                                       PathTracerStats* stats = nullptr, Progress* progress = nullptr) const;

    // The area-averaged radiosity of every patch: each path starts at its own uniform random point on the
    // patch, so the standard error covers the variation over the patch as well as the paths'.
    std::vector<Estimate> patch_radiosity(int paths_per_patch, PathTracerStats* stats = nullptr,
                                          Progress* progress = nullptr) const;

    // A reference image of radiance from `camera`, `samples_per_pixel` paths per pixel.
    ReferenceImage render(const Camera& camera, int width, int height, int samples_per_pixel,
                          Progress* progress = nullptr) const;

  private:
    PathTracerOptions options_;
    std::unique_ptr<path_tracing::PathContext> context_;
};

// Area-weighted relative RMS difference of `radiosity` from `reference` over all patches and channels:
// sqrt(Σ A_i |B_i − R_i|² / Σ A_i |R_i|²), |·| the Euclidean norm over RGB.
double relative_rms_difference(const PatchMesh& patches, std::span<const glm::dvec3> radiosity,
                               std::span<const glm::dvec3> reference);

}  // namespace rad
