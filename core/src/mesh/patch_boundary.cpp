#include "mesh/patch_boundary.hpp"

namespace rad {

PointPatches patches_at_points(const PatchMesh& mesh) {
    PointPatches at;
    at.begin.assign(mesh.points.size() + 1, 0);
    for (std::size_t q = 0; q < mesh.size(); ++q) {
        for (std::uint32_t p : patch_boundary(mesh, q)) ++at.begin[p + 1];
    }
    for (std::size_t p = 0; p < mesh.points.size(); ++p) at.begin[p + 1] += at.begin[p];
    at.patch.resize(at.begin.back());
    std::vector<std::uint32_t> next(at.begin.begin(), at.begin.end() - 1);
    for (std::size_t q = 0; q < mesh.size(); ++q) {
        for (std::uint32_t p : patch_boundary(mesh, q)) at.patch[next[p]++] = static_cast<std::uint32_t>(q);
    }
    return at;
}

}  // namespace rad
