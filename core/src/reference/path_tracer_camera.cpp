// The path tracer's reference image: camera rays as the OpenGL renderer projects, first visible surfaces.
#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "rad/reference/path_tracer.hpp"
#include "reference/path_tracer_runner.hpp"

namespace rad {

namespace {

using path_tracing::PathKey;
using path_tracing::PathScratch;
using path_tracing::PathStart;

// Back faces a camera ray may pass through before it gives up (and sees black).
constexpr int kMaxBackFaces = 64;

// glm::lookAt's frame and glm::perspective's frustum: a point (x, y) of normalized device coordinates,
// each in [-1, 1] with y up, looks along f + x · aspect · tan(fov / 2) · s + y · tan(fov / 2) · u.
class PinholeCamera {
  public:
    PinholeCamera(const Camera& camera, int width, int height)
        : eye_(camera.eye), width_(width), height_(height) {
        forward_ = glm::normalize(camera.target - camera.eye);
        side_ = glm::normalize(glm::cross(forward_, camera.up));
        up_ = glm::cross(side_, forward_);
        tan_half_ = std::tan(glm::radians(camera.fov_degrees) * 0.5);
        aspect_ = static_cast<double>(width) / static_cast<double>(height);
    }

    // A ray through the point (px + jx, py + jy) of the image, pixel (0, 0) at the top left.
    Ray ray(std::uint64_t pixel, double jx, double jy) const {
        const auto px = static_cast<double>(pixel % static_cast<std::uint64_t>(width_));
        const auto py = static_cast<double>(pixel / static_cast<std::uint64_t>(width_));
        const double x = 2.0 * (px + jx) / width_ - 1.0;
        const double y = 1.0 - 2.0 * (py + jy) / height_;
        const glm::dvec3 direction =
            glm::normalize(forward_ + (x * aspect_ * tan_half_) * side_ + (y * tan_half_) * up_);
        return Ray{eye_, 0.0f, direction, std::numeric_limits<float>::infinity()};
    }

  private:
    glm::dvec3 eye_, forward_{0.0}, side_{0.0}, up_{0.0};
    int width_, height_;
    double tan_half_ = 0.0, aspect_ = 1.0;
};

// The first front face along each ray (through back faces, which the renderer culls), or no patch.
// Returns the rays traced.
std::uint64_t first_visible(const path_tracing::PathContext& context, std::span<Ray> rays,
                            std::span<PathStart> starts, PathScratch& s) {
    std::uint64_t traced = 0;
    s.live.resize(rays.size());
    for (std::uint32_t k = 0; k < rays.size(); ++k) s.live[k] = k;
    for (int pass = 0; pass <= kMaxBackFaces && !s.live.empty(); ++pass) {
        s.shadow_rays.clear();  // free here: the rays still looking
        for (const std::uint32_t k : s.live) s.shadow_rays.push_back(rays[k]);
        s.hits.resize(s.live.size());
        context.rays().intersect(s.shadow_rays, s.hits);
        traced += s.live.size();
        std::size_t kept = 0;
        for (std::size_t j = 0; j < s.live.size(); ++j) {
            const std::uint32_t k = s.live[j];
            const RayHit& hit = s.hits[j];
            if (hit.patch == RayHit::kBackFace) {
                rays[k].tnear = hit.t + static_cast<float>(context.offset());
                s.live[kept++] = k;
            } else if (hit.patch != RayHit::kMissed) {
                starts[k] = {
                    glm::dvec3(rays[k].origin) + static_cast<double>(hit.t) * glm::dvec3(rays[k].direction),
                    hit.patch};
            }
        }
        s.live.resize(kept);
    }
    return traced;
}

}  // namespace

ReferenceImage PathTracer::render(const Camera& camera, int width, int height, int samples_per_pixel,
                                  Progress* progress) const {
    if (width <= 0 || height <= 0) throw std::invalid_argument("PathTracer::render: empty image");
    const auto began = std::chrono::steady_clock::now();
    const PinholeCamera pinhole(camera, width, height);
    const path_tracing::PathContext& context = *context_;
    const auto start = [&pinhole, &context](std::span<const PathKey> keys, std::span<RandomStream> random,
                                            std::span<PathStart> starts, PathScratch& s) -> std::uint64_t {
        s.rays.clear();
        for (std::size_t k = 0; k < keys.size(); ++k) {
            const double jx = random[k].uniform();
            const double jy = random[k].uniform();
            s.rays.push_back(pinhole.ray(keys[k].item, jx, jy));
        }
        return first_visible(context, s.rays, starts, s);
    };
    ReferenceImage result{filled_image(width, height), filled_image(width, height), {}};
    const std::size_t pixels = result.image.pixel_count();
    const std::vector<Estimate> estimates =
        path_tracing::run_paths(context, pixels, samples_per_pixel, start, result.stats, progress, "render");
    for (std::size_t i = 0; i < pixels; ++i) {
        result.image.pixels[i] = glm::vec3(estimates[i].mean / std::numbers::pi);
        result.standard_error.pixels[i] = glm::vec3(estimates[i].standard_error / std::numbers::pi);
    }
    result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    return result;
}

}  // namespace rad
