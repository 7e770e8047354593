#pragma once

// What the tests of the balanced hierarchies (clustering, hierarchical radiosity) share. Header-only.

#include <cmath>
#include <span>
#include <vector>

#include "rad/transport/transport.hpp"

namespace rad::test {

// (what arrives + what its rows leave unreached) / what is sent, for a radiosity that is no solution (a sine
// over the elements), given each element's row sum (`rows`, its reach): 1 where every element sends what it
// gathers, so that emitted = absorbed + escaped holds converged or not.
inline double any_radiosity_balance(const Transport& transport, std::span<const double> rows) {
    const std::size_t n = transport.size();
    std::vector<glm::dvec3> radiosity(n), arriving(n);
    for (std::size_t k = 0; k < n; ++k)
        radiosity[k] = glm::dvec3(0.5 + 0.5 * std::sin(0.1 * static_cast<double>(k)));
    transport.gather(radiosity, arriving);
    double sent = 0.0, received = 0.0, unreached = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        sent += transport.area[k] * radiosity[k].x;
        received += transport.area[k] * arriving[k].x;
        unreached += transport.area[k] * (1.0 - rows[k]) * radiosity[k].x;
    }
    return (received + unreached) / sent;
}

}  // namespace rad::test
