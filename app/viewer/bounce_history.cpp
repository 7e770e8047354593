#include "viewer/bounce_history.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <memory>
#include <span>
#include <utility>

namespace rad {

namespace {

// Steps whose light alone the panel can show: Jacobi's light is mostly in its first dozens of bounces, and
// each kept step costs a copy of the solution (and of the colours).
constexpr std::size_t kKeptBounces = 64;

float log10_or_floor(double value) {
    return static_cast<float>(std::log10(std::max(value, 1e-30)));
}

std::vector<glm::dvec3> positive_difference(std::span<const glm::dvec3> now,
                                            std::span<const glm::dvec3> before) {
    std::vector<glm::dvec3> difference(now.begin(), now.end());
    if (before.size() != now.size()) return difference;  // the first step: the emission itself
    for (std::size_t i = 0; i < now.size(); ++i)
        difference[i] = glm::max(now[i] - before[i], glm::dvec3(0.0));
    return difference;
}

// One bounce's light alone is no solution to gather from: its patches show it.
ViewerRadiance::Colours bounce_colours(const DisplayMesh& display, const std::vector<glm::dvec3>& bounce,
                                       double direct_share) {
    return std::make_shared<const std::vector<glm::vec3>>(
        vertex_radiance(display, bounce, direct_share, false));
}

}  // namespace

void BounceHistory::restart(std::size_t first_step) {
    patch_bounces_.clear();
    vertex_bounces_.clear();
    direct_share_.clear();
    first_step_ = first_step;
    dropped_ = 0;
    previous_solution_.clear();
    log_residual_.clear();
    log_unshot_.clear();
}

void BounceHistory::add_start(const DisplayMesh& display, std::vector<glm::dvec3> radiosity) {
    const double direct_share = direct_light_share(display, radiosity);
    add_bounce(display, std::move(radiosity), direct_share);
}

void BounceHistory::add_step(const DisplayMesh& display, std::vector<glm::dvec3> before,
                             const std::vector<glm::dvec3>& after, const StepReport& report) {
    add_bounce(display, positive_difference(after, before),
               direct_light_share(display, after) - direct_light_share(display, before));
    previous_solution_ = std::move(before);
    log_residual_.push_back(log10_or_floor(report.residual));
    log_unshot_.push_back(
        log10_or_floor(report.unshot_power.x + report.unshot_power.y + report.unshot_power.z));
}

void BounceHistory::recolour(const DisplayMesh& display) {
    for (std::size_t i = 0; i < patch_bounces_.size(); ++i)
        vertex_bounces_[i] = bounce_colours(display, patch_bounces_[i], direct_share_[i]);
}

void BounceHistory::add_bounce(const DisplayMesh& display, std::vector<glm::dvec3> bounce,
                               double direct_share) {
    vertex_bounces_.push_back(bounce_colours(display, bounce, direct_share));
    patch_bounces_.push_back(std::move(bounce));
    direct_share_.push_back(direct_share);
    if (patch_bounces_.size() > kKeptBounces) {
        patch_bounces_.pop_front();
        vertex_bounces_.pop_front();
        direct_share_.pop_front();
        ++dropped_;
    }
}

}  // namespace rad
