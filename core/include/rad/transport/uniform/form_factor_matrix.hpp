#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rad {

// One row of a FormFactorMatrix: the patches j that patch i sees, ascending, and F_ij.
struct FormFactorRow {
    std::span<const std::uint32_t> columns;
    std::span<const float> values;

    std::size_t size() const { return columns.size(); }
    // Σ_j F_ij in double, in column order.
    double sum() const {
        double total = 0.0;
        for (const float v : values) total += static_cast<double>(v);
        return total;
    }
};

// Form factors F_ij in compressed sparse rows: row i holds the patches j that patch i sees, with F_ij in
// float (accumulated in double while computing). Row i's entries are [row_begin[i], row_begin[i + 1]);
// row(i) is the way to read them.
struct FormFactorMatrix {
    std::vector<std::uint64_t> row_begin{0};
    std::vector<std::uint32_t> column;
    std::vector<float> value;
    // Per row, the share of the patch that other geometry does not cover (a box standing on a floor covers
    // part of the floor patches under its edges); empty means every patch is wholly exposed. A row then holds
    // the form factors of its exposed part, so the light a partly covered patch reflects leaves from that
    // part only instead of being lost into the box.
    std::vector<float> exposed;
    // Per row, the share of the light it sends that meets nothing and leaves the scene (hemisphere rays that
    // escaped); the rest of what the row does not reach meets the backs of one-sided surfaces, which absorb
    // it. Empty where it was not measured (analytic rows), or the rows were normalized.
    std::vector<float> escaped;

    std::size_t rows() const { return row_begin.size() - 1; }
    FormFactorRow row(std::size_t i) const {
        const std::size_t first = row_begin[i], count = row_begin[i + 1] - row_begin[i];
        return {std::span(column).subspan(first, count), std::span(value).subspan(first, count)};
    }
    // Row i's values, to rescale them in place.
    std::span<float> row_values(std::size_t i) {
        return std::span(value).subspan(row_begin[i], row_begin[i + 1] - row_begin[i]);
    }
    double exposed_fraction(std::size_t row) const { return exposed.empty() ? 1.0 : exposed[row]; }
    std::size_t nonzeros() const { return column.size(); }
    std::size_t memory_bytes() const {
        return row_begin.capacity() * sizeof(std::uint64_t) + column.capacity() * sizeof(std::uint32_t) +
               (value.capacity() + exposed.capacity() + escaped.capacity()) * sizeof(float);
    }
};

}  // namespace rad
