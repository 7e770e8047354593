#pragma once

#include <string>

#include "pipeline/exposure.hpp"
#include "pipeline/radiosity_pipeline.hpp"

namespace rad {

// What `radiosity view` takes: the pipeline's options, the window, and a script for tests.
struct ViewerOptions {
    PipelineOptions pipeline;
    int width = 1280;
    int height = 800;
    Exposure exposure;  // as `render` PNGs take it
    // Scripted run: take `steps` solver steps (after the form factors), then write `screenshot` (if given)
    // and close when `exit` is set. steps < 0: no script.
    int steps = -1;
    std::string screenshot;
    bool exit = false;
    // Then stay open this long with nothing asked of it, and print the frames drawn and the CPU time used
    // meanwhile (an idle window should sleep).
    double idle_seconds = 0.0;
};

}  // namespace rad
