#pragma once

#include "gl/renderer.hpp"
#include "image_io.hpp"
#include "radiosity_pipeline.hpp"

namespace rad {

// Draws a pipeline's scene into images from any camera: geometry goes to the GPU once, colours whenever
// refresh_colours() is called (after solver steps); a new viewpoint costs one frame, no solver work.
// Needs a current OpenGL context for its whole life.
class SceneImageRenderer {
  public:
    SceneImageRenderer(const RadiosityPipeline& pipeline, bool outline);

    void refresh_colours();
    RadianceImage render(const Camera& camera, int width, int height) const;

    const Renderer& renderer() const { return renderer_; }

  private:
    const RadiosityPipeline& pipeline_;
    Renderer renderer_;
    bool outline_;
};

}  // namespace rad
