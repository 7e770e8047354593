// A second viewpoint after a solve costs one frame: no form-factor pass, no solver step, no geometry upload.
#include <gtest/gtest.h>

#include "gl/headless_context.hpp"
#include "gl/scene_image_renderer.hpp"
#include "pipeline/radiosity_pipeline.hpp"
#include "rad/camera/camera_view.hpp"

namespace rad {
namespace {

TEST(RenderViews, SecondViewpointDoesNoSolverOrFormFactorWork) {
    PipelineOptions options;
    options.scene.scene = "builtin:cornell";
    options.scene.patch_size = 100.0;
    RadiosityPipeline pipeline(options);
    pipeline.solve();
    const WorkCounts after_solve = pipeline.work();
    EXPECT_EQ(after_solve.form_factor_passes, 1u);
    EXPECT_GT(after_solve.solver_steps, 0u);

    const HeadlessContext context;
    SceneImageRenderer renderer(pipeline, false);
    const Camera front = scene_camera(pipeline.loaded().scene);
    Camera side = front;
    side.eye = {500.0, 300.0, -300.0};
    const Image first = renderer.render(front, 64, 64);
    const Image second = renderer.render(side, 64, 64);

    EXPECT_EQ(pipeline.work().form_factor_passes, after_solve.form_factor_passes);
    EXPECT_EQ(pipeline.work().solver_steps, after_solve.solver_steps);
    EXPECT_EQ(renderer.renderer().geometry_uploads(), 1u);
    EXPECT_EQ(renderer.renderer().colour_uploads(), 1u);
    EXPECT_NE(first.pixels, second.pixels);  // it did draw a different view
}

}  // namespace
}  // namespace rad
