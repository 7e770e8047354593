// The viewer's "copy --camera": the text it copies gives render the same camera back.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "text/camera_text.hpp"

namespace rad {
namespace {

TEST(CameraOption, TheCopiedTextReadsBackAsTheSameCamera) {
    Camera camera;
    camera.eye = {278.123456, 273.5, -799.987654};
    camera.target = {277.9, 273.01, -798.99};
    camera.up = {0.01, 0.99995, 0.0};
    camera.fov_degrees = 39.3077;
    const std::string text = camera_option_text(camera);
    // "--camera ex,ey,ez,tx,ty,tz,ux,uy,uz --fov F"
    std::istringstream words(text);
    std::string option, numbers, fov_option;
    double fov = 0.0;
    words >> option >> numbers >> fov_option >> fov;
    ASSERT_EQ(option, "--camera") << text;
    ASSERT_EQ(fov_option, "--fov") << text;
    const Camera back = parse_camera(numbers, Camera{}, "--camera");
    const double size = glm::length(camera.eye);
    EXPECT_LT(glm::length(back.eye - camera.eye), 1e-6 * size) << text;
    EXPECT_LT(glm::length(back.target - camera.target), 1e-6 * size) << text;
    EXPECT_LT(glm::length(back.up - camera.up), 1e-6) << text;
    EXPECT_NEAR(fov, camera.fov_degrees, 1e-4) << text;
}

TEST(CameraOption, TheViewsFileHoldsOneCameraPerLineAsRenderReadsThem) {
    Camera a, b;
    a.eye = {1, 2, 3};
    a.target = {1, 2, 2};
    b.eye = {-4.5, 0.25, 7};
    b.target = {0, 0, 0};
    b.up = {0, 0, 1};
    const std::string text = cameras_file_text({a, b});
    std::istringstream lines(text);
    std::string line;
    std::vector<Camera> read;
    while (std::getline(lines, line)) {
        if (line.empty() || line[0] == '#') continue;
        read.push_back(parse_camera(line, Camera{}, "views"));
    }
    ASSERT_EQ(read.size(), 2u) << text;
    EXPECT_LT(glm::length(read[0].target - a.target), 1e-9);
    EXPECT_LT(glm::length(read[1].eye - b.eye), 1e-9);
    EXPECT_LT(glm::length(read[1].up - b.up), 1e-9);
}

}  // namespace
}  // namespace rad
