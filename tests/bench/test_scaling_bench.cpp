// `radiosity bench --scaling --quick`: both furnaces solve both ways, every row holds the furnace's closed
// form, the figures per row hold together, and the table names the crossover.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>

#include "test_support.hpp"

namespace rad {
namespace {

std::vector<std::map<std::string, std::string>> read_csv(const std::string& text) {
    std::stringstream in(text);
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    for (std::stringstream h(line); std::getline(h, line, ',');) header.push_back(line);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        std::map<std::string, std::string> row;
        std::stringstream fields(line);
        std::string field;
        for (std::size_t i = 0; std::getline(fields, field, ','); ++i) {
            if (i < header.size()) row[header[i]] = field;
        }
        EXPECT_EQ(row.size(), header.size()) << line;
        rows.push_back(row);
    }
    return rows;
}

TEST(ScalingBench, SolvesEveryFurnaceBothWaysToItsClosedForm) {
    test::TempDir dir;
    const std::filesystem::path folder = dir.path() / "scaling";
    const test::CommandResult result =
        test::run_radiosity({"bench", "--scaling", "--quick", "--out-dir", folder.string()});
    ASSERT_EQ(result.status, 0) << result.err;
    const auto rows = read_csv(test::read_file_text(folder / "bench.csv"));
    ASSERT_EQ(rows.size(), 4u);  // 1k and 2k faces, clustered and uniform
    std::map<std::string, int> runs;
    for (const auto& row : rows) {
        ++runs[row.at("subdivision")];
        const std::string what = row.at("scene") + " " + row.at("subdivision");
        EXPECT_EQ(row.at("failed"), "0") << what;
        EXPECT_EQ(row.at("converged"), "1") << what;
        // B = E / (1 − ρ) = 2 on every face, to the solver's tolerance and the estimates' rounding.
        EXPECT_LT(std::stod(row.at("furnace_error")), 1e-3) << what;
        const double faces = std::stod(row.at("faces"));
        EXPECT_NEAR(faces, row.at("scene") == "builtin:furnace-1k" ? 1000.0 : 2000.0, 112.0) << what;
        EXPECT_GE(std::stod(row.at("patches")), faces) << what;  // a face is one patch or more
        EXPECT_GE(std::stod(row.at("elements")), std::stod(row.at("patches"))) << what;
        EXPECT_GT(std::stod(row.at("links")), 0.0) << what;
        EXPECT_EQ(std::stod(row.at("clusters")) > 0.0, row.at("subdivision") == "clustered") << what;
        EXPECT_GT(std::stod(row.at("peak_bytes")), 1e6) << what;
        EXPECT_NEAR(std::stod(row.at("total_s")),
                    std::stod(row.at("mesh_s")) + std::stod(row.at("build_s")) + std::stod(row.at("solve_s")),
                    2e-6)
            << what;
    }
    EXPECT_EQ(runs["clustered"], 2);
    EXPECT_EQ(runs["uniform"], 2);
    const std::string table = test::read_file_text(folder / "bench.md");
    EXPECT_NE(table.find("| builtin:furnace-2k | clustered |"), std::string::npos) << table;
    EXPECT_NE(table.find("Crossover: "), std::string::npos) << table;
    EXPECT_EQ(table, result.out.substr(0, table.size()));  // the table is what it printed
}

TEST(ScalingBench, BadSizesAndAScaleSceneAreRefused) {
    test::TempDir dir;
    const std::string out = (dir.path() / "s").string();
    // Every size is checked before any runs: nothing is written.
    test::CommandResult result =
        test::run_radiosity({"bench", "--scaling", "--scaling-faces", "1k,12x", "--out-dir", out});
    EXPECT_EQ(result.status, 2);
    EXPECT_NE(result.err.find("builtin:furnace-12x"), std::string::npos) << result.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "s" / "bench.md"));
    result = test::run_radiosity({"bench", "--scaling-faces", "1k", "--quick", "--out-dir", out});
    EXPECT_EQ(result.status, 2);
    EXPECT_NE(result.err.find("--scaling-faces"), std::string::npos) << result.err;
    result = test::run_radiosity({"bench", "builtin:cornell", "--scaling", "--quick", "--out-dir", out});
    EXPECT_EQ(result.status, 2);
    EXPECT_NE(result.err.find("builtin:cornell"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace rad
