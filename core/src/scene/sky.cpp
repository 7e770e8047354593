#include "rad/scene/sky.hpp"

#include <algorithm>

namespace rad {

namespace {

bool positive(const glm::dvec3& c) {
    return std::max({c.x, c.y, c.z}) > 0.0;
}

}  // namespace

bool Sky::present() const {
    return kind != Kind::none && positive(radiance);
}

glm::dvec3 Sky::radiance_from(const glm::dvec3& toward) const {
    switch (kind) {
        case Kind::uniform:
            return radiance;
        case Kind::overcast:
            return toward.y > 0.0 ? radiance * ((1.0 + 2.0 * toward.y) / 3.0) : glm::dvec3(0.0);
        case Kind::none:
            break;
    }
    return glm::dvec3(0.0);
}

bool Sun::present() const {
    return positive(irradiance);
}

}  // namespace rad
