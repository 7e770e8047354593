#include "display/display_patches.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "rad/ray/ray_scene.hpp"
#include "ray/ray_offset.hpp"

namespace rad {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;
constexpr int kGrid = 4;  // kDisplayPatchSamples = kGrid²
static_assert(kGrid * kGrid == kDisplayPatchSamples);

// The probe rays start this many ray offsets off the surface: past the float error of the surface itself,
// well short of coplanar faces lifted in front (a thousandth of the scene).
constexpr double kProbeOffsets = 16.0;

using Samples = std::array<glm::dvec3, kDisplayPatchSamples>;

// A regular grid over the patch: a quad's cell centres in its bilinear parameters; for a triangle, the
// centroids of its 16 equal sub-triangles (four to an edge).
Samples sample_points(const PatchMesh& mesh, std::size_t d) {
    const glm::uvec4 c = mesh.corners[d];
    const glm::dvec3 p0 = mesh.points[c[0]], p1 = mesh.points[c[1]], p2 = mesh.points[c[2]],
                     p3 = mesh.points[c[3]];
    Samples out{};
    int k = 0;
    if (!mesh.is_triangle(d)) {
        for (int j = 0; j < kGrid; ++j)
            for (int i = 0; i < kGrid; ++i) {
                const double u = (i + 0.5) / kGrid, v = (j + 0.5) / kGrid;
                out[k++] = (1 - u) * (1 - v) * p0 + u * (1 - v) * p1 + u * v * p2 + (1 - u) * v * p3;
            }
        return out;
    }
    const auto at = [&](double a, double b) { return p0 + a * (p1 - p0) + b * (p2 - p0); };
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i + j < kGrid; ++i) {
            out[k++] = at((i + 1.0 / 3) / kGrid, (j + 1.0 / 3) / kGrid);
            if (i + j + 1 < kGrid) out[k++] = at((i + 2.0 / 3) / kGrid, (j + 2.0 / 3) / kGrid);
        }
    return out;
}

// The solution's patches of each input face.
std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> patches_by_face(const PatchMesh& mesh) {
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> out;
    for (std::size_t q = 0; q < mesh.size(); ++q)
        out[face_key(mesh.patches[q])].push_back(static_cast<std::uint32_t>(q));
    return out;
}

// The solution patch whose centroid is nearest p among `candidates` (a sample the probes missed).
std::uint32_t nearest(const PatchMesh& mesh, std::span<const std::uint32_t> candidates, const glm::dvec3& p) {
    std::uint32_t best = kNone;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::uint32_t q : candidates) {
        const glm::dvec3 d = mesh.patches[q].centroid - p;
        const double distance = d.x * d.x + d.y * d.y + d.z * d.z;
        if (distance < best_distance) {
            best_distance = distance;
            best = q;
        }
    }
    return best;
}

struct Locator {
    const PatchMesh& display;
    const PatchMesh& solution;
    const RayScene& rays;
    const std::unordered_map<std::uint64_t, std::vector<std::uint32_t>>& by_face;
    double offset = 0.0;

    // The solution patch under each sample of display patch d: a ray from just in front of the surface into
    // it, then one from just behind (where something touches the front, a block's base on a floor), then the
    // nearest patch of the same face.
    void locate(std::size_t d, std::span<std::uint32_t> out, std::vector<Ray>& batch,
                std::vector<RayHit>& hits) const {
        const Patch& patch = display.patches[d];
        const auto found = by_face.find(face_key(patch));
        if (found == by_face.end()) {
            std::fill(out.begin(), out.end(), kNone);
            return;
        }
        const std::vector<std::uint32_t>& candidates = found->second;
        if (candidates.size() == 1) {
            std::fill(out.begin(), out.end(), candidates.front());
            return;
        }
        const Samples points = sample_points(display, d);
        std::fill(out.begin(), out.end(), kNone);
        for (double side : {1.0, -1.0}) {
            batch.clear();
            for (const glm::dvec3& p : points)
                batch.push_back(Ray{p + side * offset * patch.normal, 0.0f, -side * patch.normal,
                                    static_cast<float>(2.0 * offset)});
            hits.resize(batch.size());
            rays.intersect(batch, hits);
            for (std::size_t k = 0; k < points.size(); ++k) {
                const std::uint32_t q = hits[k].met;
                if (out[k] == kNone && q != RayHit::kMissed &&
                    face_key(solution.patches[q]) == face_key(patch))
                    out[k] = q;
            }
        }
        for (std::size_t k = 0; k < points.size(); ++k)
            if (out[k] == kNone) out[k] = nearest(solution, candidates, points[k]);
    }
};

// Display patch d's shares from the solution patches under its samples: counted, weighted by their exposed
// shares (by the counts alone where every one is covered).
void add_shares(std::span<const std::uint32_t> under, std::span<const double> exposed, DisplayPatches& out) {
    std::vector<std::pair<std::uint32_t, int>> counts;
    for (std::uint32_t q : under) {
        if (q == kNone) continue;
        const auto it =
            std::find_if(counts.begin(), counts.end(), [&](const auto& c) { return c.first == q; });
        if (it == counts.end())
            counts.emplace_back(q, 1);
        else
            ++it->second;
    }
    double weighted = 0.0, total = 0.0;
    for (const auto& [q, n] : counts) {
        weighted += n * exposed[q];
        total += n;
    }
    PatchRestriction& r = out.from_solution;
    for (const auto& [q, n] : counts) {
        r.source.push_back(q);
        r.share.push_back(static_cast<float>(weighted > 0.0 ? n * exposed[q] / weighted : n / total));
    }
    r.begin.push_back(static_cast<std::uint32_t>(r.source.size()));
    out.exposed.push_back(total > 0.0 ? weighted / total : 0.0);
}

}  // namespace

DisplayPatches make_display_patches(const Scene& scene, const PatchMesh& solution,
                                    const RayScene& solution_rays, std::span<const double> exposed,
                                    double patch_size) {
    if (exposed.size() != solution.size())
        throw std::invalid_argument("make_display_patches: `exposed` does not have one entry per patch");
    DisplayPatches out;
    out.mesh = build_patches(scene, MeshingOptions{.patch_size = patch_size});
    const std::size_t n = out.mesh.size();
    const auto by_face = patches_by_face(solution);
    const Locator locator{out.mesh, solution, solution_rays, by_face, kProbeOffsets * ray_offset(solution)};
    std::vector<std::uint32_t> under(n * kDisplayPatchSamples);
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, n, 256), [&](const tbb::blocked_range<std::size_t>& r) {
            std::vector<Ray> batch;
            std::vector<RayHit> hits;
            for (std::size_t d = r.begin(); d != r.end(); ++d)
                locator.locate(d, std::span(under).subspan(d * kDisplayPatchSamples, kDisplayPatchSamples),
                               batch, hits);
        });
    out.from_solution.source_count = solution.size();
    out.from_solution.begin.reserve(n + 1);
    out.from_solution.begin.push_back(0);
    out.exposed.reserve(n);
    for (std::size_t d = 0; d < n; ++d)
        add_shares(std::span(under).subspan(d * kDisplayPatchSamples, kDisplayPatchSamples), exposed, out);
    return out;
}

}  // namespace rad
