#include "rad/atomic_file.hpp"

#include <unistd.h>

#include <fstream>
#include <stdexcept>

namespace rad {

void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::path temporary = path;
    temporary += ".tmp-" + std::to_string(::getpid());
    try {
        {
            std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
            if (!out) throw std::runtime_error("cannot create " + temporary.string());
            out << text;
            out.flush();
            if (!out) throw std::runtime_error("cannot write " + temporary.string());
        }
        std::filesystem::rename(temporary, path);
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

}  // namespace rad
