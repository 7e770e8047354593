// Numeric options are checked when the command line is read: CLI11's Range lets NaN through, so every
// floating-point option also refuses NaN and infinity, and counts that would make the program try the
// impossible (a million threads) are refused. Each gives exit status 2, one line naming the option, and
// writes nothing. (In tests/render so that under the sanitizers it runs without leak checks, as every
// program that opens an OpenGL context does: see tests/CMakeLists.txt.)
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace rad {
namespace {

TEST(RenderOptionChecks, NonFiniteAndAbsurdValuesExitTwoNamingTheOption) {
    test::TempDir dir;
    const std::string out = (dir.path() / "x.png").string();
    const std::vector<std::vector<std::string>> cases = {
        {"--fov", "nan"},          {"--fov", "inf"},
        {"--exposure", "nan"},     {"--exposure", "-inf"},
        {"--exposure", "1e300"},   {"--patch-size", "nan"},
        {"--threads", "99999999"}, {"--threads", "0"},
        {"--refine-tol", "nan"},   {"--min-patch-size", "inf"},
        {"--tol", "nan"},          {"--sor", "nan"},
    };
    for (const auto& option : cases) {
        SCOPED_TRACE(option[0] + " " + option[1]);
        std::vector<std::string> args{"render", "builtin:cube", "--out", out, "--width",
                                      "8",      "--height",     "8"};
        args.insert(args.end(), option.begin(), option.end());
        const auto result = test::run_radiosity(args);
        EXPECT_EQ(result.status, 2) << result.err;
        EXPECT_NE(result.err.find(option[0]), std::string::npos) << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_FALSE(std::filesystem::exists(out));
    }
}

TEST(RenderOptionChecks, ValuesAtTheEdgesOfTheRangesAreAccepted) {
    test::TempDir dir;
    const std::string out = (dir.path() / "x.png").string();
    const auto result =
        test::run_radiosity({"render", "builtin:cube", "--out", out, "--width", "8", "--height", "8", "--fov",
                             "179", "--exposure", "-100", "--threads", "1"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_TRUE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace rad
