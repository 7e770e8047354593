#include "fuzz_inputs.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli/command_line.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/util/error.hpp"

namespace rad::fuzz {

namespace {

namespace fs = std::filesystem;

// A folder of this process's own, so that parallel fuzzers (or test programs) do not share files; removed
// when the process exits normally.
class ScratchFolder {
  public:
    ScratchFolder() : path_(fs::temp_directory_path() / ("radiosity-fuzz-" + std::to_string(::getpid()))) {
        fs::create_directories(path_);
    }
    ~ScratchFolder() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;

    std::string write(const std::string& name, std::string_view bytes) const {
        const fs::path file = path_ / name;
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (!out.flush()) throw std::runtime_error("cannot write " + file.string());
        return file.string();
    }
    void remove(const std::string& name) const {
        std::error_code ignored;
        fs::remove(path_ / name, ignored);
    }

  private:
    fs::path path_;
};

const ScratchFolder& scratch() {
    static const ScratchFolder folder;
    return folder;
}

std::string_view as_text(std::span<const std::uint8_t> bytes) {
    return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

void require(bool holds, const std::string& what) {
    if (!holds) throw SanityCheckFailed(what);
}

// What the commands do first with a loaded scene: its default patch size and the patch count there.
void check_scene(const Scene& scene) {
    const double area = total_area(scene);
    require(std::isfinite(area) && area > 0.0, "total area " + std::to_string(area));
    const double patch_size = default_patch_size(scene);
    require(std::isfinite(patch_size) && patch_size > 0.0,
            "default patch size " + std::to_string(patch_size));
    require(count_patches(scene, patch_size) >= 1, "no patches at the default patch size");
}

// Loads the scene file; InputError is the expected way to refuse it, and only load_scene may throw it.
Outcome load_and_check(const std::string& path) {
    Scene scene;
    try {
        scene = load_scene(path);
    } catch (const InputError&) {
        return Outcome::refused;
    }
    check_scene(scene);
    return Outcome::accepted;
}

std::vector<std::string> split_arguments(std::string_view text) {
    std::vector<std::string> arguments;
    std::size_t start = 0;
    while (start < text.size() && arguments.size() < kMaxArguments) {
        const std::size_t end = std::min(text.find_first_of(std::string_view("\0\n", 2), start), text.size());
        arguments.emplace_back(text.substr(start, end - start));
        start = end + 1;
    }
    return arguments;
}

}  // namespace

Outcome load_obj_and_mtl(std::span<const std::uint8_t> bytes) {
    const std::string_view text = as_text(bytes);
    const std::size_t separator = text.find(kMtlSeparator);
    if (separator == std::string_view::npos) {
        scratch().remove("scene.mtl");
    } else {
        const std::size_t line_end = text.find('\n', separator);
        scratch().write("scene.mtl", line_end == std::string_view::npos ? "" : text.substr(line_end + 1));
    }
    return load_and_check(scratch().write("scene.obj", text.substr(0, separator)));
}

Outcome load_ply(std::span<const std::uint8_t> bytes) {
    return load_and_check(scratch().write("scene.ply", as_text(bytes)));
}

Outcome load_gltf_or_glb(std::span<const std::uint8_t> bytes) {
    const std::string_view text = as_text(bytes);
    return load_and_check(scratch().write(text.starts_with("glTF") ? "scene.glb" : "scene.gltf", text));
}

Outcome parse_command_line(std::span<const std::uint8_t> bytes) {
    const std::vector<std::string> arguments = split_arguments(as_text(bytes));
    std::vector<const char*> argv{"radiosity"};
    for (const std::string& argument : arguments) argv.push_back(argument.c_str());
    CommandLine command_line;
    try {
        command_line.app().parse(static_cast<int>(argv.size()), argv.data());
    } catch (const CLI::ParseError&) {  // also --help and --help-all (CLI::Success)
        return Outcome::refused;
    }
    return Outcome::accepted;
}

}  // namespace rad::fuzz
