#include "cli/scene_summary.hpp"

#include <cstdio>
#include <string>

namespace rad {

namespace {

std::string rgb(const glm::dvec3& c) {
    char text[64];
    std::snprintf(text, sizeof text, "%.3g %.3g %.3g", c.x, c.y, c.z);
    return text;
}

std::string point(const glm::dvec3& p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p.x, p.y, p.z);
    return text;
}

}  // namespace

void print_scene_summary(std::ostream& out, const LoadedScene& loaded) {
    const Scene& scene = loaded.scene;
    const PatchMesh& patches = *loaded.patches;
    char line[256];
    out << "scene: " << scene.source << '\n';
    out << "surfaces: " << scene.surfaces.size() << '\n';
    std::snprintf(line, sizeof line, "  %-20s %-12s %6s %14s %8s  %-20s %s\n", "name", "material", "faces",
                  "area", "patches", "reflectance", "emission (Le)");
    out << line;
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const Surface& surface = scene.surfaces[s];
        const auto count = patches.surface_begin[s + 1] - patches.surface_begin[s];
        std::snprintf(line, sizeof line, "  %-20s %-12s %6zu %14.6g %8u  %-20s %s\n", surface.name.c_str(),
                      surface.material.name.c_str(), surface.mesh.n_faces(), surface_area(surface.mesh),
                      count, rgb(surface.material.reflectance).c_str(),
                      rgb(surface.material.emission).c_str());
        out << line;
    }
    std::snprintf(line, sizeof line, "patches: %zu (patch size %.6g)\n", patches.size(), loaded.patch_size);
    out << line;
    std::snprintf(line, sizeof line, "total area: %.9g\n", total_area(scene));
    out << line;
    const BoundingBox box = bounding_box(scene);
    out << "bounding box: " << point(box.min) << " to " << point(box.max) << '\n';
}

}  // namespace rad
