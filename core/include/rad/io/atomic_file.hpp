#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace rad {

// Calls `write` with a fresh temporary path in target's folder, then renames the temporary onto target, so
// target appears whole or not at all. The temporary is hidden and keeps target's extension, as some writers
// choose their format by it. On any failure (write throws, or the rename fails) the temporary is removed
// and the exception passes on; target is left as it was.
void replace_file_atomically(const std::filesystem::path& target,
                             const std::function<void(const std::filesystem::path& temporary)>& write);

// Writes `text` to `path` through replace_file_atomically; throws std::runtime_error when it cannot.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace rad
