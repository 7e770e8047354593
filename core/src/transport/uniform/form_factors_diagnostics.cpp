#include "transport/uniform/form_factors_diagnostics.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rad {

namespace {

using Range = tbb::blocked_range<std::size_t>;

// Where row i stores column j, or npos.
constexpr std::uint64_t kAbsent = std::numeric_limits<std::uint64_t>::max();
std::uint64_t find_entry(const FormFactorMatrix& m, std::size_t i, std::uint32_t j) {
    const auto first = m.column.begin() + static_cast<std::ptrdiff_t>(m.row_begin[i]);
    const auto last = m.column.begin() + static_cast<std::ptrdiff_t>(m.row_begin[i + 1]);
    const auto it = std::lower_bound(first, last, j);
    return it != last && *it == j ? static_cast<std::uint64_t>(it - m.column.begin()) : kAbsent;
}

// Partial results of diagnose() over a range of rows, combined in a fixed tree by
// parallel_deterministic_reduce so the figures do not depend on the thread count.
struct Tally {
    double max_error = 0.0;
    double error_energy = 0.0;
    double energy = 0.0;
    double min_row_sum = std::numeric_limits<double>::infinity();
    double max_row_sum = -std::numeric_limits<double>::infinity();
    std::size_t rows_over_one = 0;

    static Tally combine(Tally a, const Tally& b) {
        a.max_error = std::max(a.max_error, b.max_error);
        a.error_energy += b.error_energy;
        a.energy += b.energy;
        a.min_row_sum = std::min(a.min_row_sum, b.min_row_sum);
        a.max_row_sum = std::max(a.max_row_sum, b.max_row_sum);
        a.rows_over_one += b.rows_over_one;
        return a;
    }
    void add_pair(double forward_energy, double back_energy) {
        const double larger = std::max(forward_energy, back_energy);
        if (!(larger > 0.0)) return;
        const double difference = std::abs(forward_energy - back_energy);
        max_error = std::max(max_error, difference / larger);
        error_energy += difference;
        energy += forward_energy + back_energy;
    }
};

// Each unordered pair once, from its lower row: the entries (i, j > i), with their mirror (j, i) looked up
// and marked in `mirrored` (each mirror belongs to one pair, so threads never write the same byte).
Tally tally_upper(const FormFactorMatrix& m, const PatchMesh& patches, const Range& rows,
                  std::vector<std::uint8_t>& mirrored, Tally t) {
    for (std::size_t i = rows.begin(); i != rows.end(); ++i) {
        const double s = m.row(i).sum();
        t.min_row_sum = std::min(t.min_row_sum, s);
        t.max_row_sum = std::max(t.max_row_sum, s);
        if (s > 1.0 + kRowSumSlack) ++t.rows_over_one;
        const auto first =
            std::upper_bound(m.column.begin() + static_cast<std::ptrdiff_t>(m.row_begin[i]),
                             m.column.begin() + static_cast<std::ptrdiff_t>(m.row_begin[i + 1]),
                             static_cast<std::uint32_t>(i));
        for (auto k = static_cast<std::uint64_t>(first - m.column.begin()); k < m.row_begin[i + 1]; ++k) {
            const std::uint32_t j = m.column[k];
            const std::uint64_t back = find_entry(m, j, static_cast<std::uint32_t>(i));
            if (back != kAbsent) mirrored[back] = 1;
            // Exposed areas: rows of partly covered patches are those of their exposed parts.
            t.add_pair(
                patches.patches[i].area * m.exposed_fraction(i) * m.value[k],
                back != kAbsent ? patches.patches[j].area * m.exposed_fraction(j) * m.value[back] : 0.0);
        }
    }
    return t;
}

// The pairs stored only in their higher row: entries (i, j < i) that no lower row marked.
Tally tally_lower_only(const FormFactorMatrix& m, const PatchMesh& patches, const Range& rows,
                       const std::vector<std::uint8_t>& mirrored, Tally t) {
    for (std::size_t i = rows.begin(); i != rows.end(); ++i) {
        for (std::uint64_t k = m.row_begin[i]; k < m.row_begin[i + 1] && m.column[k] < i; ++k) {
            if (!mirrored[k]) t.add_pair(patches.patches[i].area * m.exposed_fraction(i) * m.value[k], 0.0);
        }
    }
    return t;
}

// The transpose's pattern and values: entry (j, i) holds F_ij. Counting sort, so rows stay sorted.
FormFactorMatrix transpose(const FormFactorMatrix& m) {
    FormFactorMatrix t;
    t.row_begin.assign(m.rows() + 1, 0);
    for (std::uint32_t j : m.column) ++t.row_begin[j + 1];
    for (std::size_t r = 0; r < m.rows(); ++r) t.row_begin[r + 1] += t.row_begin[r];
    t.column.resize(m.nonzeros());
    t.value.resize(m.nonzeros());
    std::vector<std::uint64_t> next(t.row_begin.begin(), t.row_begin.end() - 1);
    for (std::size_t i = 0; i < m.rows(); ++i) {
        for (std::uint64_t k = m.row_begin[i]; k < m.row_begin[i + 1]; ++k) {
            const std::uint64_t slot = next[m.column[k]]++;
            t.column[slot] = static_cast<std::uint32_t>(i);
            t.value[slot] = m.value[k];
        }
    }
    return t;
}

// Walks row i of F and row i of its transpose together, calling emit(j, F_ij, F_ji) once per column j.
template <class Emit>
void merge_row(const FormFactorMatrix& f, const FormFactorMatrix& t, std::size_t i, Emit&& emit) {
    std::uint64_t a = f.row_begin[i], b = t.row_begin[i];
    const std::uint64_t a_end = f.row_begin[i + 1], b_end = t.row_begin[i + 1];
    while (a < a_end || b < b_end) {
        const std::uint32_t ja = a < a_end ? f.column[a] : std::numeric_limits<std::uint32_t>::max();
        const std::uint32_t jb = b < b_end ? t.column[b] : std::numeric_limits<std::uint32_t>::max();
        const std::uint32_t j = std::min(ja, jb);
        const float forward = ja == j ? f.value[a++] : 0.0f;
        const float back = jb == j ? t.value[b++] : 0.0f;
        emit(j, forward, back);
    }
}

}  // namespace

