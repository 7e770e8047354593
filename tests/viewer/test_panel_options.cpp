// What the panel asks of the worker when a scene is opened: the scene's own default patch size and the
// default subdivision, whatever the previous scene was meshed at; the other settings stay.
#include <gtest/gtest.h>

#include "viewer/viewer_panel.hpp"

namespace rad {
namespace {

TEST(PanelOptions, ANewSceneOpensAtItsOwnPatchSizeAndTheDefaultSubdivision) {
    PipelineOptions panel;
    panel.scene.scene = "builtin:cornell";
    panel.scene.patch_size = 20.0;  // set for the Cornell box's millimetres
    panel.subdivision.method = "adaptive";
    panel.subdivision.tolerance = 0.1;
    panel.form_factors.rays = 4096;
    panel.solver.method = "gauss-seidel";

    const PipelineOptions opened = options_for_new_scene(panel, "builtin:cube");
    EXPECT_EQ(opened.scene.scene, "builtin:cube");
    EXPECT_EQ(opened.scene.patch_size, 0.0);  // 0: the scene's default
    EXPECT_EQ(opened.subdivision.method, PipelineOptions{}.subdivision.method);
    EXPECT_EQ(opened.subdivision.tolerance, PipelineOptions{}.subdivision.tolerance);
    EXPECT_EQ(opened.form_factors.rays, 4096);
    EXPECT_EQ(opened.solver.method, "gauss-seidel");
}

}  // namespace
}  // namespace rad
