#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene_limits.hpp"

namespace rad {

// The whole file, or InputError naming it: missing, a directory, unreadable, or larger than max_bytes.
std::string read_text_file(const std::string& path, std::size_t max_bytes = kMaxSceneFileBytes);

// A word from a file as a message shows it: in quotes, and cut short when long.
std::string quote_for_message(std::string_view word);

// The whitespace-separated words of a line, its comment (from '#') removed.
std::vector<std::string_view> split_words(std::string_view line);
// The whitespace-separated words of a line, '#' included (PLY has no such comments).
std::vector<std::string_view> split_whitespace(std::string_view line);

// Parses the whole word as a number; false for anything else ("1.5x", "", "--").
bool parse_number(std::string_view word, double& value);
// Why parse_number refused `word`: "number '1e999' is out of range" or "malformed number 'x'".
std::string bad_number_message(std::string_view word);
bool parse_integer(std::string_view word, long long& value);

}  // namespace rad
