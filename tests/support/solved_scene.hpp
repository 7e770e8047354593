#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"
#include "rad/solve/solution.hpp"
#include "rad/transport/scene_transport.hpp"

namespace rad::test {

// A scene solved by jacobi to a tight tolerance, kept with everything its solution refers to.
struct SolvedScene {
    Scene scene;
    PatchMesh patches;
    SceneTransport system;
    std::vector<glm::dvec3> radiosity;  // per element of system.transport
};

// patch_size 0 takes the scene's default; seed is the form factors'.
std::unique_ptr<SolvedScene> solve_scene(Scene scene, Subdivision subdivision, double patch_size = 0.0,
                                         std::uint64_t seed = 1);
// The same with all the transport's settings given.
std::unique_ptr<SolvedScene> solve_scene(Scene scene, const TransportSettings& settings,
                                         double patch_size = 0.0);

// The solved scene as a Solution: its elements, their arrays, ρ H_d from the transport's gather of the
// emission, and the settings of its method with `patch_size` (the base patches' size) and `seed`.
Solution solution_of(const SolvedScene& solved, double patch_size, std::uint64_t seed = 1);

}  // namespace rad::test
