// libFuzzer target: a glTF file, text or (starting with "glTF") binary (see fuzz_inputs.hpp).
#include <cstddef>
#include <cstdint>

#include "fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    rad::fuzz::load_gltf_or_glb({data, size});
    return 0;
}