FormFactorDiagnostics diagnose(const FormFactorMatrix& matrix, const PatchMesh& patches) {
    std::vector<std::uint8_t> mirrored(matrix.nonzeros(), 0);
    const Range rows(0, matrix.rows(), 256);
    const Tally upper = tbb::parallel_deterministic_reduce(
        rows, Tally{},
        [&](const Range& r, Tally partial) { return tally_upper(matrix, patches, r, mirrored, partial); },
        &Tally::combine);
    const Tally lower_only = tbb::parallel_deterministic_reduce(
        rows, Tally{},
        [&](const Range& r, Tally partial) {
            return tally_lower_only(matrix, patches, r, mirrored, partial);
        },
        &Tally::combine);
    const Tally t = Tally::combine(upper, lower_only);
    FormFactorDiagnostics d;
    d.max_reciprocity_error = t.max_error;
    d.mean_reciprocity_error = t.energy > 0.0 ? t.error_energy / t.energy : 0.0;
    d.min_row_sum = matrix.rows() > 0 ? t.min_row_sum : 0.0;
    d.max_row_sum = matrix.rows() > 0 ? t.max_row_sum : 0.0;
    d.rows_over_one = t.rows_over_one;
    return d;
}

FormFactorMatrix enforce_reciprocity(const FormFactorMatrix& matrix, const PatchMesh& patches) {
    const FormFactorMatrix t = transpose(matrix);
    const std::size_t rows = matrix.rows();
    FormFactorMatrix out;
    out.row_begin.assign(rows + 1, 0);
    tbb::parallel_for(Range(0, rows, 256), [&](const Range& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            std::uint64_t count = 0;
            merge_row(matrix, t, i, [&](std::uint32_t, float, float) { ++count; });
            out.row_begin[i + 1] = count;
        }
    });
    for (std::size_t i = 0; i < rows; ++i) out.row_begin[i + 1] += out.row_begin[i];
    out.column.resize(out.row_begin.back());
    out.value.resize(out.row_begin.back());
    tbb::parallel_for(Range(0, rows, 256), [&](const Range& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            std::uint64_t k = out.row_begin[i];
            const double area_i = patches.patches[i].area;
            merge_row(matrix, t, i, [&](std::uint32_t j, float forward, float back) {
                const double mean_energy = 0.5 * (area_i * forward + patches.patches[j].area * back);
                out.column[k] = j;
                out.value[k++] = static_cast<float>(mean_energy / area_i);
            });
        }
    });
    return out;
}

void normalize_rows(FormFactorMatrix& matrix) {
    matrix.escaped.clear();  // a normalized row reaches everything it sends
    tbb::parallel_for(Range(0, matrix.rows(), 256), [&](const Range& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            const double sum = matrix.row(i).sum();
            if (!(sum > 0.0)) continue;
            for (float& value : matrix.row_values(i)) value = static_cast<float>(value / sum);
        }
    });
}

}  // namespace rad
