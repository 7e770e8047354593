#pragma once

#include <string>

#include "rad/scene/sky.hpp"

namespace rad {

// --sky: "R,G,B" or "L" (a uniform sky of that radiance), "overcast,L" or "overcast,R,G,B" (the CIE
// overcast sky with that zenith radiance), or "none". Throws InputError naming --sky.
Sky parse_sky(const std::string& text);

// --sun: "X,Y,Z,E" or "X,Y,Z,R,G,B": the direction toward the sun (any length) and the irradiance on a plane
// facing it; "none". Throws InputError naming --sun.
Sun parse_sun(const std::string& text);

}  // namespace rad
