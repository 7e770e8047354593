#include "display/gather_rows.hpp"

namespace rad {

void append_rows(std::vector<GatherRow>& rows, GatherTable& table) {
    std::vector<std::uint32_t>& row_begin = table.row_begin;
    std::vector<std::uint32_t>& patch = table.patch;
    std::vector<float>& weight = table.weight;
    std::size_t entries = 0;
    for (const GatherRow& row : rows) entries += row.patch.size();
    patch.reserve(patch.size() + entries);
    weight.reserve(weight.size() + entries);
    row_begin.reserve(row_begin.size() + rows.size() + 1);
    if (row_begin.empty()) row_begin.push_back(0);
    for (GatherRow& row : rows) {
        patch.insert(patch.end(), row.patch.begin(), row.patch.end());
        weight.insert(weight.end(), row.weight.begin(), row.weight.end());
        row = GatherRow{};
        row_begin.push_back(static_cast<std::uint32_t>(patch.size()));
    }
}

}  // namespace rad
