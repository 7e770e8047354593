#pragma once

#include <string>

#include "pipeline/radiosity_pipeline.hpp"

namespace rad {

// What `radiosity view` takes: the pipeline's options, the window, and a script for tests.
struct ViewerOptions {
    PipelineOptions pipeline;
    int width = 1280;
    int height = 800;
    double exposure = 0.0;  // the image shows L · 2^exposure, as `render` PNGs do
    // Scripted run: take `steps` solver steps (after the form factors), then write `screenshot` (if given)
    // and close when `exit` is set. steps < 0: no script.
    int steps = -1;
    std::string screenshot;
    bool exit = false;
};

}  // namespace rad
