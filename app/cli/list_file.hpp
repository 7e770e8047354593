#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace rad {

// A file people type a list into, one entry per line (cameras, sensors): calls `read_line(line, where)` for
// each line that holds anything once its # comment is cut, the line trimmed of blanks and `where` being
// "FILE:LINE". Throws InputError naming the file and `option` when it does not exist, is not a regular file
// or cannot be read, and "FILE: larger than `size_text`; `holds`" when it is larger than max_bytes.
void read_list_file(const std::string& path, std::string_view option, std::uintmax_t max_bytes,
                    std::string_view size_text, std::string_view holds,
                    const std::function<void(std::string_view line, const std::string& where)>& read_line);

}  // namespace rad
