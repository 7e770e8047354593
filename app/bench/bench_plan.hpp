#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "rad/solve/solver.hpp"
#include "rad/transport/transport_methods.hpp"
#include "rad/transport/uniform/form_factors.hpp"

namespace rad {

// A form-factor estimator and its ray count.
struct EstimatorSetting {
    FormFactorMethod method = FormFactorMethod::hemisphere;
    int rays = 4096;
};

// One refining transport method (rad/transport/transport_methods.hpp) and its --refine-tol values.
struct RefinedRuns {
    Subdivision method;
    std::vector<double> tolerances;
};

// What `radiosity bench` sweeps, per scene: meshes from coarse to fine (patch sizes as multiples of the
// scene's default), at each mesh every estimator setting with the default solver, and every solver with
// the default estimator; then the reference work and the comparison with the path tracer.
struct BenchPlan {
    std::vector<std::string> scenes;
    std::vector<double> size_factors;
    std::vector<EstimatorSetting> estimators;  // the first is the default, the one every solver runs on
    std::size_t analytic_max_patches = 0;      // the analytic estimator is slow: only on meshes up to this
    std::vector<SolverMethod> solvers;         // the first is the default
    std::size_t direct_max_patches = 0;        // the direct solver runs on meshes up to this (n³)
    double tolerance = 1e-5;
    // Paths for the path-traced patch reference of each mesh, in all; each patch gets its share, at least
    // min_paths_per_patch.
    std::size_t reference_paths = 0;
    int min_paths_per_patch = 64;
    int image_size = 256;   // the image compared with the path-traced reference, square
    int reference_spp = 0;  // paths per pixel of that reference
    // Image sides at which radiosity is set beside the path tracer, on the first scene, at the default mesh
    // (or the one nearest it) with the default estimator and solver.
    std::vector<int> comparison_sizes;
    int comparison_max_spp = 0;    // the path tracer's search for radiosity's image error stops here
    int further_view_frames = 21;  // frames whose median time is a further view's cost
    // The methods that refine their own elements (the table's entries with refinement tolerances), each at
    // these --refine-tol values (default first or base patches and solver), per scene, in this order.
    std::vector<RefinedRuns> refined;
};

// The default sweep (a few minutes on 2 cores), or the quick one for CI (seconds).
BenchPlan default_bench_plan(bool quick);

}  // namespace rad
