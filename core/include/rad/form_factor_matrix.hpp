#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rad {

// Form factors F_ij in compressed sparse rows: row i holds the patches j that patch i sees, with F_ij in
// float (accumulated in double while computing). Row i's entries are [row_begin[i], row_begin[i + 1]).
struct FormFactorMatrix {
    std::vector<std::uint64_t> row_begin{0};
    std::vector<std::uint32_t> column;
    std::vector<float> value;

    std::size_t rows() const { return row_begin.size() - 1; }
    std::size_t nonzeros() const { return column.size(); }
    std::size_t memory_bytes() const {
        return row_begin.capacity() * sizeof(std::uint64_t) + column.capacity() * sizeof(std::uint32_t) +
               value.capacity() * sizeof(float);
    }
};

}  // namespace rad
