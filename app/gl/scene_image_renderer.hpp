#pragma once

#include "gl/offscreen_target.hpp"
#include "gl/renderer.hpp"
#include "pipeline/radiosity_pipeline.hpp"
#include "rad/io/image.hpp"

namespace rad {

// Draws a pipeline's scene into images from any camera: geometry goes to the GPU once, colours whenever
// refresh_colours() is called (after solver steps); a new viewpoint costs one frame, no solver work.
// Needs a current OpenGL context for its whole life.
class SceneImageRenderer {
  public:
    SceneImageRenderer(const RadiosityPipeline& pipeline, bool outline);

    void refresh_colours();
    Image render(const Camera& camera, int width, int height) const;
    // Draws one frame from `camera` into `target` and waits until it is drawn: what a further viewpoint
    // costs a viewer, whose framebuffer exists already and is shown rather than read back.
    void draw_frame(const Camera& camera, const OffscreenTarget& target) const;

    const Renderer& renderer() const { return renderer_; }

  private:
    void draw(const Camera& camera, const OffscreenTarget& target) const;

    const RadiosityPipeline& pipeline_;
    Renderer renderer_;
    bool outline_;
};

}  // namespace rad
