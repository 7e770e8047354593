#include "viewer/panel_text.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace rad {

namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 16> kAscii{{
    {"≤", "<="},
    {"≥", ">="},
    {"×", "x"},
    {"²", "^2"},
    {"³", "^3"},
    {"−", "-"},
    {"±", "+/-"},
    {"°", " deg"},
    {"ρ", "rho"},
    {"ω", "omega"},
    {"π", "pi"},
    {"→", "->"},
    {"·", "*"},
    {"…", "..."},
    {"–", "-"},
    {"√", "sqrt"},
}};

// The length of the UTF-8 sequence that starts with byte c (1 for a stray continuation byte).
std::size_t sequence_length(unsigned char c) {
    if (c >= 0xf0) return 4;
    if (c >= 0xe0) return 3;
    if (c >= 0xc0) return 2;
    return 1;
}

}  // namespace

std::string panel_text(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x80) {
            out += text[i++];
            continue;
        }
        const std::size_t length = std::min(sequence_length(c), text.size() - i);
        const std::string_view symbol = text.substr(i, length);
        std::string_view ascii = "?";
        for (const auto& [from, to] : kAscii)
            if (symbol == from) ascii = to;
        out += ascii;
        i += length;
    }
    return out;
}

}  // namespace rad
