// `radiosity solve`: the JSON it writes (the schema of docs/architecture.md, emission = π Ke, values that
// conserve power), the summary it prints, and exit status 2 with the option named for bad input, leaving no
// file behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "test_support.hpp"

namespace rad {
namespace {

using nlohmann::json;
using test::run_radiosity;

json read_json(const std::string& path) {
    std::ifstream in(path);
    return json::parse(in);
}

std::array<double, 3> rgb(const json& v) {
    return {v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>()};
}

TEST(SolveCommand, WritesTheDesignSchemaForTheCube) {
    test::TempDir dir;
    const std::string out = (dir.path() / "cube.json").string();
    const auto result = run_radiosity({"solve", "builtin:cube", "--patch-size", "0.5", "--solver",
                                       "gauss-seidel", "--tol", "1e-9", "--json", out});
    ASSERT_EQ(result.status, 0) << result.err;
    for (const char* word : {"24 patches", "nonzeros", "steps", "residual", "seconds", "converged"}) {
        EXPECT_NE(result.out.find(word), std::string::npos) << word << " missing from:\n" << result.out;
    }
    const json doc = read_json(out);
    const json& patches = doc.at("patches");
    ASSERT_EQ(patches.size(), 24u);
    double area = 0.0, emitted = 0.0, leaving = 0.0;
    for (const json& p : patches) {
        for (const char* key : {"surface", "material", "area", "exposed", "centroid", "normal", "reflectance",
                                "emission", "radiosity"}) {
            ASSERT_TRUE(p.contains(key)) << key;
        }
        const double a = p.at("area").get<double>();
        const auto e = rgb(p.at("emission"));
        const auto b = rgb(p.at("radiosity"));
        const auto l = rgb(p.at("radiance"));
        // builtin:cube: the top emits Le = 1/π, so E = π Le = 1; every face reflects 0.5.
        const double expected_e = p.at("surface") == "top" ? 1.0 : 0.0;
        for (int c = 0; c < 3; ++c) {
            EXPECT_DOUBLE_EQ(e[c], expected_e);
            EXPECT_DOUBLE_EQ(rgb(p.at("reflectance"))[c], 0.5);
            EXPECT_GT(b[c], e[c]);
            EXPECT_NEAR(l[c], b[c] / std::numbers::pi, 1e-15);
        }
        EXPECT_EQ(p.at("material") == "emitter", p.at("surface") == "top");
        EXPECT_DOUBLE_EQ(a, 0.25);
        EXPECT_DOUBLE_EQ(p.at("exposed").get<double>(), 1.0);  // nothing covers a face of the empty cube
        area += a;
        emitted += a * e[0];
        leaving += a * b[0];
    }
    EXPECT_NEAR(area, 6.0, 1e-12);
    EXPECT_NEAR(emitted, 1.0, 1e-12);
    // Closed, uniform ρ: Σ A B = Σ A E / (1 − ρ), to within the sampled form factors' reciprocity error.
    EXPECT_NEAR(leaving, 2.0, 5e-3);

    const json& stats = doc.at("stats");
    EXPECT_EQ(stats.at("patches").get<int>(), 24);
    EXPECT_EQ(stats.at("nonzeros").get<int>(),
              24 * 20);  // each patch sees every patch of the other five faces
    EXPECT_GT(stats.at("iterations").get<int>(), 3);
    EXPECT_LE(stats.at("residual").get<double>(), 1e-9);
    EXPECT_TRUE(stats.at("converged").get<bool>());
    EXPECT_EQ(stats.at("status"), "converged");
    EXPECT_EQ(stats.at("solver"), "gauss-seidel");
    for (const char* key : {"mesh", "form_factors", "solve"})
        EXPECT_GE(stats.at("seconds").at(key).get<double>(), 0.0);
    EXPECT_GT(stats.at("peak_memory_bytes").get<double>(), 1e6);
    EXPECT_NEAR(rgb(stats.at("energy").at("emitted"))[1], 1.0, 1e-12);
    EXPECT_NEAR(rgb(stats.at("energy").at("absorbed"))[1], 1.0, 5e-3);
    // Nothing but the result is left in the folder.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
}

TEST(SolveCommand, CornellEmissionIsPiTimesKe) {
    test::TempDir dir;
    const std::string out = (dir.path() / "cornell.json").string();
    const auto result = run_radiosity({"solve", "--patch-size", "150", "--solver", "cg", "--json", out});
    ASSERT_EQ(result.status, 0) << result.err;
    std::size_t lights = 0;
    const json doc = read_json(out);
    for (const json& p : doc.at("patches")) {
        if (p.at("material") != "light") continue;
        ++lights;
        const auto e = rgb(p.at("emission"));
        EXPECT_DOUBLE_EQ(e[0], 17.0 * std::numbers::pi);
        EXPECT_DOUBLE_EQ(e[1], 12.0 * std::numbers::pi);
        EXPECT_DOUBLE_EQ(e[2], 4.0 * std::numbers::pi);
    }
    EXPECT_GT(lights, 0u);
}

TEST(SolveCommand, StepLimitIsReportedNotHidden) {
    test::TempDir dir;
    const std::string out = (dir.path() / "two.json").string();
    const auto result = run_radiosity(
        {"solve", "builtin:cube", "--patch-size", "1", "--bounces", "2", "--tol", "0", "--json", out});
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.err.find("step limit"), std::string::npos) << result.err;
    const json stats = read_json(out).at("stats");
    EXPECT_FALSE(stats.at("converged").get<bool>());
    EXPECT_EQ(stats.at("status"), "iteration limit");
    EXPECT_EQ(stats.at("iterations").get<int>(), 2);
}

// Hierarchical radiosity through the command line: the leaves are the JSON's patches, their power (area ×
// exposed share × radiosity) adds up to what the uniform solve of the same box gives (within 4 %; the
// library test holds the worst surface to 2.5 %), and the summary names the hierarchy.
TEST(SolveCommand, HierarchicalSolvesTheCornellBox) {
    test::TempDir dir;
    const std::string uniform_out = (dir.path() / "uniform.json").string();
    const std::string hierarchical_out = (dir.path() / "hierarchical.json").string();
    const auto uniform = run_radiosity({"solve", "--json", uniform_out});
    ASSERT_EQ(uniform.status, 0) << uniform.err;
    const auto hierarchical =
        run_radiosity({"solve", "--subdivision", "hierarchical", "--json", hierarchical_out});
    ASSERT_EQ(hierarchical.status, 0) << hierarchical.err;
    EXPECT_NE(hierarchical.out.find("transport: hierarchical"), std::string::npos) << hierarchical.out;
    EXPECT_NE(hierarchical.out.find("base_patches 197"), std::string::npos) << hierarchical.out;
    auto power = [](const json& doc) {
        double sum = 0.0;
        for (const json& p : doc.at("patches")) {
            const auto b = rgb(p.at("radiosity"));
            sum += p.at("area").get<double>() * p.at("exposed").get<double>() * (b[0] + b[1] + b[2]);
        }
        return sum;
    };
    const json u = read_json(uniform_out), h = read_json(hierarchical_out);
    EXPECT_GT(h.at("patches").size(), 197u);
    // "nonzeros" counts the links, as the transport reports them (it was 0: an empty form-factor matrix).
    const json& transport = h.at("stats").at("transport");
    EXPECT_EQ(transport.at("kind"), "hierarchical");
    EXPECT_EQ(transport.at("interaction_name"), "links");
    EXPECT_EQ(transport.at("elements").get<std::size_t>(), h.at("patches").size());
    EXPECT_GT(h.at("stats").at("nonzeros").get<std::size_t>(), h.at("patches").size());
    EXPECT_EQ(h.at("stats").at("nonzeros"), transport.at("interactions"));
    EXPECT_EQ(u.at("stats").at("nonzeros"), u.at("stats").at("transport").at("interactions"));
    EXPECT_EQ(transport.at("base_patches").get<int>(), 197);
    EXPECT_NEAR(power(h) / power(u), 1.0, 0.04);
    EXPECT_EQ(h.at("stats").at("converged"), true);
}

TEST(SolveCommand, BadOptionsExitTwoNamingTheOptionAndWriteNothing) {
    test::TempDir dir;
    const std::string out = (dir.path() / "x.json").string();
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"--solver", "newton"}, "--solver"},
        {{"--tol", "-1"}, "--tol"},
        {{"--sor", "2.5"}, "--sor"},
        {{"--bounces", "0"}, "--bounces"},
        {{"--initial", "zero"}, "--initial"},
        {{"--patch-size", "-3"}, "--patch-size"},
        {{"--subdivision", "fractal"}, "--subdivision"},
        {{"--refine-tol", "0"}, "--refine-tol"},
        {{"--subdivision", "hierarchical", "--solver", "cg"}, "--solver"},
    };
    for (const auto& [extra, option] : cases) {
        std::vector<std::string> args = {"solve", "builtin:cube", "--json", out};
        args.insert(args.end(), extra.begin(), extra.end());
        const auto result = run_radiosity(args);
        EXPECT_EQ(result.status, 2) << option << ": " << result.err;
        EXPECT_NE(result.err.find(option), std::string::npos) << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    }
    const auto missing_json = run_radiosity({"solve", "builtin:cube"});
    EXPECT_EQ(missing_json.status, 2);
    EXPECT_NE(missing_json.err.find("--json"), std::string::npos) << missing_json.err;
    const auto no_folder =
        run_radiosity({"solve", "builtin:cube", "--json", (dir.path() / "nope" / "x.json").string()});
    EXPECT_EQ(no_folder.status, 2);
    EXPECT_NE(no_folder.err.find("--json"), std::string::npos) << no_folder.err;
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace rad

