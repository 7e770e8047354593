#include "rad/io/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <stdexcept>

namespace rad {

namespace {

// ".NAME.PID-N.tmp.EXT" beside target: unique across processes (pid) and threads (N).
std::filesystem::path temporary_beside(const std::filesystem::path& target) {
    static std::atomic<unsigned> counter{0};
    const std::filesystem::path folder = target.parent_path().empty() ? "." : target.parent_path();
    return folder / ("." + target.filename().string() + "." + std::to_string(::getpid()) + "-" +
                     std::to_string(counter++) + ".tmp" + target.extension().string());
}

}  // namespace

void replace_file_atomically(const std::filesystem::path& target,
                             const std::function<void(const std::filesystem::path& temporary)>& write) {
    const std::filesystem::path temporary = temporary_beside(target);
    try {
        write(temporary);
        std::filesystem::rename(temporary, target);
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
    replace_file_atomically(path, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error("cannot create " + temporary.string());
        out << text;
        out.flush();
        if (!out) throw std::runtime_error("cannot write " + temporary.string());
    });
}

}  // namespace rad
