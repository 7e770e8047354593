// The screenshot key's file names: a second screenshot within the same second must not overwrite the first.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "test_support.hpp"
#include "viewer/window_screenshot.hpp"

namespace rad {
namespace {

TEST(ScreenshotPath, EveryScreenshotWithinASecondGetsANameOfItsOwn) {
    test::TempDir dir;
    std::set<std::string> names;
    for (int k = 0; k < 4; ++k) {
        const std::string path = timestamped_screenshot_path(dir.path());
        EXPECT_FALSE(std::filesystem::exists(path)) << path;
        EXPECT_EQ(std::filesystem::path(path).parent_path(), dir.path());
        EXPECT_TRUE(std::filesystem::path(path).filename().string().starts_with("radiosity-"));
        std::ofstream(path) << "png";
        names.insert(path);
    }
    EXPECT_EQ(names.size(), 4u);
}

}  // namespace
}  // namespace rad
