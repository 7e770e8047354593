#pragma once

#include <string>
#include <string_view>

namespace rad {

// Throws SettingError naming `setting` (image_path, json_path, export_path) when the folder an output file
// would go to does not exist, so a command fails before its long work rather than after it.
void require_output_folder(std::string_view setting, const std::string& path);

}  // namespace rad
