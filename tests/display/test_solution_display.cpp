// The display builder over a Solution: it draws any solution of its scene and refuses one that is not, before
// any ray is traced.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "rad/display/solution_display.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "solved_scene.hpp"

namespace rad {
namespace {

// The Cornell box solved by uniform transport, as a Solution.
Solution cornell_solution(const test::SolvedScene& solved) {
    const Transport& t = *solved.system.transport;
    Solution solution;
    solution.settings.patch_size = 100.0;
    solution.settings.subdivision = "uniform";
    solution.elements = std::make_shared<const PatchMesh>(*solved.system.patches);
    solution.area = t.area;
    solution.reflectance = t.reflectance;
    solution.emission = t.emission;
    solution.direct.assign(solution.size(), glm::dvec3(0.0));
    solution.radiosity = solved.radiosity;
    solution.shown_radiosity = solved.radiosity;
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
    EXPECT_FALSE(display.direct.vertex.empty());  // smooth mode traced the lamp's light at the vertices
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
