#pragma once

#include <string>
#include <string_view>

namespace rad {

// Refuses an output path whose folder does not exist, naming the option (--out, --json, --export), so a
// command fails before its long work rather than after it.
void require_output_folder(std::string_view option, const std::string& path);

}  // namespace rad
