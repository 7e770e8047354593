// libFuzzer target: an OBJ text, then optionally a line "#---mtl---" and its MTL text (see fuzz_inputs.hpp).
#include <cstddef>
#include <cstdint>

#include "fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    rad::fuzz::load_obj_and_mtl({data, size});
    return 0;
}
