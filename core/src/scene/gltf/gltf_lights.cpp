#include "scene/gltf/gltf_lights.hpp"

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>

#include "rad/util/error.hpp"
#include "scene/scene_limits.hpp"

namespace rad {

namespace {

[[noreturn]] void refuse(const GltfFile& file, const std::string& what) {
    throw InputError(gltf_message(file, what));
}

using Triangle = std::array<int, 3>;

// The regular icosahedron's corners (on the unit sphere once normalized) and faces, counter-clockwise from
// outside.
void icosahedron(std::vector<glm::dvec3>& corners, std::vector<Triangle>& faces) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    corners = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
               {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (glm::dvec3& c : corners) c = glm::normalize(c);
    faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
}

// Each face split into four at its edges' midpoints, pushed out to the unit sphere.
void subdivide(std::vector<glm::dvec3>& corners, std::vector<Triangle>& faces) {
    std::map<std::pair<int, int>, int> midpoint;
    const auto middle = [&](int a, int b) {
        const auto key = std::minmax(a, b);
        if (const auto it = midpoint.find(key); it != midpoint.end()) return it->second;
        corners.push_back(
            glm::normalize(corners[static_cast<std::size_t>(a)] + corners[static_cast<std::size_t>(b)]));
        return midpoint[key] = static_cast<int>(corners.size() - 1);
    };
    std::vector<Triangle> finer;
    for (const Triangle& f : faces) {
        const int ab = middle(f[0], f[1]), bc = middle(f[1], f[2]), ca = middle(f[2], f[0]);
        finer.insert(finer.end(), {Triangle{f[0], ab, ca}, Triangle{f[1], bc, ab}, Triangle{f[2], ca, bc},
                                   Triangle{ab, bc, ca}});
    }
    faces = std::move(finer);
}

BoundingBox soup_bounds(const PolygonSoup& soup) {
    BoundingBox box;
    for (const glm::dvec3& p : soup.positions) box.extend(p);
    return box;
}

struct PunctualLight {
    int light = -1;
    glm::dvec3 position{0.0};
    glm::dvec3 toward{0.0, 0.0, 1.0};  // the node's +z in the world: a light shines along its -z
};

// The lights the placed nodes carry (KHR_lights_punctual on a node: {"light": N}).
std::vector<PunctualLight> placed_lights(const GltfFile& file, const std::vector<PlacedNode>& nodes) {
    std::vector<PunctualLight> lights;
    for (const PlacedNode& placed : nodes) {
        const auto& extensions = file.model.nodes[static_cast<std::size_t>(placed.node)].extensions;
        const auto ext = extensions.find("KHR_lights_punctual");
        if (ext == extensions.end() || !ext->second.Has("light")) continue;
        const tinygltf::Value& index = ext->second.Get("light");
        const std::string where = "nodes[" + std::to_string(placed.node) + "]";
        if (!index.IsInt()) refuse(file, where + ": its light is not an index");
        const int light = index.GetNumberAsInt();
        if (light < 0 || static_cast<std::size_t>(light) >= file.model.lights.size())
            refuse(file, where + ": light " + std::to_string(light) + " does not exist (" +
                             std::to_string(file.model.lights.size()) + " in the file)");
        const glm::dvec3 position = glm::dvec3(placed.world[3]) / placed.world[3][3];
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(position[c]) || std::abs(position[c]) > kMaxCoordinate)
                refuse(file, where + ": its light lies beyond 1e30 (or not at a finite place)");
        const glm::dvec3 z = glm::dvec3(placed.world[2]);
        const double length = glm::length(z);
        const glm::dvec3 toward = length > 0.0 && std::isfinite(length) ? z / length : glm::dvec3(0, 0, 1);
        lights.push_back({light, position, toward});
    }
    return lights;
}

glm::dvec3 light_colour(const GltfFile& file, const tinygltf::Light& light, const std::string& where) {
    glm::dvec3 colour(1.0);
    if (!light.color.empty()) {
        if (light.color.size() != 3) refuse(file, where + ": color needs 3 numbers");
        colour = {light.color[0], light.color[1], light.color[2]};
    }
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(colour[c]) || colour[c] < 0.0)
            refuse(file, where + ": color must be finite and not negative");
    if (!std::isfinite(light.intensity) || light.intensity < 0.0)
        refuse(file, where + ": intensity must be finite and not negative");
    return colour * light.intensity;
}

}  // namespace

