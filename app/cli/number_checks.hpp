#pragma once

#include <CLI/CLI.hpp>

namespace rad {

// CLI11 checks for numeric options, with a message naming the value. CLI11's own Range lets NaN through
// (every comparison with NaN is false), so these test finiteness first.
CLI::Validator positive_number();                     // finite and above zero
CLI::Validator finite_number();                       // any finite value
CLI::Validator finite_range(double min, double max);  // finite, within [min, max]

}  // namespace rad
