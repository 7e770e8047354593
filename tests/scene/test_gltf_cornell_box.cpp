// assets/cornell_box.gltf (written by scripts/obj_to_gltf.py from assets/cornell_box.obj) is the same scene
// as the OBJ: the same surfaces, areas and materials, and, solved the same way, the same light.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/scene_transport.hpp"

namespace rad {
namespace {

const std::string kAssets = std::string(RAD_SOURCE_DIR) + "/assets/";
// Relative agreement of the solved light: glTF positions are 32-bit floats, the OBJ's doubles; measured
// below 1e-6.
constexpr double kTolerance = 1e-5;

// Per surface name: area-weighted radiosity power Σ A B, and the energy balance, solved with jacobi over
// uniform patches.
struct Solution {
    std::map<std::string, glm::dvec3> power;
    EnergyBalance balance;
};

Solution solve(const Scene& scene) {
    const PatchMesh patches = build_patches(scene, MeshingOptions{.patch_size = 60.0});
    TransportSettings settings;
    settings.subdivision = Subdivision::uniform;
    const SceneTransport system = build_scene_transport(scene, patches, settings);
    auto solver = make_solver(SolverMethod::jacobi, *system.transport, SolverOptions{});
    while (!solver->report().finished()) solver->step();
    Solution s;
    const PatchMesh& elements = *system.patches;
    for (std::size_t i = 0; i < elements.size(); ++i)
        s.power[scene.surfaces[elements.patches[i].surface].name] +=
            system.transport->area[i] * solver->solution()[i];
    s.balance = energy_balance(*system.transport, solver->solution());
    return s;
}

TEST(GltfCornellBox, HasTheObjSurfacesAndMaterials) {
    const Scene obj = load_scene(kAssets + "cornell_box.obj");
    const Scene gltf = load_scene(kAssets + "cornell_box.gltf");
    ASSERT_EQ(gltf.surfaces.size(), obj.surfaces.size());
    for (std::size_t i = 0; i < obj.surfaces.size(); ++i) {
        const Surface& a = obj.surfaces[i];
        const Surface& b = gltf.surfaces[i];
        SCOPED_TRACE(a.name);
        EXPECT_EQ(b.name, a.name);
        EXPECT_EQ(b.material.name, a.material.name);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(b.material.reflectance[c], a.material.reflectance[c], 1e-12);
            EXPECT_NEAR(b.material.emission[c], a.material.emission[c], 1e-12);
        }
        // glTF positions are 32-bit floats: millimetres to about 3e-5.
        EXPECT_NEAR(surface_area(b.mesh), surface_area(a.mesh), 1e-6 * surface_area(a.mesh));
    }
    EXPECT_NEAR(total_area(gltf), total_area(obj), 1e-6 * total_area(obj));
    EXPECT_EQ(count_patches(gltf, default_patch_size(gltf)), count_patches(obj, default_patch_size(obj)));
    // The same warning: the light moved below the ceiling it overlaps.
    EXPECT_EQ(gltf.warnings.size(), obj.warnings.size());
}

// The OBJ's quads are the glTF's pairs of triangles, merged back into quads by the loader, so both are cut
// into the same patches and solve to the same light, but for the positions' rounding to floats.
TEST(GltfCornellBox, SolvesToTheObjLight) {
    const Solution obj = solve(load_scene(kAssets + "cornell_box.obj"));
    const Solution gltf = solve(load_scene(kAssets + "cornell_box.gltf"));
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(gltf.balance.emitted[c], obj.balance.emitted[c], 1e-6 * obj.balance.emitted[c]);
        EXPECT_NEAR(gltf.balance.absorbed[c], obj.balance.absorbed[c], kTolerance * obj.balance.absorbed[c]);
    }
    for (const auto& [name, power] : obj.power) {
        SCOPED_TRACE(name);
        ASSERT_TRUE(gltf.power.contains(name));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(gltf.power.at(name)[c], power[c], kTolerance * power[c]);
    }
}

}  // namespace
}  // namespace rad
