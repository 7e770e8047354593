#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/radiosity_pipeline.hpp"
#include "rad/display/display_mesh.hpp"
#include "rad/scene/scene.hpp"
#include "rad/solve/solver.hpp"

namespace rad {

// What the render thread draws: uploaded once per mesh (or after a smooth/flat switch).
struct ViewerGeometry {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> triangles;  // three indices per triangle
    std::vector<std::uint32_t> outline;    // two indices per patch edge
    std::vector<glm::vec2> texcoords;      // per vertex where any surface is textured
    // Per triangle, its material's place in ViewerStatistics::materials (for picking by a click).
    std::vector<std::uint32_t> triangle_material;
    std::vector<DisplayMesh::TexturedRange> textured;
    BoundingBox bounds;
    Camera scene_camera;
    std::uint64_t scene_version =
        0;  // changes when another scene is opened, not when the same one is re-meshed
};

// The colours after one solver step, per display vertex (linear radiance L).
struct ViewerRadiance {
    using Colours = std::shared_ptr<const std::vector<glm::vec3>>;

    std::vector<glm::vec3> cumulative;  // the solution as it stands
    // What step k alone added, B_k − B_{k−1} (E for k = 0), for the last steps: bounces[i] is step
    // first_bounce + i. For Jacobi that is the light of paths L D^k E. Shared between snapshots, each built
    // once.
    std::vector<Colours> bounces;
    std::size_t first_bounce = 0;
    std::size_t step = 0;

    // Step k's light alone, or nullptr when it is not kept (or not yet computed).
    Colours bounce(std::size_t k) const {
        if (k < first_bounce || k - first_bounce >= bounces.size()) return nullptr;
        return bounces[k - first_bounce];
    }
};

// A material of the scene shown, as the panel edits it (every surface of that name at once).
struct ViewerMaterial {
    std::string name;
    glm::dvec3 reflectance{0.0};
    glm::dvec3 emitted_radiance{0.0};  // Le
    bool textured = false;             // its reflectance comes from its texels
    double area = 0.0;                 // of its surfaces, for the emitted power π Le A
};

// Figures for the panel, small enough to copy every frame.
struct ViewerStatistics {
    std::string scene;  // what is open: a scene, or a saved solution (FILE.radiosity)
    // While a saved solution is open, the options it was solved with, their scene the one it was solved
    // from: what "Re-mesh and recompute" starts from. Empty for a scene.
    std::optional<PipelineOptions> saved_options;
    std::string remesh_unavailable;     // why those cannot be recomputed (the scene file is gone), or empty
    std::uint64_t opened = 0;           // scenes and saved solutions opened so far
    std::vector<std::string> warnings;  // the loader's about the scene shown (clamped values, skipped faces)
    // In the order of their first surface; shared, as the statistics are copied every frame and a scene may
    // have thousands of materials. Made again only when a scene opens or a material is edited.
    std::shared_ptr<const std::vector<ViewerMaterial>> materials;
    std::size_t patches = 0;
    std::size_t interactions = 0;  // the transport's form factors, or links
    std::string interaction_name;  // "form factors", "links"
    std::string subdivision;       // uniform, adaptive, hierarchical
    double patch_size = 0.0;
    StageSeconds seconds;
    SolverMethod method = SolverMethod::jacobi;
    SolverStatus status = SolverStatus::running;
    std::string status_message;
    bool prepared = false;
    std::size_t form_factor_passes = 0;  // stays 1 across solver resets; a re-mesh computes them again
    std::vector<float> log_residual;     // log10 per step, for the plot
    std::vector<float> log_unshot;       // log10 of the unshot (or last update's) power, summed over channels
};

// The worker's latest results, handed over under its mutex. Shared pointers make the hand-over cheap; a
// new pointer means new data, so the render thread uploads only when one changes.
struct SolverSnapshot {
    std::shared_ptr<const ViewerGeometry> geometry;
    std::shared_ptr<const ViewerRadiance> radiance;
    ViewerStatistics statistics;
    std::string error;       // the last failure, for the panel; empty when the last job succeeded
    std::string written;     // "wrote FILE" after the last file the panel asked for
    bool bad_input = false;  // the failure was the user's input (a scene file, an option): exit status 2
};

}  // namespace rad
