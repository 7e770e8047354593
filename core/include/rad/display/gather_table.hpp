#pragma once

#include <cstdint>
#include <vector>

namespace rad {

// The rows a gather traced, as a sparse table: row r (a vertex or a patch) met patch[k] with the share
// weight[k] of its rays, for k in [row_begin[r], row_begin[r + 1]). Empty: no gather.
struct GatherTable {
    std::vector<std::uint32_t> row_begin;
    std::vector<std::uint32_t> patch;
    std::vector<float> weight;
    bool empty() const { return row_begin.empty(); }
};

}  // namespace rad
