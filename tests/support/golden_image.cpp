#include "golden_image.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/common.hpp>
#include <sstream>

#include "rad/io/image_file.hpp"

namespace rad::test {

namespace {

std::filesystem::path actual_folder() {
    return std::filesystem::path(RAD_GOLDEN_ACTUAL_DIR);
}

void keep_for_review(const std::string& name, const std::string& actual_path, const Image* difference) {
    std::filesystem::create_directories(actual_folder());
    std::filesystem::copy_file(actual_path, actual_folder() / (name + ".png"),
                               std::filesystem::copy_options::overwrite_existing);
    if (difference != nullptr) write_image((actual_folder() / (name + ".diff.png")).string(), *difference);
}

}  // namespace

GoldenResult compare_with_golden(const std::string& name, const std::string& actual_path,
                                 const GoldenTolerance& tolerance) {
    const std::filesystem::path golden_path = std::filesystem::path(RAD_GOLDEN_DIR) / (name + ".png");
    return compare_with_image(name, golden_path.string(), actual_path, tolerance);
}

GoldenResult compare_with_image(const std::string& name, const std::string& golden_path,
                                const std::string& actual_path, const GoldenTolerance& tolerance) {
    GoldenResult result;
    if (!std::filesystem::exists(golden_path)) {
        keep_for_review(name, actual_path, nullptr);
        result.message = "no golden image " + golden_path + "; the actual one is in " +
                         (actual_folder() / (name + ".png")).string() +
                         ": review it and run scripts/promote-golden.sh";
        return result;
    }
    const Image golden = read_image(golden_path);
    const Image actual = read_image(actual_path);
    if (golden.width != actual.width || golden.height != actual.height) {
        keep_for_review(name, actual_path, nullptr);
        result.message = "size " + std::to_string(actual.width) + "x" + std::to_string(actual.height) +
                         " differs from the golden " + std::to_string(golden.width) + "x" +
                         std::to_string(golden.height);
        return result;
    }
    Image difference = filled_image(actual.width, actual.height);
    double sum = 0.0;
    std::size_t outliers = 0;
    for (std::size_t i = 0; i < actual.pixels.size(); ++i) {
        const glm::vec3 d = glm::abs(actual.pixels[i] - golden.pixels[i]);
        difference.pixels[i] = d * 8.0f;  // amplified so small differences show
        sum += double(d.x) + d.y + d.z;
        if (std::max({d.x, d.y, d.z}) > tolerance.outlier_difference) ++outliers;
    }
    const double mean = sum / (3.0 * static_cast<double>(actual.pixels.size()));
    const double outlier_fraction = static_cast<double>(outliers) / static_cast<double>(actual.pixels.size());
    result.passed =
        mean <= tolerance.max_mean_difference && outlier_fraction <= tolerance.max_outlier_fraction;
    std::ostringstream message;
    message << name << ": mean difference " << mean * 255.0 << "/255 (allowed "
            << tolerance.max_mean_difference * 255.0 << "), " << outlier_fraction * 100.0
            << " % of pixels off by more than " << tolerance.outlier_difference * 255.0 << "/255 (allowed "
            << tolerance.max_outlier_fraction * 100.0 << " %)";
    if (!result.passed) {
        keep_for_review(name, actual_path, &difference);
        message << "; actual and difference images in " << actual_folder().string();
    }
    result.message = message.str();
    return result;
}

}  // namespace rad::test
