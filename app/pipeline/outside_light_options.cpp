#include "pipeline/outside_light_options.hpp"

#include <glm/geometric.hpp>
#include <span>
#include <sstream>
#include <vector>

#include "rad/util/error.hpp"
#include "text/comma_numbers.hpp"

namespace rad {

namespace {

void refuse_negative(std::span<const double> values, const std::string& option, const std::string& what) {
    for (double value : values) {
        if (value < 0.0) {
            std::ostringstream written;
            written << value;
            throw InputError(option + ": " + what + " '" + written.str() + "' is negative");
        }
    }
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
        comma_numbers(overcast ? text.substr(kOvercast.size()) : text, "--sky", want);
    refuse_negative(v, "--sky", "the radiance");
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
    const std::vector<double> v = comma_numbers(text, "--sun", want);
    if (v.size() != 4 && v.size() != 6)
        throw InputError("--sun: " + std::to_string(v.size()) + " numbers; want " + want);
    const glm::dvec3 direction(v[0], v[1], v[2]);
    if (!(glm::length(direction) > 0.0)) throw InputError("--sun: the direction X,Y,Z is zero");
    refuse_negative(std::span(v).subspan(3), "--sun", "the irradiance");
    sun.direction = glm::normalize(direction);
    sun.irradiance = colour(v, 3);
    return sun;
}

}  // namespace rad
