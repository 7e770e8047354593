// Closed solids among a soup's polygons (scene/solid_components), which faces are cut at.
#include <gtest/gtest.h>

#include <vector>

#include "scene/solid_components.hpp"

namespace rad {
namespace {

using Polygons = std::vector<std::vector<glm::dvec3>>;

// A box's six faces, outwards (or inwards), each with corners of its own.
void add_box(Polygons& out, const glm::dvec3& lo, const glm::dvec3& hi, bool inwards = false) {
    const auto q = [&](glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
        out.push_back(inwards ? std::vector<glm::dvec3>{d, c, b, a} : std::vector<glm::dvec3>{a, b, c, d});
    };
    const double x0 = lo.x, y0 = lo.y, z0 = lo.z, x1 = hi.x, y1 = hi.y, z1 = hi.z;
    q({x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1});
    q({x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0});
    q({x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0});
    q({x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1});
    q({x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}, {x1, y0, z0});
    q({x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1});
}

TEST(SolidComponents, AnOutwardBoxIsASolidAnInwardOneAHollowAnOpenOneNeither) {
    Polygons p;
    add_box(p, glm::dvec3(0.0), glm::dvec3(1.0));
    add_box(p, glm::dvec3(2.0), glm::dvec3(3.0), true);
    add_box(p, glm::dvec3(4.0), glm::dvec3(5.0));
    p.pop_back();  // the third box loses a face
    const Solids s = find_solids(p, std::vector<std::uint32_t>(p.size(), 0));
    ASSERT_EQ(s.polygons.size(), 1u);
    for (std::uint32_t i = 0; i < 6; ++i) EXPECT_EQ(s.of_polygon[i], 0u);
    for (std::uint32_t i = 6; i < p.size(); ++i) EXPECT_EQ(s.of_polygon[i], kNoSolid);
}

// Two slabs of one group touching face to face share edges where four faces meet: each face closes with its
// neighbour behind it, so they are two solids, not one open set.
TEST(SolidComponents, SlabsSharingEdgesAreTwoSolids) {
    Polygons p;
    add_box(p, glm::dvec3(0.0), glm::dvec3(1.0, 1.0, 0.1));
    add_box(p, glm::dvec3(0.0, 0.0, 0.1), glm::dvec3(1.0, 1.0, 0.2));
    const Solids s = find_solids(p, std::vector<std::uint32_t>(p.size(), 0));
    ASSERT_EQ(s.polygons.size(), 2u);
    EXPECT_EQ(s.polygons[0].size(), 6u);
    EXPECT_EQ(s.polygons[1].size(), 6u);
    EXPECT_NE(s.of_polygon[0], s.of_polygon[6]);
}

// Overlapping slabs of different groups share coplanar faces along an edge: told apart by their groups.
TEST(SolidComponents, OverlappingSlabsOfTwoGroupsAreTwoSolids) {
    Polygons p;
    add_box(p, glm::dvec3(-0.1), glm::dvec3(1.1, 0.0, 1.1));
    add_box(p, glm::dvec3(-0.1), glm::dvec3(0.0, 1.1, 1.1));
    std::vector<std::uint32_t> groups(12, 0);
    for (int i = 6; i < 12; ++i) groups[i] = 1;
    const Solids s = find_solids(p, groups);
    EXPECT_EQ(s.polygons.size(), 2u);
}

}  // namespace
}  // namespace rad
