// The golden-image check itself: it passes the golden image, fails a changed one beyond the tolerance, and
// leaves the actual and difference images for review.
#include <gtest/gtest.h>

#include <filesystem>

#include "golden_image.hpp"
#include "rad/io/image_file.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

const std::string kGolden = "cornell_256";

std::filesystem::path golden_path() {
    return std::filesystem::path(RAD_GOLDEN_DIR) / (kGolden + ".png");
}

TEST(GoldenImage, TheGoldenImagePassesAgainstItself) {
    const test::GoldenResult result = test::compare_with_golden(kGolden, golden_path().string());
    EXPECT_TRUE(result.passed) << result.message;
}

TEST(GoldenImage, AChangedImageFailsAndIsKeptForReview) {
    test::TempDir dir;
    Image image = read_image(golden_path().string());
    // Brighten a 40 × 40 square (2.4 % of the pixels) by a third of the range: beyond the outlier allowance.
    for (int y = 100; y < 140; ++y)
        for (int x = 100; x < 140; ++x) image.at(x, y) += glm::vec3(0.34f);
    const std::string changed = (dir.path() / "changed.png").string();
    write_image(changed, image);  // the values are already sRGB-encoded: writing them linear keeps them
    const std::string name = "golden_self_test";
    const test::GoldenResult result = test::compare_with_image(name, golden_path().string(), changed);
    EXPECT_FALSE(result.passed) << result.message;
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(RAD_GOLDEN_ACTUAL_DIR) / (name + ".png")));
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(RAD_GOLDEN_ACTUAL_DIR) / (name + ".diff.png")));
}

TEST(GoldenImage, AMissingGoldenImageFailsWithAHint) {
    test::TempDir dir;
    const test::GoldenResult result = test::compare_with_golden("no_such_golden", golden_path().string());
    EXPECT_FALSE(result.passed);
    EXPECT_NE(result.message.find("promote-golden"), std::string::npos) << result.message;
}

}  // namespace
}  // namespace rad
