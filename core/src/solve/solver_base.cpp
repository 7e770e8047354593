#include "solve/solver_base.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/common.hpp>
#include <limits>
#include <stdexcept>

#include "rad/util/error.hpp"

namespace rad {

namespace {

// A thousandfold growth over the lowest residual seen is divergence, not a transient.
constexpr double kGrowthLimit = 1e3;
// Below this level a residual measures rounding, not light: growth and stagnation down there are noise.
constexpr double kRoundingLevel = 1e-10;
// Less than this relative fall over a stagnation window is no progress.
constexpr double kStagnationFall = 1e-3;
// Form factors are floats (relative precision 6e-8). When ρF's spectral radius is this close to 1 the
// system's condition number exceeds 1e6 and float rounding alone moves the answer by several per cent, so
// such a system is treated as singular.
constexpr double kSingularMargin = 1e-6;

const char* channel_name(int c) {
    static const char* const names[3] = {"red", "green", "blue"};
    return names[c];
}

std::string format(const char* pattern, double a, double b = 0.0) {
    char text[160];
    std::snprintf(text, sizeof text, pattern, a, b);
    return text;
}

// Collatz–Wielandt: for a non-negative matrix M and any positive x, min_i (M x)_i / x_i bounds M's spectral
// radius from below. With x = 1 and M = ρF that is min_i ρ_i Σ_j F_ij: at or above 1 on every patch, the
// light of a channel that emits never decays, whatever the method. Returns why, or nothing.
std::optional<std::string> light_cannot_decay(const Transport& transport) {
    const std::vector<double> reach = transport.reach();
    glm::dvec3 lowest(std::numeric_limits<double>::infinity());
    glm::dvec3 emitted(0.0);
    for (std::size_t i = 0; i < transport.size(); ++i) {
        lowest = glm::min(lowest, transport.reflectance[i] * reach[i]);
        emitted += transport.emission[i];
    }
    for (int c = 0; c < 3; ++c) {
        if (emitted[c] > 0.0 && transport.size() > 0 && lowest[c] >= 1.0 - kSingularMargin) {
            return std::string("the light cannot decay in the ") + channel_name(c) +
                   " channel: every patch has reflectance × form-factor row sum ≥ " +
                   format("%.9g", lowest[c]) +
                   ", so ρF has spectral radius ≥ 1 (reflectance 1 in a closed scene, or rows summing over "
                   "1)";
        }
    }
    return std::nullopt;
}

std::vector<glm::dvec3> initial_guess(SolverMethod method, const Transport& transport,
                                      const SolverOptions& options) {
    if (options.initial == InitialGuess::given) {
        // Southwell would take B − E for unshot radiosity, which is right only for the direct illumination.
        if (method == SolverMethod::southwell) {
            throw SettingError("initial_guess", "southwell cannot start from a given radiosity");
        }
        if (options.given.size() != transport.size()) {
            throw std::invalid_argument("given radiosity has " + std::to_string(options.given.size()) +
                                        " values for " + std::to_string(transport.size()) + " elements");
        }
        return options.given;
    }
    std::vector<glm::dvec3> guess = transport.emission;
    if (options.initial == InitialGuess::direct_illumination) {
        jacobi_step(transport, transport.emission, guess);
    }
    return guess;
}

}  // namespace

SolverBase::SolverBase(SolverMethod method, const Transport& transport, const SolverOptions& options)
    : transport_(transport), options_(options), method_(method) {
    const glm::dvec3 emitted = power_per_channel(transport.area, transport.emission);
    const double total = emitted.x + emitted.y + emitted.z;
    emitted_power_ = total > 0.0 ? total : 1.0;
    solution_ = initial_guess(method, transport, options);
    // A first guess that overflows is not handed on; start() then reports the divergence.
    if (!all_finite(solution_)) {
        solution_ = transport.emission;
        first_guess_overflowed_ = true;
    }
}

void SolverBase::start(double residual, const glm::dvec3& unshot_power) {
    report_.step = 0;
    report_.residual = residual;
    report_.unshot_power = unshot_power;
    lowest_residual_ = residual;
    checkpoint_residual_ = residual;
    if (const auto why = light_cannot_decay(transport_)) {
        finish(SolverStatus::not_converging, *why);
    } else if (first_guess_overflowed_ || !std::isfinite(residual) || !is_finite(unshot_power)) {
        report_.residual = 0.0;
        report_.unshot_power = glm::dvec3(0.0);
        finish(SolverStatus::diverged, "the first guess already overflows");
    } else if (residual <= options_.tolerance) {
        finish(SolverStatus::converged,
               format("the first guess has relative residual %.3g ≤ %.3g", residual, options_.tolerance));
    }
}

StepReport SolverBase::step() {
    if (report_.finished()) return report_;
    const StepOutcome outcome = advance();
    ++report_.step;
    report_.residual = outcome.residual;
    report_.unshot_power = outcome.unshot_power;
    judge(outcome);
    return report_;
}

void SolverBase::judge(const StepOutcome& outcome) {
    const double r = outcome.residual;
    const std::size_t k = report_.step;
    if (!std::isfinite(r) || !is_finite(outcome.unshot_power)) {
        report_.residual = lowest_residual_;  // never hand NaN or infinity on
        report_.unshot_power = glm::dvec3(0.0);
        finish(SolverStatus::diverged,
               "step " + std::to_string(k) + " overflowed; the solution keeps its last finite values");
    } else if (outcome.verdict) {
        finish(*outcome.verdict, outcome.reason);
    } else if (r <= options_.tolerance) {
        finish(SolverStatus::converged, format("relative residual %.3g ≤ %.3g", r, options_.tolerance));
    } else if (r > kGrowthLimit * std::max(lowest_residual_, kRoundingLevel)) {
        finish(SolverStatus::diverged, format("the residual grew from %.3g to %.3g", lowest_residual_, r));
    } else if (k % stagnation_window() == 0 && r > (1.0 - kStagnationFall) * checkpoint_residual_) {
        if (r <= kRoundingLevel) {
            finish(SolverStatus::converged,
                   format("converged to working precision: relative residual %.3g", r));
        } else {
            finish(SolverStatus::not_converging,
                   format("the residual went from %.3g to %.3g over the last ", checkpoint_residual_, r) +
                       std::to_string(stagnation_window()) + " steps: the light is not decaying");
        }
    } else if (options_.max_steps > 0 && k >= options_.max_steps) {
        finish(SolverStatus::iteration_limit,
               "stopped at the step limit of " + std::to_string(options_.max_steps) +
                   format(" with relative residual %.3g > %.3g", r, options_.tolerance));
    }
    lowest_residual_ = std::min(lowest_residual_, r);
    if (k % stagnation_window() == 0) checkpoint_residual_ = r;
}

void SolverBase::finish(SolverStatus status, std::string message) {
    report_.status = status;
    message_ = std::move(message);
}

double SolverBase::relative_power(std::span<const glm::dvec3> residual) const {
    return relative_power(power_per_channel(transport_.area, residual));
}

void jacobi_step(const Transport& transport, std::span<const glm::dvec3> radiosity,
                 std::span<glm::dvec3> out) {
    transport.gather(radiosity, out);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = transport.emission[i] + transport.reflectance[i] * out[i];
}

glm::dvec3 power_per_channel(std::span<const double> area, std::span<const glm::dvec3> v) {
    glm::dvec3 power(0.0);
    for (std::size_t i = 0; i < v.size(); ++i) power += area[i] * glm::abs(v[i]);
    return power;
}

glm::dvec3 power_of_difference(std::span<const double> area, std::span<const glm::dvec3> a,
                               std::span<const glm::dvec3> b) {
    glm::dvec3 power(0.0);
    for (std::size_t i = 0; i < a.size(); ++i) power += area[i] * glm::abs(a[i] - b[i]);
    return power;
}

bool is_finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool all_finite(std::span<const glm::dvec3> v) {
    return std::all_of(v.begin(), v.end(), is_finite);
}

}  // namespace rad
