#include "transport/uniform/form_factors_exposed.hpp"

#include <algorithm>

namespace rad {

namespace {

// A wholly covered patch keeps this much area, so the system stays valid; its row is empty anyway.
constexpr double kMinExposed = 1e-6;

}  // namespace

void expose_rows(FormFactorMatrix& matrix, std::span<const double> covered) {
    matrix.exposed.assign(matrix.rows(), 1.0f);
    bool any = false;
    for (std::size_t i = 0; i < matrix.rows(); ++i) {
        if (!(covered[i] > 0.0)) continue;
        any = true;
        // The probes and the rows' own rays estimate the exposed share independently; a row must not come
        // to sum over 1, so the share is at least the row's sum.
        const double row_sum = matrix.row(i).sum();
        const double exposed = std::max({1.0 - covered[i], row_sum, kMinExposed});
        matrix.exposed[i] = static_cast<float>(exposed);
        for (float& value : matrix.row_values(i)) value = static_cast<float>(value / exposed);
    }
    if (!any) matrix.exposed.clear();
}

double covered_area_fraction(const PatchMesh& patches, std::span<const double> covered) {
    if (covered.empty()) return 0.0;
    double area = 0.0, hidden = 0.0;
    for (std::size_t i = 0; i < patches.size(); ++i) {
        area += patches.patches[i].area;
        hidden += patches.patches[i].area * covered[i];
    }
    return area > 0.0 ? hidden / area : 0.0;
}

}  // namespace rad
