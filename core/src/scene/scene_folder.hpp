#pragma once

#include <filesystem>
#include <string>

namespace rad {

// The files a scene names besides itself (material libraries, buffers, textures) must lie in the scene's
// folder or below it, reached without links, so a scene cannot read (and echo in messages) files its author
// did not ship with it. Returns the path of `name` in `folder`, or empty: with `why` set (a phrase such as
// "reaches outside the scene's folder", for the caller to put after the name) when the rule refuses it, and
// `why` left empty when it does not exist.
std::filesystem::path file_in_scene_folder(const std::filesystem::path& folder, const std::string& name,
                                           std::string& why);

}  // namespace rad
