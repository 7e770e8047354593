#include "pipeline/outside_light_options.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>
#include <vector>

#include "rad/util/error.hpp"

namespace rad {

namespace {

// The comma-separated numbers of `text`, each finite and not negative unless `signed_values`.
std::vector<double> numbers(const std::string& text, const std::string& option, const std::string& want,
                            bool signed_values) {
    std::vector<double> values;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        double value = 0.0;
        std::size_t used = 0;
        try {
            value = std::stod(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != item.size() || !std::isfinite(value))
            throw InputError(option + ": '" + item + "' is not a number (want " + want + ")");
        if (!signed_values && value < 0.0)
            throw InputError(option + ": '" + item + "' is negative (want " + want + ")");
        values.push_back(value);
    }
    return values;
}

glm::dvec3 colour(const std::vector<double>& v, std::size_t at) {
    return v.size() - at == 1 ? glm::dvec3(v[at]) : glm::dvec3(v[at], v[at + 1], v[at + 2]);
}

}  // namespace

Sky parse_sky(const std::string& text) {
    const std::string want = "R,G,B, L, overcast,L or overcast,R,G,B";
    Sky sky;
    if (text == "none") return sky;
    constexpr std::string_view kOvercast = "overcast,";
    const bool overcast = text.starts_with(kOvercast);
    const std::vector<double> v =
        numbers(overcast ? text.substr(kOvercast.size()) : text, "--sky", want, false);
    if (v.size() != 1 && v.size() != 3)
        throw InputError("--sky: " + std::to_string(v.size()) + " numbers; want " + want);
    sky.kind = overcast ? Sky::Kind::overcast : Sky::Kind::uniform;
    sky.radiance = colour(v, 0);
    return sky;
}

Sun parse_sun(const std::string& text) {
    const std::string want = "X,Y,Z,E or X,Y,Z,R,G,B";
    Sun sun;
    if (text == "none") return sun;
    const std::vector<double> v = numbers(text, "--sun", want, true);
    if (v.size() != 4 && v.size() != 6)
        throw InputError("--sun: " + std::to_string(v.size()) + " numbers; want " + want);
    const glm::dvec3 direction(v[0], v[1], v[2]);
    if (!(glm::length(direction) > 0.0)) throw InputError("--sun: the direction X,Y,Z is zero");
    for (std::size_t k = 3; k < v.size(); ++k)
        if (v[k] < 0.0) throw InputError("--sun: the irradiance '" + std::to_string(v[k]) + "' is negative");
    sun.direction = glm::normalize(direction);
    sun.irradiance = colour(v, 3);
    return sun;
}

}  // namespace rad
