#pragma once

// The rows a gather traces, one per vertex or patch, before they go into its GatherTable. Private to the
// library.

#include <cstdint>
#include <vector>

#include "rad/display/gather_table.hpp"

namespace rad {

// The patches one point's or patch's rays met, each with its share of the rays.
struct GatherRow {
    std::vector<std::uint32_t> patch;
    std::vector<float> weight;
};

// Appends the rows in order to the table (row_begin gets one offset per row and the first 0), freeing each
// row as it is copied, so the rows and the table are not held twice.
void append_rows(std::vector<GatherRow>& rows, GatherTable& table);

}  // namespace rad
