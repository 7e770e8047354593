#include "pipeline/form_factor_options.hpp"

#include <tbb/global_control.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>

namespace rad {

namespace {

// More threads than any machine this runs on has; a larger count is a typo, and TBB would try to honour it.
constexpr std::size_t kMaxThreads = 1024;

// TBB takes its thread limit from a global_control object for as long as the object lives, so the limit
// the command line asked for lives until the process ends.
void limit_threads(std::size_t threads) {
    static std::unique_ptr<tbb::global_control> limit;
    limit.reset();
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
}

}  // namespace

void add_form_factor_options(CLI::App& command, FormFactorOptions& options) {
    const std::map<std::string, FormFactorMethod> methods = {{"hemisphere", FormFactorMethod::hemisphere},
                                                             {"analytic", FormFactorMethod::analytic}};
    command
        .add_option(
            "--ff", options.method,
            "Form factors: hemisphere (cosine-weighted rays from each patch; cost grows with patches x "
            "rays) or analytic (closed-form point-to-polygon factors times shadow-ray visibility; cost "
            "grows with patches²)")
        ->transform(CLI::CheckedTransformer(methods, CLI::ignore_case))
        ->default_str("hemisphere");
    command
        .add_option("--rays", options.rays,
                    "Rays per patch for hemisphere (default " + std::to_string(kDefaultHemisphereRays) +
                        "; light sources' factors are analytic), shadow rays per pair of patches for "
                        "analytic (default " +
                        std::to_string(kDefaultAnalyticRays) + ")")
        ->check(CLI::PositiveNumber);
    command
        .add_option("--seed", options.seed,
                    "Seed of the form factors' random numbers; the same seed gives the "
                    "same results whatever the number of threads")
        ->capture_default_str();
    command
        .add_option_function<std::size_t>(
            "--threads", [](const std::size_t& threads) { limit_threads(threads); },
            "Threads to use (default: all cores)")
        ->check(CLI::Range(std::size_t{1}, kMaxThreads));
    command
        .add_option(
            "--max-memory", options.max_memory_bytes,
            "Memory budget of the form factors, e.g. 512M or 4G (default: half the machine's memory); "
            "over it, the command stops and names a --patch-size that fits")
        ->transform(CLI::AsSizeValue(false))
        ->check(CLI::PositiveNumber);
    command.add_flag("--reciprocity", options.enforce_reciprocity,
                     "Make the form factors reciprocal (A_i F_ij = A_j F_ji) by averaging each pair");
    command.add_flag("--normalize-rows", options.normalize_rows,
                     "Scale each patch's form factors to sum to exactly 1 (for closed scenes only)");
}

FormFactorOptions form_factor_options_for(const FormFactorOptions& options, const LoadedScene& loaded) {
    FormFactorOptions out = options;
    out.patch_size = loaded.patch_size;
    out.emitting_surfaces = emitting_surfaces(loaded.scene);
    out.emitted_luminance = emitted_luminance(loaded.scene, out.emitting_surfaces);
    out.count_patches_at = [&scene = loaded.scene](double patch_size) {
        return count_patches(scene, patch_size);
    };
    return out;
}

}  // namespace rad
