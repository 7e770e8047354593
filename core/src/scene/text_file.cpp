#include "scene/text_file.hpp"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "rad/util/error.hpp"

namespace rad {

std::string read_text_file(const std::string& path, std::size_t max_bytes) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) throw InputError(path + ": no such file");
    if (fs::is_directory(status)) throw InputError(path + ": is a directory, not a scene file");
    // A pipe or a device would block or never end.
    if (!fs::is_regular_file(status)) throw InputError(path + ": is not a regular file");
    const auto too_large = [&](std::uintmax_t size) {
        return InputError(path + ": file is " + std::to_string(size) + " bytes, more than the limit of " +
                          std::to_string(max_bytes));
    };
    const auto size = fs::file_size(path, ec);
    if (!ec && size > max_bytes) throw too_large(size);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot be read: " + std::strerror(errno));
    // Reads at most one byte past the limit, so a file that grows while it is read is still refused.
    std::string text(static_cast<std::size_t>(ec ? 0 : size), '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.bad() || static_cast<std::size_t>(in.gcount()) != text.size()) {
        throw InputError(path + ": read error (the file changed while it was read?)");
    }
    char extra[4096];
    while (in.read(extra, sizeof extra) || in.gcount() > 0) {
        text.append(extra, static_cast<std::size_t>(in.gcount()));
        if (text.size() > max_bytes) throw too_large(text.size());
    }
    if (in.bad()) throw InputError(path + ": read error");
    return text;
}

std::vector<std::string_view> split_words(std::string_view line) {
    if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    return split_whitespace(line);
}

std::vector<std::string_view> split_whitespace(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

bool parse_number(std::string_view word, double& value) {
    if (word.starts_with('+')) {
        word.remove_prefix(1);
        if (word.starts_with('-')) return false;  // "+-1": from_chars would take the '-'
    }
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    return ec == std::errc() && end == word.data() + word.size() && !word.empty();
}

std::string bad_number_message(std::string_view word) {
    const std::string_view digits = word.starts_with('+') ? word.substr(1) : word;
    double value = 0.0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    const bool whole = end == digits.data() + digits.size() && !digits.empty();
    if (whole && ec == std::errc::result_out_of_range)
        return "number " + quote_for_message(word) + " is out of range";
    return "malformed number " + quote_for_message(word);
}

std::string quote_for_message(std::string_view word) {
    constexpr std::size_t kMaxShown = 40;
    return "'" + std::string(word.substr(0, kMaxShown)) + (word.size() > kMaxShown ? "...'" : "'");
}

bool parse_integer(std::string_view word, long long& value) {
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    return ec == std::errc() && end == word.data() + word.size() && !word.empty();
}

}  // namespace rad
