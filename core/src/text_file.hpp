#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace rad {

// Scene files larger than this are refused before they are read.
constexpr std::size_t kMaxSceneFileBytes = std::size_t{1} << 30;

// The whole file, or InputError naming it: missing, a directory, unreadable, or larger than max_bytes.
std::string read_text_file(const std::string& path, std::size_t max_bytes = kMaxSceneFileBytes);

// The whitespace-separated words of a line, its comment (from '#') removed.
std::vector<std::string_view> split_words(std::string_view line);
// The whitespace-separated words of a line, '#' included (PLY has no such comments).
std::vector<std::string_view> split_whitespace(std::string_view line);

// Parses the whole word as a number; false for anything else ("1.5x", "", "--").
bool parse_number(std::string_view word, double& value);
bool parse_integer(std::string_view word, long long& value);

}  // namespace rad
