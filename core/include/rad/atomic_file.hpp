#pragma once

#include <filesystem>
#include <string>

namespace rad {

// Writes `text` to a temporary file beside `path` and renames it into place, so the file appears whole or
// not at all; on any failure removes what it wrote and throws std::runtime_error.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace rad