namespace rad {
namespace {

// --save alone is enough (no --json), the file holds the solution the JSON reports, and a bad --save is
// refused before any work, writing nothing.
TEST(SolveCommand, SavesTheSolvedStateWithOrWithoutJson) {
    test::TempDir dir;
    const std::string saved = (dir.path() / "cube.radiosity").string();
    const auto alone = run_radiosity({"solve", "builtin:cube", "--patch-size", "0.5", "--save", saved});
    ASSERT_EQ(alone.status, 0) << alone.err;
    EXPECT_NE(alone.out.find("wrote " + saved), std::string::npos) << alone.out;
    const std::string bytes = test::read_file_text(saved);
    ASSERT_GT(bytes.size(), 32u);
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x89RADSOL\n", 8));

    const std::string json_path = (dir.path() / "cube.json").string();
    const std::string saved_too = (dir.path() / "both.radiosity").string();
    const auto both = run_radiosity(
        {"solve", "builtin:cube", "--patch-size", "0.5", "--json", json_path, "--save", saved_too});
    ASSERT_EQ(both.status, 0) << both.err;
    EXPECT_TRUE(std::filesystem::exists(json_path));
    // The same solve twice: the same bytes (the format holds no times or machine details).
    EXPECT_EQ(test::read_file_text(saved_too), bytes);

    test::TempDir empty;
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"solve", "builtin:cube", "--save", (empty.path() / "x.bin").string()}, "--save"},
        {{"solve", "builtin:cube", "--save", (empty.path() / "no" / "x.radiosity").string()}, "--save"},
        {{"solve", saved, "--save", (empty.path() / "x.radiosity").string()}, saved},
        {{"solve", "builtin:cube"}, "--save"},
    };
    for (const auto& [args, words] : cases) {
        const auto result = run_radiosity(args);
        EXPECT_EQ(result.status, 2) << args.back();
        EXPECT_NE(result.err.find(words), std::string::npos) << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    }
    EXPECT_TRUE(std::filesystem::is_empty(empty.path()));
}

}  // namespace
}  // namespace rad
