#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "rad/transport/uniform/form_factor_matrix.hpp"
#include "rad/util/progress.hpp"

namespace rad {

struct RowEntry {
    std::uint32_t column = 0;
    double value = 0.0;
};

struct RowStats {
    std::uint64_t rays = 0;
    std::uint64_t hemisphere_rays = 0;  // of `rays`: those sent into the hemisphere, which may escape
    std::uint64_t escaped_rays = 0;

    RowStats& operator+=(const RowStats& other) {
        rays += other.rays;
        hemisphere_rays += other.hemisphere_rays;
        escaped_rays += other.escaped_rays;
        return *this;
    }
};

// Computes one row: fills `entries` (cleared by the caller) with the nonzero F_ij of row i, sorted by column,
// and adds the rays it traced to `stats`. Called from many threads at once, each row exactly once.
using RowFunction = std::function<void(std::uint32_t row, std::vector<RowEntry>& entries, RowStats& stats)>;

// Runs `row` for every row on all cores (TBB) and assembles the rows in order, so the matrix does not depend
// on how the rows were scheduled. Rows are computed in waves that are compacted as they finish, so the
// working memory beyond the matrix is one wave's rows; assembling the matrix briefly holds its columns
// twice. Advances `progress` per row and throws Cancelled soon after it is cancelled.
FormFactorMatrix assemble_rows(std::size_t rows, const RowFunction& row, RowStats& stats, Progress* progress);

}  // namespace rad
