// `radiosity measure`: the illuminance at the sensors of a points file as CSV, the same from a saved solution
// as from the solve that saved it, the daylight factor under an overcast sky, and bad points files refused
// with the file and line and nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace rad {
namespace {

using test::run_radiosity;

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        std::vector<std::string> cells;
        std::istringstream fields(line);
        std::string cell;
        while (std::getline(fields, cell, ',')) cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

constexpr const char* kPoints =
    "# two sensors at desk height and one on the ceiling\n"
    "278 85 279 0 1 0\n\n"
    "100 85 100 0 2 0  # a direction of any length\n"
    "278 548 279 0 -1 0\n";

TEST(MeasureCommand, WritesOneRowPerSensorInLuxAndTheSameFromTheSavedSolution) {
    const test::TempDir dir;
    const std::string points = dir.write("points.txt", kPoints);
    const std::string saved = (dir.path() / "box.radiosity").string();
    ASSERT_EQ(run_radiosity({"solve", "--patch-size", "60", "--save", saved}).status, 0);
    const auto fresh = run_radiosity({"measure", "--patch-size", "60", "--points", points});
    ASSERT_EQ(fresh.status, 0) << fresh.err;
    const auto rows = csv_rows(fresh.out);
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(fresh.out.substr(0, fresh.out.find('\n')),
              "x,y,z,dx,dy,dz,illuminance_lux,irradiance_r,irradiance_g,irradiance_b");
    for (std::size_t r = 1; r < rows.size(); ++r) {
        ASSERT_EQ(rows[r].size(), 10u);
        const double lux = std::stod(rows[r][6]);
        const double red = std::stod(rows[r][7]), green = std::stod(rows[r][8]), blue = std::stod(rows[r][9]);
        EXPECT_GT(lux, 0.0);
        EXPECT_NEAR(lux, 683.0 * (0.2126 * red + 0.7152 * green + 0.0722 * blue), 1e-6 * lux);
    }
    EXPECT_EQ(rows[2][4], "1");  // the direction normalized
    const std::string out = (dir.path() / "lux.csv").string();
    const auto from_file = run_radiosity({"measure", saved, "--points", points, "--out", out});
    ASSERT_EQ(from_file.status, 0) << from_file.err;
    EXPECT_EQ(test::read_file_text(out), fresh.out);  // no form factors, no solve: the same light
}

TEST(MeasureCommand, GivesTheDaylightFactorUnderAnOvercastSky) {
    const test::TempDir dir;
    const std::string points = dir.write("points.txt", kPoints);
    const auto result =
        run_radiosity({"measure", "--patch-size", "100", "--sky", "overcast,1", "--points", points});
    ASSERT_EQ(result.status, 0) << result.err;
    const auto rows = csv_rows(result.out);
    ASSERT_EQ(rows[0].back(), "daylight_factor_percent");
    for (std::size_t r = 1; r < rows.size(); ++r) {
        // The lamp's light counts too: the factor is the sensor's illuminance over the open sky's 7π/9 Lz.
        const double lux = std::stod(rows[r][6]);
        EXPECT_NEAR(std::stod(rows[r][10]), 100.0 * lux / (683.0 * 7.0 * std::numbers::pi / 9.0), 1e-6 * lux);
    }
}

TEST(MeasureCommand, RefusesBadPointsFilesNamingTheLineAndWritesNothing) {
    const test::TempDir dir;
    const std::string out = (dir.path() / "lux.csv").string();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"1 2 3 0 1 0\n1 2 3 0 0 0\n", ":2: the direction is zero"},
        {"1 2 3 0 1\n", ":1: 5 values"},
        {"\n# nothing\n1 2 nan 0 1 0\n", ":3: 'nan' is not a finite number"},
        {"1 2 3 0 1 0 7\n", ":1: 7 values"},
        {"# only comments\n", ": no sensors"},
    };
    for (const auto& [text, words] : cases) {
        const std::string points = dir.write("points.txt", text);
        const auto result =
            run_radiosity({"measure", "--patch-size", "150", "--points", points, "--out", out});
        EXPECT_EQ(result.status, 2) << text;
        EXPECT_NE(result.err.find(points + words), std::string::npos) << result.err;
        EXPECT_FALSE(std::filesystem::exists(out));
    }
    const std::string points = dir.write("points.txt", "1 2 3 0 1 0\n");
    const auto no_folder =
        run_radiosity({"measure", "--points", points, "--out", (dir.path() / "none" / "lux.csv").string()});
    EXPECT_EQ(no_folder.status, 2);
    EXPECT_NE(no_folder.err.find("--out"), std::string::npos) << no_folder.err;
    const auto missing = run_radiosity({"measure", "--points", (dir.path() / "none.txt").string()});
    EXPECT_EQ(missing.status, 2);
    EXPECT_NE(missing.err.find("no such file"), std::string::npos);
}

}  // namespace
}  // namespace rad
