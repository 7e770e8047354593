#include "transport/adaptive/adaptive_gradient.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "transport/adaptive/adaptive_neighbours.hpp"

namespace rad {

namespace {

double mean_luminance(const SolvedLeaves& leaves) {
    double power = 0.0, area = 0.0;
    for (std::size_t i = 0; i < leaves.radiosity.size(); ++i) {
        power += leaves.system.area[i] * luminance(leaves.radiosity[i]);
        area += leaves.system.area[i];
    }
    return area > 0.0 ? power / area : 0.0;
}

}  // namespace

std::vector<double> radiosity_noise(const SolvedLeaves& leaves, int rays) {
    std::vector<double> noise(leaves.radiosity.size(), 0.0);
    if (rays <= 0) return noise;
    const FormFactorMatrix& f = leaves.system.form_factors;
    for (std::size_t i = 0; i < noise.size(); ++i) {
        double h = 0.0, h2 = 0.0;
        const FormFactorRow row = f.row(i);
        for (std::size_t k = 0; k < row.size(); ++k) {
            const double y = luminance(leaves.radiosity[row.columns[k]]);
            h += static_cast<double>(row.values[k]) * y;
            h2 += static_cast<double>(row.values[k]) * y * y;
        }
        if (!(h > 0.0)) continue;
        const double reflected =
            std::max(0.0, luminance(leaves.radiosity[i]) - luminance(leaves.system.emission[i]));
        noise[i] = kStratifiedNoiseFactor * reflected * std::sqrt(std::max(0.0, h2 - h * h) / rays) / h;
    }
    return noise;
}

std::vector<double> gradient_excess(const SolvedLeaves& leaves, double tolerance,
                                    std::span<const double> noise) {
    std::vector<double> excess(leaves.radiosity.size(), 0.0);
    const double floor = kGradientFloorFraction * mean_luminance(leaves);
    for (const auto& [a, b] : neighbour_pairs(leaves.mesh)) {
        if (leaves.exposed_share(a) < kMinExposedShare || leaves.exposed_share(b) < kMinExposedShare)
            continue;
        if (glm::dot(leaves.mesh.patches[a].normal, leaves.mesh.patches[b].normal) < kCreaseCosine) continue;
        const double ya = luminance(leaves.radiosity[a]), yb = luminance(leaves.radiosity[b]);
        const double threshold =
            std::max(tolerance * std::max({ya, yb, floor}), kNoiseSigmas * std::hypot(noise[a], noise[b]));
        if (!(threshold > 0.0)) continue;  // a black scene
        const double ratio = std::abs(ya - yb) / threshold;
        excess[a] = std::max(excess[a], ratio);
        excess[b] = std::max(excess[b], ratio);
    }
    return excess;
}

}  // namespace rad
