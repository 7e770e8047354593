#pragma once

#include "rad/display/false_colour.hpp"

namespace rad {

// The false-colour view's legend: the colour bar with its decades labelled in cd/m², in a Dear ImGui window
// whose top right corner is at (right, top) in window units.
void draw_false_colour_legend(const FalseColourScale& scale, float right, float top);

}  // namespace rad
