#include "rad/scene/material.hpp"

#include <cmath>
#include <sstream>

#include "rad/util/error.hpp"

namespace rad {

Material default_material() {
    return Material{"default", glm::dvec3(0.5), glm::dvec3(0.0)};
}

namespace {

std::string format_rgb(const glm::dvec3& c) {
    std::ostringstream out;
    out << c.x << ' ' << c.y << ' ' << c.z;
    return out.str();
}

}  // namespace

void validate_material(const Material& material, const std::string& where) {
    const std::string prefix = where + ": material '" + material.name + "': ";
    for (int c = 0; c < 3; ++c) {
        const double rho = material.reflectance[c];
        if (!std::isfinite(rho) || rho < 0.0 || rho >= 1.0) {
            throw InputError(prefix + "reflectance (Kd) " + format_rgb(material.reflectance) +
                             " must lie in [0, 1) in every channel");
        }
        const double le = material.emission[c];
        if (!std::isfinite(le) || le < 0.0) {
            throw InputError(prefix + "emission (Ke) " + format_rgb(material.emission) +
                             " must be finite and not negative");
        }
    }
}

}  // namespace rad
