#pragma once

#include <cstddef>

namespace rad {

// The memory this process may use: the machine's physical memory, or the container's limit (cgroup v2 or
// v1) when that is lower.
std::size_t usable_memory_bytes();

}  // namespace rad
