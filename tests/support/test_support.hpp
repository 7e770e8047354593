#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rad::test {

struct CommandResult {
    int status = -1;  // exit status, or -1 if the process did not exit normally
    std::string out;
    std::string err;
};

// Runs the radiosity binary with these arguments (no shell involved) and captures what it prints.
CommandResult run_radiosity(const std::vector<std::string>& args);
// Runs `program` (a path, or a name looked up in PATH) with these arguments, likewise.
CommandResult run_program(const std::string& program, const std::vector<std::string>& args);
// The whole file's bytes (empty if it cannot be read).
std::string read_file_text(const std::filesystem::path& path);
// The full path of `name` found in PATH, or empty.
std::string find_in_path(const std::string& name);

// The corners and faces of an OBJ unit cube [0, 1]³ with every face facing inwards (a closed room); its
// first face is the one at z = 0.
inline constexpr const char* kInwardUnitCubeCorners =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
inline constexpr const char* kInwardUnitCubeFirstFace = "f 1 2 3 4\n";
inline constexpr const char* kInwardUnitCubeOtherFaces =
    "f 5 8 7 6\nf 1 5 6 2\nf 4 3 7 8\nf 1 4 8 5\nf 2 6 7 3\n";

// A fresh directory under the build tree's temp space, removed at the end of the test.
class TempDir {
  public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    // Writes `text` to name inside the directory and returns the full path.
    std::string write(const std::string& name, const std::string& text) const;

  private:
    std::filesystem::path path_;
};

// Writes furnace.obj and furnace.mtl into `dir`: the inward unit cube, every face emitting E = 1 (Le = 1 / π)
// with reflectance 0.5, so B = E / (1 − ρ) = 2 everywhere and every pixel seen from inside shows L = 2 / π.
// Returns the OBJ's path.
std::string write_furnace(const TempDir& dir);

}  // namespace rad::test
