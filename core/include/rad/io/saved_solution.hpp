#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "rad/display/gather_table.hpp"
#include "rad/scene/scene.hpp"
#include "rad/solve/solution.hpp"

namespace rad {

// A solved scene, as `solve --save` writes it: the scene as loaded (its warnings excepted) and its solution,
// with what the display drew that is slow to trace again.
struct SavedSolution {
    Scene scene;  // source is solution.settings.scene_source
    Solution solution;
    // A hierarchy's display patches' own gather (DisplayMesh::PatchGather's table: a row per display patch,
    // over the elements), so that opening the file does not trace it again; empty where the display has none.
    GatherTable display_gather;
};

// The file: a 32-byte header, then the payload, all little-endian.
//   0  magic "\x89RADSOL\n" (8 bytes)   8  u32 version   12  u32 0   16  u64 payload bytes
//   24 u64 checksum: 64-bit FNV-1a of the payload
// The payload's layout is in docs/architecture.md ("Saved solutions") and saved_solution.cpp.
inline constexpr std::string_view kSavedSolutionMagic{"\x89RADSOL\n", 8};
inline constexpr std::uint32_t kSavedSolutionVersion = 6;
inline constexpr std::size_t kSavedSolutionHeaderBytes = 32;

// Whether a scene argument names a saved solution rather than a scene: it ends in .radiosity (any case).
bool is_saved_solution_path(const std::filesystem::path& path);

// The whole file's bytes. Throws std::invalid_argument for inconsistent input (array sizes that differ from
// the patch count, a non-finite value), which is a bug of the caller, not bad input.
std::string encode_saved_solution(const SavedSolution& saved);
// Reads what encode_saved_solution wrote. Throws InputError, "NAME: what is wrong" on one line, for a file
// that is not one (wrong magic), another version, a truncated or corrupt file (size, checksum), counts that
// do not fit the bytes left (checked before anything is allocated for them), non-finite or out-of-range
// values, indices out of range and trailing bytes.
SavedSolution decode_saved_solution(std::string_view bytes, const std::string& name);
// 64-bit FNV-1a, the payload's checksum.
std::uint64_t saved_solution_checksum(std::string_view payload);

// Writes through a temporary file renamed into place, so the file appears whole or not at all. Throws
// std::runtime_error when it cannot be written.
void write_saved_solution(const std::filesystem::path& path, const SavedSolution& saved);
// Throws InputError naming the file for a missing, unreadable or non-regular file, and as
// decode_saved_solution does.
SavedSolution read_saved_solution(const std::filesystem::path& path);

}  // namespace rad
