#pragma once

#include <string>

#include "bench/bench_sweep.hpp"

namespace rad {

// The sweep as a Markdown table (one row per run), then the comparison with the path tracer.
std::string bench_table(const BenchResults& results);
// One line per run, with a header; numbers in full precision.
std::string bench_csv(const BenchResults& results);
// Total error against the time from the start (mesh, form factors, solve), one series per estimator and
// solver, for each scene.
std::string bench_plot_svg(const BenchResults& results);

}  // namespace rad
