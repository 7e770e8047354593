#pragma once

#include <string>
#include <string_view>

#include "rad/util/error.hpp"

namespace rad {

// The command-line flag that sets a library setting ("patch_size" -> "--patch-size"); a setting without a
// flag reads as words ("patch size").
std::string flag_of(std::string_view setting);

// What to tell the user about bad input: the library's settings named by their flags, and for a memory
// budget overrun the advice of a coarser --patch-size or a larger --max-memory.
std::string input_error_message(const InputError& error);

}  // namespace rad
