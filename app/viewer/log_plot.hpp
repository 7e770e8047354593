#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rad {

// A line plot of a quantity that falls by decades (a residual, a power), one value per solver step, with
// its axes: the steps along x (the first and the last labelled), powers of ten along y, a grid line per
// decade, and `title` (the quantity and its unit) above with the latest value. `log10_values[i]` is step
// `first_step + i`'s value's log10. Draws into the current Dear ImGui window.
void log_plot(const std::string& title, const std::vector<float>& log10_values, std::size_t first_step = 1);

// The decades a plot of values from `low` to `high` (log10) spans: whole numbers, at least one apart.
struct DecadeRange {
    int low = 0;
    int high = 1;
};
DecadeRange decade_range(float low, float high);

// "1e-3", "1", "1e+05": the label of 10^decade.
std::string decade_label(int decade);

}  // namespace rad
