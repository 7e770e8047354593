#pragma once

// The form-factor matrix seen by Eigen, for the solvers that need its linear algebra (transposes, sums,
// factorizations). Private to the library: Eigen stays out of the public headers.

#include <Eigen/SparseCore>
#include <vector>

#include "rad/transport/uniform/form_factor_matrix.hpp"

namespace rad {

using SparseRowsF = Eigen::SparseMatrix<float, Eigen::RowMajor, int>;

// F mapped without copying its values and columns; only the row offsets are converted, since Eigen wants
// one signed index type. Throws std::length_error past 2³¹ − 1 entries. `matrix` must outlive the view.
class EigenFormFactors {
  public:
    explicit EigenFormFactors(const FormFactorMatrix& matrix);
    Eigen::Map<const SparseRowsF> rows() const;

  private:
    const FormFactorMatrix& matrix_;
    std::vector<int> row_begin_;
};

}  // namespace rad
