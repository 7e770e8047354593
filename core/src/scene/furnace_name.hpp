#pragma once

#include <cstddef>
#include <string_view>

namespace rad {

// Throws InputError naming `spec` when `faces` is outside what a furnace may have.
void check_furnace_faces(std::size_t faces, std::string_view spec);

}  // namespace rad
