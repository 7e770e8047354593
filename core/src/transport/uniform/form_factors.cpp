#include "rad/transport/uniform/form_factors.hpp"

#include <chrono>
#include <limits>
#include <string>

#include "rad/ray/ray_scene.hpp"
#include "rad/util/error.hpp"
#include "ray/coverage.hpp"
#include "transport/uniform/form_factors_analytic.hpp"
#include "transport/uniform/form_factors_diagnostics.hpp"
#include "transport/uniform/form_factors_emitter_columns.hpp"
#include "transport/uniform/form_factors_exposed.hpp"
#include "transport/uniform/form_factors_hemisphere.hpp"
#include "transport/uniform/form_factors_memory.hpp"
#include "transport/uniform/form_factors_rows.hpp"

namespace rad {

namespace {

int rays_for(const FormFactorOptions& options) {
    if (options.rays < 0) throw SettingError("rays", "must be a positive number of rays");
    if (options.rays > 0) return options.rays;
    return options.method == FormFactorMethod::hemisphere ? kDefaultHemisphereRays : kDefaultAnalyticRays;
}

void check_patch_count(const PatchMesh& patches) {
    // Column indices are 32-bit and RayHit reserves the top two values.
    if (patches.size() >= std::numeric_limits<std::uint32_t>::max() - 2) {
        throw SettingError("patch_size", "form factors: too many patches (" + std::to_string(patches.size()) +
                                             "); use a larger {patch_size}");
    }
}

void fill_report(FormFactorReport& report, const FormFactorMatrix& matrix,
                 const FormFactorDiagnostics& final_d, const RowStats& stats) {
    report.memory_bytes = matrix.memory_bytes();
    report.nonzeros = matrix.nonzeros();
    report.rays = stats.rays;
    report.escaped_ray_fraction = stats.hemisphere_rays > 0 ? static_cast<double>(stats.escaped_rays) /
                                                                  static_cast<double>(stats.hemisphere_rays)
                                                            : 0.0;
    report.max_reciprocity_error = final_d.max_reciprocity_error;
    report.mean_reciprocity_error = final_d.mean_reciprocity_error;
    report.min_row_sum = final_d.min_row_sum;
    report.max_row_sum = final_d.max_row_sum;
    report.rows_over_one = final_d.rows_over_one;
}

// A seed of its own for the emitter columns' shadow rays, so they share no random numbers with the hemisphere
// rays.
constexpr std::uint64_t kEmitterSeedSalt = 0x5eed'e417'7e55'0001ull;

// Each emitter patch's emitted luminance, its surface's (1 for all where the options give none).
std::vector<double> emitter_luminance(const PatchMesh& patches, std::span<const std::uint32_t> emitters,
                                      const FormFactorOptions& options) {
    std::vector<double> by_surface(patches.surface_begin.size(), 1.0);
    if (options.emitted_luminance.size() == options.emitting_surfaces.size()) {
        for (std::size_t k = 0; k < options.emitting_surfaces.size(); ++k) {
            if (options.emitting_surfaces[k] < by_surface.size())
                by_surface[options.emitting_surfaces[k]] = options.emitted_luminance[k];
        }
    }
    std::vector<double> luminance;
    luminance.reserve(emitters.size());
    for (std::uint32_t e : emitters) luminance.push_back(by_surface[patches.patches[e].surface]);
    return luminance;
}

RowFunction hemisphere_rows_with_emitters(const PatchMesh& patches, const RayScene& scene, int rays,
                                          const FormFactorOptions& options, std::vector<double>& covered,
                                          std::vector<double>& escaped) {
    std::vector<std::uint32_t> emitters = emitting_patches(patches, options.emitting_surfaces);
    if (!sample_emitter_columns(patches, emitters))
        return hemisphere_rows(patches, scene, rays, options.seed, covered, escaped);
    RowFunction hemisphere = hemisphere_rows(patches, scene, rays, options.seed, covered, escaped,
                                             column_flags(patches.size(), emitters));
    std::vector<double> luminance = emitter_luminance(patches, emitters, options);
    return merged_rows(std::move(hemisphere),
                       emitter_rows(patches, scene, std::move(emitters), std::move(luminance), rays,
                                    options.seed ^ kEmitterSeedSalt));
}

// The share of each row's light that leaves the scene, per unit of its exposed area as the row is.
void record_escape(FormFactorMatrix& matrix, std::span<const double> escaped) {
    matrix.escaped.resize(matrix.rows());
    for (std::size_t i = 0; i < matrix.rows(); ++i)
        matrix.escaped[i] = static_cast<float>(escaped[i] / matrix.exposed_fraction(i));
}

// "2516 patches × 2048 rays, about 11 MB": what the pass will do and the memory it will take, told before
// the pass so that a long one is expected.
std::string pass_note(const PatchMesh& patches, const FormFactorOptions& options, int rays) {
    const std::size_t n = patches.size();
    const std::string memory =
        format_bytes(static_cast<double>(form_factor_memory_estimate(n, options.method, rays)));
    if (options.method == FormFactorMethod::hemisphere) {
        return std::to_string(n) + " patches × " + std::to_string(rays) + " rays, about " + memory;
    }
    return std::to_string(n) + " patches, " + std::to_string(rays) + " shadow rays per pair, about " + memory;
}

}  // namespace

FormFactorMatrix compute_form_factors(const PatchMesh& patches, const FormFactorOptions& options,
                                      FormFactorReport* report, Progress* progress) {
    const auto start = std::chrono::steady_clock::now();
    const int rays = rays_for(options);
    check_patch_count(patches);
    check_memory_budget(patches, options, rays);

    if (progress) {
        progress->begin("form factors", patches.size());
        if (patches.size() > 0) progress->note(pass_note(patches, options, rays));
    }
    RowStats stats;
    FormFactorMatrix matrix;
    std::vector<double> covered(patches.size(), 0.0);
    std::vector<double> escaped(patches.size(), 0.0);
    if (patches.size() > 0) {
        const RayScene scene(patches);
        const RowFunction row =
            options.method == FormFactorMethod::hemisphere
                ? hemisphere_rows_with_emitters(patches, scene, rays, options, covered, escaped)
                : analytic_rows(patches, scene, rays, options.seed);
        matrix = assemble_rows(patches.size(), row, stats, progress);
        // The analytic rows' shadow rays do not tell covered points apart; probe every patch (a small cost
        // beside its pairs).
        if (options.method == FormFactorMethod::analytic)
            measure_coverage(patches, scene, options.seed, covered);
    }

    const FormFactorDiagnostics estimate = diagnose(matrix, patches);
    if (options.enforce_reciprocity) matrix = enforce_reciprocity(matrix, patches);
    if (!covered.empty()) expose_rows(matrix, covered);
    if (options.method == FormFactorMethod::hemisphere) record_escape(matrix, escaped);
    if (options.normalize_rows) normalize_rows(matrix);
    if (report) {
        report->estimate = estimate;
        const bool changed = options.enforce_reciprocity || options.normalize_rows;
        fill_report(*report, matrix, changed ? diagnose(matrix, patches) : estimate, stats);
        report->covered_area_fraction = covered_area_fraction(patches, covered);
        report->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return matrix;
}

}  // namespace rad
