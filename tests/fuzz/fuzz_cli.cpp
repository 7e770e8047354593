// libFuzzer target: command-line arguments separated by '\0' or '\n', parsed but not run.
#include <cstddef>
#include <cstdint>

#include "fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    rad::fuzz::parse_command_line({data, size});
    return 0;
}
