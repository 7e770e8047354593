#include "rad/scene/material.hpp"

#include <algorithm>
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

void ReflectanceClamps::clamp(Material& material) {
    const double largest = std::max({material.reflectance.x, material.reflectance.y, material.reflectance.z});
    if (!(largest >= 1.0)) return;
    for (int c = 0; c < 3; ++c)
        if (material.reflectance[c] >= 1.0) material.reflectance[c] = kMaxReflectance;
    largest_ = std::max(largest_, largest);
    if (std::find(names_.begin(), names_.end(), material.name) == names_.end())
        names_.push_back(material.name);
}

std::string ReflectanceClamps::warning(const std::string& source) const {
    if (names_.empty()) return {};
    std::ostringstream out;
    out << source << ": " << names_.size() << " material(s) reflect 1 or more (largest " << largest_
        << ", first '" << names_.front() << "'); clamped to " << kMaxReflectance
        << ", as a surface reflecting all light would make the light grow without end";
    if (largest_ > 2.0) out << " (were colours written from 0 to 255?)";
    return out.str();
}

}  // namespace rad
