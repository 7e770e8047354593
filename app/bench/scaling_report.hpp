#pragma once

#include <string>

#include "bench/scaling_sweep.hpp"

namespace rad {

// The scaling sweep as a Markdown table (one row per run), the crossover and the notes.
std::string scaling_table(const ScalingResults& results);
// One line per run, with a header; numbers in full precision.
std::string scaling_csv(const ScalingResults& results);

}  // namespace rad
