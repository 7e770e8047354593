#pragma once

#include <string>
#include <string_view>

namespace rad {

// Text for the panel, whose font (Dear ImGui's default) has ASCII glyphs only: the symbols the program's
// messages use become ASCII ("≤" "<=", "ρ" "rho", "×" "x", "²" "^2", ...); any other non-ASCII character
// becomes "?", one per character rather than one per byte.
std::string panel_text(std::string_view text);

}  // namespace rad
