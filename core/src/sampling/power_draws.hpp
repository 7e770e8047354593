#pragma once

// Drawing light sources by power: how the emitters' columns of uniform transport and the display's direct
// light at vertices pick the emitters they aim their shadow rays at. Private to the library.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rad {

struct PowerDraw {
    std::uint32_t source;  // position in the weights
    std::uint32_t count;   // how many draws fell on it
};

// `draws` draws over the sources by weight (total = Σ weight). When no more sources have a positive weight
// than there are draws, each of them is drawn, about in proportion to its weight (at least once); else the
// draws are points evenly spaced from `offset` (in [0, 1)) along the weights' running sum (systematic
// sampling), so a source of weight share p is drawn floor(K p) or ceil(K p) times, and one with K p < 1
// once with probability K p. Returns whether every source was drawn. `out` follows the weights' order.
bool draw_by_power(const std::vector<double>& weight, double total, int draws, double offset,
                   std::vector<PowerDraw>& out);

// What one of a drawn source's `rays` open shadow rays adds to its unoccluded factor, as a share of it:
// 1 / rays when every source was drawn (or this one always is, expected_draws = K p ≥ 1), the visible share;
// else 1 / (rays · K p), which counts the draws that miss it. Every estimate is then unbiased.
double power_draw_ray_scale(std::size_t rays, double expected_draws, bool every_source);

}  // namespace rad
