#include "rad/transport/transport.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rad {

namespace {

bool finite_non_negative(double v) {
    return std::isfinite(v) && v >= 0.0;
}
bool finite_non_negative(const glm::dvec3& v) {
    return finite_non_negative(v.x) && finite_non_negative(v.y) && finite_non_negative(v.z);
}

}  // namespace

void validate_elements(const Transport& transport) {
    const std::size_t n = transport.size();
    if (n == 0) throw std::invalid_argument("radiosity system: no patches");
    if (transport.reflectance.size() != n || transport.emission.size() != n ||
        !(transport.outside.empty() || transport.outside.size() == n)) {
        throw std::invalid_argument(
            "radiosity system: area, reflectance, emission and outside light differ in size");
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!finite_non_negative(transport.area[i]) || transport.area[i] == 0.0) {
            throw std::invalid_argument("radiosity system: patch " + std::to_string(i) +
                                        " has no finite area");
        }
        if (!finite_non_negative(transport.reflectance[i]) || !finite_non_negative(transport.emission[i]) ||
            (!transport.outside.empty() && !finite_non_negative(transport.outside[i]))) {
            throw std::invalid_argument("radiosity system: patch " + std::to_string(i) +
                                        " has a negative or non-finite reflectance or emission");
        }
    }
}

std::vector<double> Transport::escape() const {
    return std::vector<double>(size(), 1.0);
}

EnergyBalance energy_balance(const Transport& transport, std::span<const glm::dvec3> radiosity) {
    if (radiosity.size() != transport.size()) {
        throw std::invalid_argument("energy_balance: the radiosity has the wrong number of patches");
    }
    std::vector<glm::dvec3> arriving(transport.size());
    transport.gather(radiosity, arriving);
    const std::vector<double> reach = transport.reach();
    const std::vector<double> escape = transport.escape();
    EnergyBalance balance;
    for (std::size_t i = 0; i < transport.size(); ++i) {
        const double a = transport.area[i];
        const glm::dvec3& rho = transport.reflectance[i];
        const glm::dvec3 outside = transport.outside.empty() ? glm::dvec3(0.0) : transport.outside[i];
        balance.emitted += a * (transport.emission[i] - rho * outside);
        balance.outside += a * outside;
        balance.absorbed += a * (1.0 - rho) * (arriving[i] + outside);
        const double escaping = std::clamp(escape[i], 0.0, std::max(0.0, 1.0 - reach[i]));
        balance.escaped += a * escaping * radiosity[i];
        balance.behind += a * (1.0 - reach[i] - escaping) * radiosity[i];
    }
    balance.absorbed += balance.behind;
    return balance;
}

}  // namespace rad
