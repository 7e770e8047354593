#include "cli/sensors_file.hpp"

#include <charconv>
#include <cmath>
#include <glm/geometric.hpp>
#include <string_view>

#include "cli/list_file.hpp"
#include "rad/util/error.hpp"

namespace rad {

namespace {

// The line's values, split on blanks; each must be a finite number.
std::vector<double> line_values(std::string_view line, const std::string& where) {
    std::vector<double> values;
    std::size_t at = 0;
    while (true) {
        at = line.find_first_not_of(" \t\r", at);
        if (at == std::string_view::npos) break;
        const std::size_t end = std::min(line.find_first_of(" \t\r", at), line.size());
        const std::string_view word = line.substr(at, end - at);
        double value = 0.0;
        const auto [rest, error] = std::from_chars(word.data(), word.data() + word.size(), value);
        if (error != std::errc() || rest != word.data() + word.size() || !std::isfinite(value))
            throw InputError(where + ": '" + std::string(word) + "' is not a finite number");
        values.push_back(value);
        at = end;
    }
    return values;
}

Sensor parse_sensor(std::string_view line, const std::string& where) {
    const std::vector<double> v = line_values(line, where);
    if (v.size() != 6)
        throw InputError(where + ": " + std::to_string(v.size()) + " values; a sensor is x y z dx dy dz");
    const glm::dvec3 direction{v[3], v[4], v[5]};
    const double length = glm::length(direction);
    if (!(length > 0.0) || !std::isfinite(length)) throw InputError(where + ": the direction is zero");
    return {{v[0], v[1], v[2]}, direction / length};
}

}  // namespace

std::vector<Sensor> read_sensors_file(const std::string& path) {
    std::vector<Sensor> sensors;
    read_list_file(path, "--points", kMaxSensorsFileBytes, "256 MiB",
                   "a points file holds one sensor per line",
                   [&](std::string_view line, const std::string& where) {
                       sensors.push_back(parse_sensor(line, where));
                   });
    if (sensors.empty()) throw InputError(path + ": no sensors (one x y z dx dy dz per line)");
    return sensors;
}

}  // namespace rad
