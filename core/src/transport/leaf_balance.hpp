#pragma once

// Sinkhorn's alternation of rows and columns that makes a hierarchy's links conserve energy, shared by
// clustering and hierarchical radiosity. Private to the library.
#include <functional>
#include <span>
#include <vector>

namespace rad {

// The most a leaf's gather or its light is scaled by. A leaf that its links hardly reach (a sliver of a face
// that its ancestors' and clusters' links, pushed down, all but miss; the underside of a model lying just
// above a floor the probes find covered) would otherwise take a scale without bound, up to overflow: it
// keeps this much and the rest of its imbalance.
inline constexpr double kMaxLeafScale = 64.0;

struct LeafScales {
    std::vector<double> receive, send;
    double error = 0.0;  // the largest row error left among the entries whose scale is not at the bound
};

// Per entry k (a leaf; other entries have target 0 and get scales 0): receive and send such that
// receive_k Σ_j T_kj send_j = target_k (the rows) and send_k Σ_j area_j receive_j T_jk = target_k area_k (the
// columns), T given by gather (rows = T · send) and its transpose spread (columns = Tᵀ · weights). At most
// 40 rounds, ending when every row is within 5e-4 of its target; the rows are scaled last, so no entry
// gathers more than its target, converged or not. Both scales at most kMaxLeafScale.
LeafScales balance_rows_and_columns(
    std::span<const double> target, std::span<const double> area,
    const std::function<void(std::span<const double> send, std::vector<double>& rows)>& gather,
    const std::function<void(std::span<const double> weights, std::span<double> columns)>& spread);

}  // namespace rad
