#include "cli/list_file.hpp"

#include <filesystem>
#include <fstream>

#include "rad/util/error.hpp"

namespace rad {

void read_list_file(const std::string& path, std::string_view option, std::uintmax_t max_bytes,
                    std::string_view size_text, std::string_view holds,
                    const std::function<void(std::string_view line, const std::string& where)>& read_line) {
    const std::string named = " (" + std::string(option) + ")";
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (error || !std::filesystem::exists(status)) throw InputError(path + ": no such file" + named);
    if (!std::filesystem::is_regular_file(status)) throw InputError(path + ": not a regular file" + named);
    if (std::filesystem::file_size(path, error) > max_bytes || error)
        throw InputError(path + ": larger than " + std::string(size_text) + "; " + std::string(holds));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot be read" + named);
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
        if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos) continue;
        const auto last = line.find_last_not_of(" \t\r");
        read_line(std::string_view(line).substr(first, last - first + 1),
                  path + ":" + std::to_string(number));
    }
    if (in.bad()) throw InputError(path + ": cannot be read" + named);
}

}  // namespace rad
