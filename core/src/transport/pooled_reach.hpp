#pragma once

// The correction of a hierarchy's links by the reach its leaves' rays measure over a pool of leaves, as
// clustering's balance takes it (cluster_balance.cpp). Private to the library.
#include <span>

namespace rad {

// One leaf of a pool: its area, its links' row sum, its measured reach, and the most its prior may be (a
// row cannot take more than every ray: 1, or the share of its area that is exposed).
struct PoolLeaf {
    double area = 0.0, links = 0.0, measured = 0.0, cap = 1.0;
};

// The ratio r ≥ 0 that corrects the pool's links to what its rays measured, counting each leaf's prior
// min(cap, r · links) as the balance will: Σ A min(cap, r links) = Σ A measured. Near a corner or a contact
// the links overestimate and the prior stops at its cap; a plain ratio of the sums would lose that excess
// from the whole pool, and the pool's surfaces would be dark. Where even every prior at its cap falls short,
// one that puts them all there; 1 where the links reach nothing.
double pooled_ratio(std::span<const PoolLeaf> pool);

}  // namespace rad
