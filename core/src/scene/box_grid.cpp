#include "scene/box_grid.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

namespace rad {

namespace {

// Cells along the scene's largest extent; a polygon over more cells than kMaxCells is kept apart.
constexpr double kCellsAcross = 64.0;
constexpr std::size_t kMaxCells = 512;

}  // namespace

std::size_t BoxGrid::CellRange::count() const {
    const glm::ivec3 n = hi - lo + glm::ivec3(1);
    return static_cast<std::size_t>(n.x) * static_cast<std::size_t>(n.y) * static_cast<std::size_t>(n.z);
}

BoxGrid::BoxGrid(const std::vector<std::vector<glm::dvec3>>& polygons, const BoundingBox& bounds)
    : lower_(polygons.size(), glm::dvec3(0.0)),
      upper_(polygons.size(), glm::dvec3(-1.0)),
      stamp_(polygons.size(), 0) {
    origin_ = bounds.min;
    cell_ = std::max(bounds.largest_extent() / kCellsAcross, 1e-300);
    for (std::uint32_t i = 0; i < polygons.size(); ++i) {
        if (polygons[i].empty()) continue;
        lower_[i] = upper_[i] = polygons[i][0];
        for (const glm::dvec3& p : polygons[i])
            lower_[i] = glm::min(lower_[i], p), upper_[i] = glm::max(upper_[i], p);
        const CellRange r = range(lower_[i], upper_[i]);
        if (r.count() > kMaxCells) {
            large_.push_back(i);
            continue;
        }
        for (int x = r.lo.x; x <= r.hi.x; ++x)
            for (int y = r.lo.y; y <= r.hi.y; ++y)
                for (int z = r.lo.z; z <= r.hi.z; ++z) cells_[key(x, y, z)].push_back(i);
    }
}

BoxGrid::CellRange BoxGrid::range(glm::dvec3 lo, glm::dvec3 hi) const {
    const auto cell = [&](const glm::dvec3& p) {
        return glm::ivec3(
            glm::clamp(glm::floor((p - origin_) / cell_), glm::dvec3(0.0), glm::dvec3(kCellsAcross)));
    };
    return {cell(lo), cell(hi)};
}

std::uint64_t BoxGrid::key(int x, int y, int z) const {
    return (static_cast<std::uint64_t>(x) << 42) | (static_cast<std::uint64_t>(y) << 21) |
           static_cast<std::uint64_t>(z);
}

void BoxGrid::query(const std::vector<glm::dvec3>& points, double margin,
                    std::vector<std::uint32_t>& out) const {
    out.clear();
    if (++query_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0u), query_ = 1;
    glm::dvec3 lo = points[0], hi = points[0];
    for (const glm::dvec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    lo -= margin;
    hi += margin;
    const auto meets = [&](std::uint32_t i) {
        return stamp_[i] != query_ && glm::all(glm::lessThanEqual(lower_[i], hi)) &&
               glm::all(glm::lessThanEqual(lo, upper_[i]));
    };
    const auto visit = [&](std::uint32_t i) {
        if (!meets(i)) return;
        stamp_[i] = query_;
        out.push_back(i);
    };
    for (std::uint32_t i : large_) visit(i);
    const CellRange r = range(lo, hi);
    if (r.count() > kMaxCells * 8) {
        for (std::uint32_t i = 0; i < lower_.size(); ++i) visit(i);
        return;
    }
    for (int x = r.lo.x; x <= r.hi.x; ++x)
        for (int y = r.lo.y; y <= r.hi.y; ++y)
            for (int z = r.lo.z; z <= r.hi.z; ++z) {
                const auto it = cells_.find(key(x, y, z));
                if (it == cells_.end()) continue;
                for (std::uint32_t i : it->second) visit(i);
            }
}

}  // namespace rad
