#pragma once

#include <span>
#include <vector>

#include "transport/adaptive/adaptive_leaves.hpp"

namespace rad {

// The dark floor of the gradient criterion, as a share of the scene's area-weighted mean luminance: below it
// differences count as if against the floor, so near-black regions, where any noise is a large relative
// change, do not split forever.
inline constexpr double kGradientFloorFraction = 0.05;

// Neighbours whose planes bend by more than the display's default crease angle, 30° (vertex_colours.hpp),
// are not compared: the light changes abruptly across a box's edge whatever the size of the patches.
inline constexpr double kCreaseCosine = 0.86602540378443865;  // cos 30°

// Differences within this many standard deviations of the form factors' Monte Carlo noise are not taken for
// gradients: with a small light a hemisphere row hits it with few rays, and neighbours then differ by 10-20 %
// at any size, so splitting on noise would never end.
inline constexpr double kNoiseSigmas = 3.0;

// The hemisphere estimator stratifies its rays, which leaves about half the deviation of independent ones:
// on the Cornell box two seeds' solutions differed by 0.48 of the independent-ray estimate below at 1/8 of
// its size and by 0.47 at 1/24.
inline constexpr double kStratifiedNoiseFactor = 0.5;

// The standard deviation of each leaf's radiosity luminance that a hemisphere estimate with `rays` rays per
// row leaves: the reflected part's relative deviation is that of the irradiance H = Σ_j F_ij Y_j, whose
// variance for independent rays is (Σ_j F_ij Y_j² − H²) / rays, times kStratifiedNoiseFactor. All zero for
// rays = 0 (an estimate without that noise).
std::vector<double> radiosity_noise(const SolvedLeaves& leaves, int rays);

// Per leaf, the largest over its neighbours on the same surface and nearly the same plane of |Y_a − Y_b| /
// max(tolerance × max(Y_a, Y_b, floor), kNoiseSigmas × √(σ_a² + σ_b²)) for luminances Y and noise σ; a leaf
// asks to be split when it is at least 1. Both leaves of a steep pair ask.
std::vector<double> gradient_excess(const SolvedLeaves& leaves, double tolerance,
                                    std::span<const double> noise);

}  // namespace rad
