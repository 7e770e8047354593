// `radiosity bench --quick`: the sweep runs end to end and what it reports holds together: every solver
// agrees with the converged solve of its own form factors, the direct solve exactly, the total errors
// against the path tracer are small on the Cornell box, and the table, CSV and plot say the same.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "test_support.hpp"

namespace rad {
namespace {

std::vector<std::string> split(const std::string& line, char separator) {
    std::vector<std::string> fields;
    std::stringstream in(line);
    std::string field;
    while (std::getline(in, field, separator)) fields.push_back(field);
    return fields;
}

// The CSV as one map of column name to value per row.
std::vector<std::map<std::string, std::string>> read_csv(const std::filesystem::path& path) {
    std::stringstream in(test::read_file_text(path));
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

// The quick sweep, run once (under ctest each test is a process of its own, and the sweep takes half a
// minute under the sanitizers), then checked part by part.
struct QuickBenchOutput {
    std::filesystem::path folder;
    std::vector<std::map<std::string, std::string>> rows;
    std::string table, svg;
};

void check_coverage(const QuickBenchOutput& out) {
    std::map<std::string, int> solvers, estimators, meshes, subdivisions;
    for (const auto& row : out.rows) {
        ++subdivisions[row.at("subdivision")];
        if (row.at("subdivision") != "uniform") continue;
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
    EXPECT_GT(subdivisions["adaptive"], 0);
    EXPECT_GT(subdivisions["hierarchical"], 0);
}

// Uniform rows only: a hierarchical run has no converged direct solve or patch reference of its leaves.
bool uniform(const std::map<std::string, std::string>& row) {
    return row.at("subdivision") == "uniform";
}

void check_solver_errors(const QuickBenchOutput& out) {
    for (const auto& row : out.rows) {
        if (!uniform(row)) continue;
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

void check_total_and_image_errors(const QuickBenchOutput& out) {
    for (const auto& row : out.rows) {
        // 64 × 64 pixels against a 16-path reference: coarse, but a wrong camera or image flip is ~100 %.
        EXPECT_LT(number(row, "image_error"), 0.3) << row.at("subdivision");
        EXPECT_GT(number(row, "links"), 0.0);
        if (!uniform(row)) continue;
        // Patch radiosity of the Cornell box against the path tracer, on meshes of 200 and 700 patches.
        EXPECT_GT(number(row, "total_error"), 0.0);
        EXPECT_LT(number(row, "total_error"), 0.05) << row.at("form_factors") << " " << row.at("solver");
        EXPECT_LT(number(row, "reference_noise"), number(row, "total_error"));
        EXPECT_NEAR(number(row, "total_s"),
                    number(row, "mesh_s") + number(row, "form_factors_s") + number(row, "solve_s"), 2e-6);
    }
}

void check_plot_and_table(const QuickBenchOutput& out) {
    EXPECT_EQ(out.svg.rfind("<svg", 0), 0u);
    // One marker per run, plus one per legend entry (the series and the one scene).
    std::set<std::string> series;
    std::size_t plotted = 0;
    for (const auto& row : out.rows) {
        if (!uniform(row)) continue;  // the plot is of total error, which hierarchical runs do not have
        ++plotted;
        series.insert(row.at("solver") == "jacobi" ? row.at("form_factors") : row.at("solver"));
    }
    EXPECT_EQ(count(out.svg, "<title>"), plotted + series.size() + 1);
    EXPECT_NE(out.table.find("path tracer spp to that error"), std::string::npos);
    EXPECT_NE(out.table.find("| builtin:cornell | 64² |"), std::string::npos);
}

TEST(QuickBench, RunsAndReportsWhatHoldsTogether) {
    test::TempDir dir;
    QuickBenchOutput out;
    out.folder = dir.path() / "bench";
    const test::CommandResult result =
        test::run_radiosity({"bench", "builtin:cornell", "--quick", "--out-dir", out.folder.string()});
    ASSERT_EQ(result.status, 0) << result.err;
    for (const char* name :
         {"bench.md", "bench.csv", "bench.svg", "cornell-radiosity.pfm", "cornell-path-traced.pfm"}) {
        EXPECT_TRUE(std::filesystem::exists(out.folder / name)) << name;
    }
    out.rows = read_csv(out.folder / "bench.csv");
    out.table = test::read_file_text(out.folder / "bench.md");
    out.svg = test::read_file_text(out.folder / "bench.svg");
    EXPECT_EQ(out.table, result.out.substr(0, out.table.size()));  // the table is what it printed
    {
        SCOPED_TRACE("every solver, both estimators, two meshes");
        check_coverage(out);
    }
    {
        SCOPED_TRACE("solver errors");
        check_solver_errors(out);
    }
    {
        SCOPED_TRACE("total and image errors");
        check_total_and_image_errors(out);
    }
    {
        SCOPED_TRACE("plot and table");
        check_plot_and_table(out);
    }
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
