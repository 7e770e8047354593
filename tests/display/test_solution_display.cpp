// The display builder over a Solution: it draws any solution of its scene and refuses one that is not, before
// any ray is traced; another solution of the same elements and emitters replaces only the display's light,
// to the same values a new build gives.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "rad/display/solution_display.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/transport_methods.hpp"
#include "solved_scene.hpp"

namespace rad {
namespace {

// The Cornell box solved by uniform transport, as a Solution.
Solution cornell_solution(const test::SolvedScene& solved) {
    Solution solution = test::solution_of(solved, 100.0);
    solution.direct.assign(solution.size(), glm::dvec3(0.0));
    return solution;
}

void expect_refused(const Scene& scene, const Solution& solution, const std::string& what) {
    try {
        build_solution_display(scene, solution, {});
        FAIL() << "drew a solution that does not fit: " << what;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
}

TEST(SolutionDisplay, DrawsASolutionOfItsScene) {
    const auto solved = test::solve_scene(make_cornell_box(), Subdivision::uniform, 100.0);
    const Solution solution = cornell_solution(*solved);
    const DisplayMesh display = build_solution_display(solved->scene, solution, {});
    EXPECT_EQ(display.solution_patch_count(), solution.size());
    EXPECT_FALSE(display.light.direct.vertex.empty());  // smooth mode traced the lamp's light at the vertices
}

// The same elements with other reflectances and another radiosity (what an edit of the materials' colours
// or of the sky gives): the traces still hold.
Solution recoloured(Solution solution) {
    for (std::size_t q = 0; q < solution.size(); ++q) {
        solution.reflectance[q] *= glm::dvec3(0.5, 0.8, 1.0);
        solution.direct[q] *= glm::dvec3(0.5, 0.8, 1.0);
        solution.emission[q] += glm::dvec3(0.01, 0.02, 0.03);  // a sky's ρ H_out
        solution.shown_radiosity[q] = 0.7 * solution.radiosity[q] + solution.emission[q];
    }
    return solution;
}

TEST(SolutionDisplay, AnotherSolutionOfTheSameElementsReplacesOnlyTheLight) {
    for (const TransportMethod& method : transport_methods()) {
        SCOPED_TRACE(std::string(method.name));
        const double base = 100.0 * method.base_patch_scale;
        const auto solved = test::solve_scene(make_cornell_box(), method.id, base);
        const Solution first = test::solution_of(*solved, base, 7);
        const Solution second = recoloured(first);
        DisplayMesh display = build_solution_display(solved->scene, first, {});
        ASSERT_FALSE(display.light.direct.vertex.empty());
        const DisplayMesh fresh = build_solution_display(solved->scene, second, {});
        ASSERT_TRUE(display_traces_fit(display, solved->scene, second));
        const std::vector<glm::vec3> before = vertex_radiance(display, second.shown_radiosity);
        relight_display(display, solved->scene, second);
        EXPECT_EQ(display.positions, fresh.positions);
        const std::vector<glm::vec3> relit = vertex_radiance(display, second.shown_radiosity);
        const std::vector<glm::vec3> built = vertex_radiance(fresh, second.shown_radiosity);
        ASSERT_EQ(relit.size(), built.size());
        double worst = 0.0, changed = 0.0;
        for (std::size_t v = 0; v < relit.size(); ++v) {
            worst = std::max(worst, static_cast<double>(glm::length(relit[v] - built[v])));
            changed = std::max(changed, static_cast<double>(glm::length(relit[v] - before[v])));
        }
        EXPECT_LT(worst, 1e-5);    // the same values, to float rounding
        EXPECT_GT(changed, 1e-3);  // and the light did change
    }
}

TEST(SolutionDisplay, RefusesToRelightWhenTheEmittersChanged) {
    const TransportMethod& method = transport_method(Subdivision::uniform);
    const auto solved = test::solve_scene(make_cornell_box(), method.id, 100.0);
    const Solution solution = test::solution_of(*solved, 100.0, 7);
    DisplayMesh display = build_solution_display(solved->scene, solution, {});
    Scene brighter = solved->scene;
    for (Surface& surface : brighter.surfaces)
        if (surface.material.emits()) surface.material.emission *= 2.0;
    EXPECT_FALSE(display_traces_fit(display, brighter, solution));
    EXPECT_THROW(relight_display(display, brighter, solution), std::invalid_argument);
    // A solution of other elements (a finer mesh) does not fit either.
    const auto finer = test::solve_scene(make_cornell_box(), method.id, 50.0);
    EXPECT_FALSE(display_traces_fit(display, finer->scene, test::solution_of(*finer, 50.0, 7)));
}

TEST(SolutionDisplay, RefusesASolutionOfAnotherScene) {
    const auto solved = test::solve_scene(make_cornell_box(), Subdivision::uniform, 100.0);
    const Solution solution = cornell_solution(*solved);
    // Fewer surfaces than the elements name.
    expect_refused(make_cube(), solution, "does not fit the scene");
    // The same surfaces and faces, moved: every element lies off its face's plane.
    Scene moved = make_cornell_box();
    for (Surface& surface : moved.surfaces)
        for (auto v : surface.mesh.vertices()) surface.mesh.point(v) += SurfaceMesh::Point(30.0, 40.0, 50.0);
    expect_refused(moved, solution, "is not on face");
}

TEST(SolutionDisplay, RefusesArraysOfAnotherSize) {
    const auto solved = test::solve_scene(make_cornell_box(), Subdivision::uniform, 100.0);
    Solution short_area = cornell_solution(*solved);
    short_area.area.pop_back();
    expect_refused(solved->scene, short_area, "areas");
    Solution no_radiosity = cornell_solution(*solved);
    no_radiosity.shown_radiosity.clear();
    expect_refused(solved->scene, no_radiosity, "shown radiosities");
    expect_refused(solved->scene, Solution{}, "no elements");
}

}  // namespace
}  // namespace rad
