// Image files: linear formats keep radiance exactly, PNG applies exposure and the sRGB curve, and a write
// either leaves the whole file or nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "rad/io/image_file.hpp"
#include "rad/util/error.hpp"
#include "rad/util/srgb.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

Image gradient(int w, int h) {
    Image image{w, h, {}};
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) image.pixels.emplace_back(0.01f * x, 0.02f * y, 123.5f);
    }
    return image;
}

TEST(ImageIo, PfmKeepsRadianceExactlyAndTopRowFirst) {
    test::TempDir dir;
    const std::string path = (dir.path() / "g.pfm").string();
    const Image image = gradient(7, 5);
    write_image(path, image);
    const Image back = read_image(path);
    ASSERT_EQ(back.width, 7);
    ASSERT_EQ(back.height, 5);
    EXPECT_EQ(back.pixels, image.pixels);
}

TEST(ImageIo, PngAppliesExposureAndSrgb) {
    test::TempDir dir;
    const std::string path = (dir.path() / "g.png").string();
    // 0.05 at exposure +2 is 0.2 linear, 0.4845 in sRGB: 124 of 255.
    Image image{2, 1, {glm::vec3(0.05f), glm::vec3(10.0f)}};
    write_image(path, image, 2.0);
    const Image back = read_image(path);
    EXPECT_EQ(std::lround(back.pixels[0].x * 255), 124);
    EXPECT_EQ(std::lround(back.pixels[1].x * 255), 255);  // clamped
    EXPECT_NEAR(srgb_encode(0.2f), 0.4845f, 1e-4f);
    EXPECT_NEAR(srgb_encode(0.002f), 0.02584f, 1e-5f);
}

TEST(ImageIo, ExrIsWritten) {
    test::TempDir dir;
    const std::string path = (dir.path() / "g.exr").string();
    write_image(path, gradient(4, 3));
    EXPECT_GT(std::filesystem::file_size(path), 0u);
}

TEST(ImageIo, BadTargetsLeaveNothingBehind) {
    test::TempDir dir;
    EXPECT_THROW(write_image((dir.path() / "x.jpg").string(), gradient(2, 2)), InputError);
    EXPECT_THROW(write_image((dir.path() / "missing" / "x.png").string(), gradient(2, 2)), InputError);
    write_image((dir.path() / "ok.pfm").string(), gradient(2, 2));
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
        ++files;
        EXPECT_EQ(entry.path().filename(), "ok.pfm");  // no temporary left
    }
    EXPECT_EQ(files, 1u);
}

// A forged header does not make the reader allocate what it declares.
TEST(ImageIo, APfmHeaderLargerThanItsFileIsRefused) {
    test::TempDir dir;
    const std::string path = dir.write("forged.pfm", "PF\n100000 100000\n-1.0\n" + std::string(48, '\0'));
    try {
        read_image(path);
        ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("100000x100000 pixels, more than the file holds"),
                  std::string::npos)
            << e.what();
    }
    const std::string whole = dir.write("two.pfm", "PF\n2 1\n-1.0\n" + std::string(24, '\0'));
    EXPECT_EQ(read_image(whole).pixels.size(), 2u);
}

}  // namespace
}  // namespace rad
