// The viewer's "copy --camera": the text it copies gives render the same camera back.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <sstream>
#include <string>

#include "cli/camera_option.hpp"

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

}  // namespace
}  // namespace rad
