#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string_view>

namespace rad::fuzz {

// What the program made of one fuzz input. Anything else that can happen (an exception of another type, a
// failed sanity check, a crash, undefined behaviour) escapes the entry functions, so that libFuzzer, or the
// regression test, reports it.
enum class Outcome {
    accepted,  // the scene loaded (and meshes sanely), or the arguments parsed
    refused,   // rad::InputError, or CLI11's ParseError family (which includes --help)
};

// A loaded scene that breaks what its users rely on: a non-finite or non-positive default patch size or
// area, or no patches.
class SanityCheckFailed : public std::logic_error {
  public:
    using std::logic_error::logic_error;
};

// Splits an OBJ input: the OBJ text ends where this marker (an OBJ comment, written as a line of its own
// in the seeds) first appears, and the MTL text starts on the line after it. Without it the whole input is
// the OBJ and scene.mtl does not exist.
constexpr std::string_view kMtlSeparator = "#---mtl---";

// Writes the OBJ and MTL parts as scene.obj and scene.mtl into this process's scratch folder and loads
// scene.obj; the OBJ seeds say `mtllib scene.mtl`.
Outcome load_obj_and_mtl(std::span<const std::uint8_t> bytes);

// Writes the bytes as scene.ply into this process's scratch folder and loads it.
Outcome load_ply(std::span<const std::uint8_t> bytes);

// Writes the bytes as scene.glb when they start with "glTF" (the binary form's magic), else as scene.gltf,
// into this process's scratch folder, and loads it. The seeds embed their buffers as data: URIs.
Outcome load_gltf_or_glb(std::span<const std::uint8_t> bytes);

// Splits the bytes into arguments at '\0' or '\n' (at most kMaxArguments) and parses them with the
// program's own command line, without running the command they choose.
constexpr std::size_t kMaxArguments = 64;
Outcome parse_command_line(std::span<const std::uint8_t> bytes);

}  // namespace rad::fuzz
