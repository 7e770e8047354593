// Clustering: the furnace of many small faces (a closed room of tessellated balls) at several sizes, with
// more faces than links would allow pairwise; links that grow about linearly with the faces; and the
// report.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "rad/solve/solver.hpp"
#include "rad/transport/scene_transport.hpp"
#include "sphere_room.hpp"

namespace rad {
namespace {

struct Furnace {
    std::size_t faces = 0;
    std::size_t links = 0;
    double worst = 0.0;    // largest |B / expected − 1| over the elements
    double balance = 0.0;  // (absorbed + escaped) / emitted
};

Furnace furnace(int spheres, int segments) {
    const double rho = 0.5, e = 1.0;
    const Scene scene = test::sphere_room(spheres, segments, rho, e);
    const PatchMesh base = build_patches(scene, MeshingOptions{0.25});
    TransportSettings settings;
    settings.subdivision = Subdivision::clustered;
    const SceneTransport built = build_scene_transport(scene, base, settings);
    const Transport& transport = *built.transport;
    SolverOptions options;
    options.tolerance = 1e-9;
    auto solver = make_solver(SolverMethod::jacobi, transport, options);
    EXPECT_TRUE(run_to_end(*solver).converged()) << solver->status_message();
    Furnace out;
    out.faces = base.size();
    out.links = transport.report().interactions;
    const double expected = e / (1.0 - rho);
    for (const glm::dvec3& b : solver->solution())
        out.worst = std::max(out.worst, std::abs(b.x / expected - 1.0));
    const EnergyBalance balance = energy_balance(transport, solver->solution());
    const auto total = [](const glm::dvec3& v) { return v.x + v.y + v.z; };
    out.balance = (total(balance.absorbed) + total(balance.escaped)) / total(balance.emitted);
    std::printf("[ figures ] %d³ balls of %d segments: %zu faces, %zu links, worst %.2e, balance %.6f\n",
                spheres, segments, out.faces, out.links, out.worst, out.balance);
    return out;
}

TEST(Clustered, SphereRoomFurnaceGivesEOverOneMinusRhoAtEverySize) {
    for (const auto& [spheres, segments] : {std::pair{2, 8}, std::pair{3, 12}, std::pair{4, 16}}) {
        const Furnace f = furnace(spheres, segments);
        EXPECT_LT(f.worst, 5e-3);
        EXPECT_NEAR(f.balance, 1.0, 5e-3);
    }
}

// The faces grow 32-fold from the smallest room to the largest; all pairs would grow a thousandfold, the
// links must grow far less than that.
TEST(Clustered, LinksGrowFarSlowerThanPairs) {
    const Furnace small = furnace(2, 8), large = furnace(4, 16);
    const double faces = static_cast<double>(large.faces) / static_cast<double>(small.faces);
    const double links = static_cast<double>(large.links) / static_cast<double>(small.links);
    EXPECT_GT(faces, 10.0);
    EXPECT_LT(links, 4.0 * faces);
    EXPECT_LT(large.links, large.faces * large.faces / 20);
}

}  // namespace
}  // namespace rad
