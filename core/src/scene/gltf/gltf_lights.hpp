#pragma once

#include <vector>

#include "rad/scene/polygon_soup.hpp"
#include "scene/gltf/gltf_file.hpp"
#include "scene/gltf/gltf_nodes.hpp"

namespace rad {

// The faces of the small sphere that stands for a punctual light (an icosahedron subdivided once: 80
// triangles, corners on the sphere), added to `soup` in a group of its own with the given material.
// Returns the sphere's area (the sum of its flat faces).
double add_light_sphere(PolygonSoup& soup, const glm::dvec3& centre, double radius, const Material& material);

// KHR_lights_punctual: every point and spot light on a placed node becomes a small sphere (add_light_sphere,
// radius 1/200 of the diagonal of the soup's bounding box with the lights in it) that emits diffusely, with
// Le = 4 I / A times the light's colour, so its power π Le A is a point light's 4π I (I, the intensity, read
// as W/sr: the renderer's units are radiometric). A spot light is treated as a point light of the same
// intensity (its cone is not modelled), with a warning. The first directional light becomes `sun` (toward the
// node's +z, the irradiance its intensity times its colour, lux read as W/m²); further ones are left out,
// with a warning.
void add_lights(GltfFile& file, const std::vector<PlacedNode>& nodes, PolygonSoup& soup, Sun& sun);

}  // namespace rad
