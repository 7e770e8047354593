#include "util/system_memory.hpp"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace rad {

namespace {

std::size_t physical_memory_bytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES);
    const long page_size = ::sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page_size > 0 ? static_cast<std::size_t>(pages) * static_cast<std::size_t>(page_size)
                                      : 0;
}

// A limit file holds a byte count, or "max" (v2) or a huge number (v1) when there is no limit.
std::size_t cgroup_limit(const char* path) {
    std::ifstream in(path);
    std::size_t limit = 0;
    return (in >> limit) ? limit : 0;
}

}  // namespace

std::size_t usable_memory_bytes() {
    std::size_t usable = physical_memory_bytes();
    for (const char* path : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
        const std::size_t limit = cgroup_limit(path);
        if (limit > 0 && (usable == 0 || limit < usable)) usable = limit;
    }
    return usable;
}

}  // namespace rad
