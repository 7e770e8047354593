#pragma once

#include <string>

namespace rad {

// Re-meshing a saved solution loads the scene it was solved from, which the file names but does not hold as
// a file: it may have moved since. Why the scene `source` cannot be loaded again, or empty when it can (a
// built-in scene, or a file that is there).
std::string missing_scene(const std::string& source);

}  // namespace rad
