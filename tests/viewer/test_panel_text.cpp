// The panel's font has ASCII glyphs only: the symbols of the program's messages are spelled in ASCII there.
#include <gtest/gtest.h>

#include <string>

#include "viewer/panel_text.hpp"

namespace rad {
namespace {

TEST(PanelText, SpellsTheMessagesSymbolsInAscii) {
    EXPECT_EQ(panel_text("relative residual 7.73e-06 ≤ 1e-05"), "relative residual 7.73e-06 <= 1e-05");
    EXPECT_EQ(panel_text("ρ ≥ 1, 2 × 3², −4 ± 5°"), "rho >= 1, 2 x 3^2, -4 +/- 5 deg");
    EXPECT_EQ(panel_text("plain text stays"), "plain text stays");
}

TEST(PanelText, AnyOtherCharacterIsOneQuestionMarkAndTheResultIsAscii) {
    const std::string out = panel_text("caf\u00e9 \u4e2d\u6587 \xf0\x9f\x98\x80 end\xe2");
    EXPECT_EQ(out, "caf? ?? ? end?");
    for (char c : out) EXPECT_LT(static_cast<unsigned char>(c), 0x80u);
}

}  // namespace
}  // namespace rad
