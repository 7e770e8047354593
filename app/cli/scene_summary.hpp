#pragma once

#include <ostream>

#include "pipeline/scene_options.hpp"

namespace rad {

// What `radiosity info` prints: surfaces with their materials, areas and patch counts, the totals and the
// bounding box.
void print_scene_summary(std::ostream& out, const LoadedScene& loaded);

}  // namespace rad
