// `radiosity bench --quick`: the sweep runs end to end and what it reports holds together: every solver
// agrees with the converged solve of its own form factors, the direct solve exactly, the total errors
// against the path tracer are small on the Cornell box, and the table, CSV and plot say the same.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "test_support.hpp"

namespace rad {
namespace {

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::string> split(const std::string& line, char separator) {
    std::vector<std::string> fields;
    std::stringstream in(line);
    std::string field;
    while (std::getline(in, field, separator)) fields.push_back(field);
    return fields;
}

// The CSV as one map of column name to value per row.
std::vector<std::map<std::string, std::string>> read_csv(const std::filesystem::path& path) {
    std::stringstream in(read_text(path));
    std::string line;
    std::getline(in, line);
    const std::vector<std::string> header = split(line, ',');
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        const std::vector<std::string> fields = split(line, ',');
        EXPECT_EQ(fields.size(), header.size()) << line;
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < std::min(fields.size(), header.size()); ++i) row[header[i]] = fields[i];
        rows.push_back(row);
    }
    return rows;
}

double number(const std::map<std::string, std::string>& row, const std::string& column) {
    return std::stod(row.at(column));
}

std::size_t count(const std::string& text, const std::string& word) {
    std::size_t n = 0;
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
    return n;
}

class QuickBench : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        dir_ = new test::TempDir;
        result_ = new test::CommandResult(test::run_radiosity(
            {"bench", "builtin:cornell", "--quick", "--out-dir", (dir_->path() / "bench").string()}));
    }
    static void TearDownTestSuite() {
        delete result_;
        delete dir_;
    }
    static std::filesystem::path out(const std::string& name) { return dir_->path() / "bench" / name; }

    static test::TempDir* dir_;
    static test::CommandResult* result_;
};

test::TempDir* QuickBench::dir_ = nullptr;
test::CommandResult* QuickBench::result_ = nullptr;

TEST_F(QuickBench, RunsAndWritesTheTableTheCsvAndThePlot) {
    ASSERT_EQ(result_->status, 0) << result_->err;
    EXPECT_TRUE(std::filesystem::exists(out("bench.md")));
    EXPECT_TRUE(std::filesystem::exists(out("bench.csv")));
    EXPECT_TRUE(std::filesystem::exists(out("bench.svg")));
    EXPECT_EQ(read_text(out("bench.md")), result_->out.substr(0, read_text(out("bench.md")).size()));
}

TEST_F(QuickBench, CoversEverySolverEveryEstimatorAndTwoMeshes) {
    ASSERT_EQ(result_->status, 0) << result_->err;
    std::map<std::string, int> solvers, estimators, meshes;
    for (const auto& row : read_csv(out("bench.csv"))) {
        ++solvers[row.at("solver")];
        ++estimators[row.at("form_factors").substr(0, row.at("form_factors").find(' '))];
        ++meshes[row.at("patches")];
    }
    for (const char* solver : {"jacobi", "gauss-seidel", "cg", "southwell", "direct"}) {
        EXPECT_GT(solvers[solver], 0) << solver;
    }
    EXPECT_GT(estimators["hemisphere"], 0);
    EXPECT_GT(estimators["analytic"], 0);
    EXPECT_EQ(meshes.size(), 2u);
}

TEST_F(QuickBench, SolverErrorsAreThoseOfTheirSolvers) {
    ASSERT_EQ(result_->status, 0) << result_->err;
    for (const auto& row : read_csv(out("bench.csv"))) {
        const std::string solver = row.at("solver");
        const double error = number(row, "solver_error");
        EXPECT_EQ(row.at("converged"), "1") << solver;
        if (solver == "direct") {
            EXPECT_LT(error, 1e-9);  // the converged solve is the direct one at these sizes
        } else if (solver != "cg") {
            // A relative residual of 1e-5 in power leaves the solution about that far from the fixed point.
            EXPECT_LT(error, 1e-4) << solver;
        } else {
            // CG solves the reciprocity-symmetrized system, which estimated form factors make differ.
            EXPECT_LT(error, 0.05) << solver;
        }
    }
}

TEST_F(QuickBench, TotalAndImageErrorsAreSmallAndTheReferenceIsQuieterThanThem) {
    ASSERT_EQ(result_->status, 0) << result_->err;
    for (const auto& row : read_csv(out("bench.csv"))) {
        // Patch radiosity of the Cornell box against the path tracer, on meshes of 200 and 700 patches.
        EXPECT_GT(number(row, "total_error"), 0.0);
        EXPECT_LT(number(row, "total_error"), 0.05) << row.at("form_factors") << " " << row.at("solver");
        EXPECT_LT(number(row, "reference_noise"), number(row, "total_error"));
        // 64 × 64 pixels against a 16-path reference: coarse, but a wrong camera or image flip is ~100 %.
        EXPECT_LT(number(row, "image_error"), 0.3);
        EXPECT_NEAR(number(row, "total_s"),
                    number(row, "mesh_s") + number(row, "form_factors_s") + number(row, "solve_s"), 2e-6);
    }
}

TEST_F(QuickBench, ThePlotHasOneMarkerPerRunAndTheTableComparesWithThePathTracer) {
    ASSERT_EQ(result_->status, 0) << result_->err;
    const std::size_t runs = read_csv(out("bench.csv")).size();
    const std::string svg = read_text(out("bench.svg"));
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    // One marker per run, plus one per legend entry (series and the one scene).
    std::set<std::string> series;
    for (const auto& row : read_csv(out("bench.csv"))) {
        series.insert(row.at("solver") == "jacobi" ? row.at("form_factors") : row.at("solver"));
    }
    EXPECT_EQ(count(svg, "<title>"), runs + series.size() + 1);
    const std::string table = read_text(out("bench.md"));
    EXPECT_NE(table.find("path tracer spp to that error"), std::string::npos);
    EXPECT_NE(table.find("| builtin:cornell | 64² |"), std::string::npos);
}

TEST(BenchCommand, AnOutputFolderThatCannotBeMadeIsAnOptionError) {
    test::TempDir dir;
    const std::string file = dir.write("a-file", "not a folder\n");
    const test::CommandResult result =
        test::run_radiosity({"bench", "--quick", "--out-dir", file + "/bench"});
    EXPECT_EQ(result.status, 2);
    EXPECT_NE(result.err.find("--out-dir"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace rad
