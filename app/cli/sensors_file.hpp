#pragma once

#include <string>
#include <vector>

#include "rad/measure/sensor_irradiance.hpp"

namespace rad {

// A points file has one sensor per line, `x y z dx dy dz`: the point and the direction its sensor faces
// (Radiance's rtrace -I reads the same), the direction normalized; blank lines and # comments are skipped.
// Throws InputError naming the file and line for a missing or extra value, a value that is not a finite
// number or a zero direction, and naming the file when it cannot be read, holds no sensor or is larger than
// kMaxSensorsFileBytes.
inline constexpr std::size_t kMaxSensorsFileBytes = std::size_t{256} << 20;
std::vector<Sensor> read_sensors_file(const std::string& path);

}  // namespace rad