double add_light_sphere(PolygonSoup& soup, const glm::dvec3& centre, double radius,
                        const Material& material) {
    std::vector<glm::dvec3> corners;
    std::vector<Triangle> faces;
    icosahedron(corners, faces);
    subdivide(corners, faces);
    const auto base = static_cast<std::uint32_t>(soup.positions.size());
    for (const glm::dvec3& c : corners) soup.positions.push_back(centre + radius * c);
    const auto group = static_cast<std::uint32_t>(soup.groups.size());
    soup.groups.push_back({material.name, material});
    double area = 0.0;
    for (const Triangle& f : faces) {
        PolygonSoup::Polygon polygon;
        polygon.group = group;
        for (int k : f) polygon.vertices.push_back(base + static_cast<std::uint32_t>(k));
        const glm::dvec3& a = soup.positions[polygon.vertices[0]];
        const glm::dvec3& b = soup.positions[polygon.vertices[1]];
        const glm::dvec3& c = soup.positions[polygon.vertices[2]];
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
        soup.polygons.push_back(std::move(polygon));
    }
    return area;
}

void add_lights(GltfFile& file, const std::vector<PlacedNode>& nodes, PolygonSoup& soup, Sun& sun) {
    const std::vector<PunctualLight> lights = placed_lights(file, nodes);
    BoundingBox box = soup_bounds(soup);
    for (const PunctualLight& l : lights) box.extend(l.position);
    // Small against the scene, so the light is nearly a point, but large enough for its faces to have area
    // in floating point; a scene of one light alone gets a sphere of radius 1/200.
    const double diagonal = glm::length(box.extent());
    const double radius = (diagonal > 0.0 ? diagonal : 1.0) / 200.0;
    std::size_t spots = 0, extra_suns = 0;
    for (const PunctualLight& l : lights) {
        const tinygltf::Light& light = file.model.lights[static_cast<std::size_t>(l.light)];
        const std::string where = "lights[" + std::to_string(l.light) + "]";
        const std::string name = gltf_name(light.name, "light " + std::to_string(l.light));
        if (light.type == "directional") {
            const glm::dvec3 irradiance = light_colour(file, light, where);
            if (!sun.present()) {
                sun = Sun{l.toward, irradiance};
            } else {
                ++extra_suns;
            }
            continue;
        }
        if (light.type != "point" && light.type != "spot")
            refuse(file, where + ": light type '" + gltf_name(light.type, "") +
                             "' is not point, spot or directional");
        if (light.type == "spot") ++spots;
        if (soup.polygons.size() + 80 > kMaxSceneFaces)
            refuse(file,
                   where + ": the scene's faces would exceed the limit of " + std::to_string(kMaxSceneFaces));
        Material material;
        material.name = name;
        material.reflectance = glm::dvec3(0.0);  // a light source reflects nothing
        const glm::dvec3 intensity = light_colour(file, light, where);
        // Le is set once the sphere's area is known: Φ = π Le A = 4π I.
        const std::size_t group = soup.groups.size();
        const double area = add_light_sphere(soup, l.position, radius, material);
        soup.groups[group].material.emission = 4.0 * intensity / area;
        validate_material(soup.groups[group].material, gltf_message(file, where));
    }
    if (extra_suns > 0)
        file.warnings.push_back(gltf_message(
            file, std::to_string(extra_suns) + " more directional light(s) left out: the first is the sun, "
                                               "and a scene has one"));
    if (spots > 0)
        file.warnings.push_back(gltf_message(
            file, std::to_string(spots) + " spot light(s) emit in every direction, as point lights of "
                                          "the same intensity: their cones are not modelled"));
}

}  // namespace rad
