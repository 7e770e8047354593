#include "solve/eigen_form_factors.hpp"

#include <cstdint>
#include <limits>
#include <stdexcept>

namespace rad {

EigenFormFactors::EigenFormFactors(const FormFactorMatrix& matrix) : matrix_(matrix) {
    constexpr auto kLargest = static_cast<std::uint64_t>(std::numeric_limits<int>::max());
    if (matrix.nonzeros() > kLargest || matrix.rows() > kLargest) {
        throw std::length_error("form-factor matrix too large for Eigen's 32-bit indices");
    }
    row_begin_.assign(matrix.row_begin.begin(), matrix.row_begin.end());
}

Eigen::Map<const SparseRowsF> EigenFormFactors::rows() const {
    const auto n = static_cast<Eigen::Index>(matrix_.rows());
    // Columns are uint32 below 2³¹, so reading them as int (the same type but for sign) is exact and allowed.
    return Eigen::Map<const SparseRowsF>(
        n, n, static_cast<Eigen::Index>(matrix_.nonzeros()), row_begin_.data(),
        reinterpret_cast<const int*>(matrix_.column.data()), matrix_.value.data());
}

}  // namespace rad
