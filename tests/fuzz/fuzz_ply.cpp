// libFuzzer target: a PLY file, ASCII or binary.
#include <cstddef>
#include <cstdint>

#include "fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    rad::fuzz::load_ply({data, size});
    return 0;
}
