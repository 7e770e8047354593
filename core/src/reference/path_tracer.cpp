#include "rad/reference/path_tracer.hpp"

#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

#include "reference/path_tracer_paths.hpp"
#include "reference/path_tracer_runner.hpp"

namespace rad {

using path_tracing::PathKey;
using path_tracing::PathScratch;
using path_tracing::PathStart;

PathTracer::PathTracer(const Scene& scene, const PatchMesh& patches, PathTracerOptions options)
    : options_(options) {
    if (options_.roulette_start < 0 || options_.max_depth < 0) {
        throw std::invalid_argument("PathTracer: roulette_start and max_depth must not be negative");
    }
    if (!(options_.max_survival > 0.0 && options_.max_survival <= 1.0)) {
        throw std::invalid_argument("PathTracer: max_survival must be in (0, 1]");
    }
    for (const Patch& p : patches.patches) {
        if (p.surface >= scene.surfaces.size()) {
            throw std::invalid_argument("PathTracer: a patch names a surface the scene does not have");
        }
    }
    context_ = std::make_unique<path_tracing::PathContext>(scene, patches, options_);
}

PathTracer::~PathTracer() = default;

std::vector<Estimate> PathTracer::radiosity_at(std::span<const SurfacePoint> points, int paths_per_point,
                                               PathTracerStats* stats, Progress* progress) const {
    for (const SurfacePoint& p : points) {
        if (p.patch >= context_->patches().size()) {
            throw std::invalid_argument("PathTracer::radiosity_at: patch " + std::to_string(p.patch) +
                                        " out of range");
        }
    }
    const auto start = [points](std::span<const PathKey> keys, std::span<RandomStream>,
                                std::span<PathStart> starts, PathScratch&) -> std::uint64_t {
        for (std::size_t k = 0; k < keys.size(); ++k) {
            const SurfacePoint& p = points[static_cast<std::size_t>(keys[k].item)];
            starts[k] = {p.position, p.patch};
        }
        return 0;
    };
    const auto began = std::chrono::steady_clock::now();
    PathTracerStats run;
    std::vector<Estimate> estimates =
        path_tracing::run_paths(*context_, points.size(), paths_per_point, start, run, progress, "paths");
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    if (stats) *stats = run;
    return estimates;
}

std::vector<Estimate> PathTracer::patch_radiosity(int paths_per_patch, PathTracerStats* stats,
                                                  Progress* progress) const {
    const PatchMesh& patches = context_->patches();
    const auto start = [&patches](std::span<const PathKey> keys, std::span<RandomStream> random,
                                  std::span<PathStart> starts, PathScratch&) -> std::uint64_t {
        for (std::size_t k = 0; k < keys.size(); ++k) {
            const auto patch = static_cast<std::uint32_t>(keys[k].item);
            const glm::dvec2 u(random[k].uniform(), random[k].uniform());
            starts[k] = {path_tracing::point_on_patch(patches, patch, u), patch};
        }
        return 0;
    };
    const auto began = std::chrono::steady_clock::now();
    PathTracerStats run;
    std::vector<Estimate> estimates =
        path_tracing::run_paths(*context_, patches.size(), paths_per_patch, start, run, progress, "paths");
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    if (stats) *stats = run;
    return estimates;
}

double relative_rms_difference(const PatchMesh& patches, std::span<const glm::dvec3> radiosity,
                               std::span<const glm::dvec3> reference) {
    if (radiosity.size() != patches.size() || reference.size() != patches.size()) {
        throw std::invalid_argument("relative_rms_difference: one value per patch expected");
    }
    double difference = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < patches.size(); ++i) {
        const glm::dvec3 d = radiosity[i] - reference[i];
        difference += patches.patches[i].area * glm::dot(d, d);
        norm += patches.patches[i].area * glm::dot(reference[i], reference[i]);
    }
    return norm > 0.0 ? std::sqrt(difference / norm) : 0.0;
}

}  // namespace rad
