// The library names its settings; the command line words them by its flags, and words the advice of a
// memory budget overrun itself.
#include <gtest/gtest.h>

#include "text/input_error_message.hpp"

namespace rad {
namespace {

TEST(InputErrorMessage, SettingsAreNamedByTheirFlags) {
    const SettingError e("patch_size", "0.001 would make 6e+06 patches; use {patch_size} 0.0854 or larger");
    EXPECT_EQ(std::string(e.what()),
              "patch size: 0.001 would make 6e+06 patches; use patch size 0.0854 or larger");
    EXPECT_EQ(input_error_message(e),
              "--patch-size: 0.001 would make 6e+06 patches; use --patch-size 0.0854 or larger");
    EXPECT_EQ(input_error_message(SettingError("tolerance", "x")), "--tol: x");
    EXPECT_EQ(input_error_message(SettingError("relaxation", "x")), "--sor: x");
    EXPECT_EQ(input_error_message(SettingError("solver", "x; or a uniform {subdivision}")),
              "--solver: x; or a uniform --subdivision");
    // A setting the command line has no flag for reads as words.
    EXPECT_EQ(flag_of("some_setting"), "some setting");
    // Input errors that are not about a setting pass through unchanged.
    EXPECT_EQ(input_error_message(InputError("scene.obj:3: bad face")), "scene.obj:3: bad face");
}

TEST(InputErrorMessage, AMemoryBudgetOverrunAdvisesAPatchSizeOrMoreMemory) {
    const MemoryBudgetError coarser("form factors need about 14 MB for 1297 patches, over the budget of 1 MB",
                                    14'000'000, 1'000'000, 1297, 0.263);
    EXPECT_EQ(input_error_message(coarser),
              "--max-memory: form factors need about 14 MB for 1297 patches, over the budget of 1 MB; use "
              "--patch-size 0.263 or larger");
    const MemoryBudgetError none("form factors need about 288 KB for 2 patches, over the budget of 10 bytes",
                                 288'000, 10, 2, 0.0);
    EXPECT_NE(input_error_message(none).find("; raise --max-memory"), std::string::npos);
}

}  // namespace
}  // namespace rad
