#include "bench/bench_plan.hpp"

namespace rad {

BenchPlan default_bench_plan(bool quick) {
    BenchPlan plan;
    plan.scenes = {"builtin:cornell", "builtin:white-room"};
    plan.solvers = {SolverMethod::jacobi, SolverMethod::gauss_seidel, SolverMethod::conjugate_gradient,
                    SolverMethod::southwell, SolverMethod::direct};
    if (quick) {
        plan.size_factors = {4.0, 2.0};
        plan.estimators = {{FormFactorMethod::hemisphere, 1024}, {FormFactorMethod::analytic, 4}};
        plan.analytic_max_patches = 1000;
        plan.direct_max_patches = 1000;
        plan.reference_paths = 200'000;
        plan.image_size = 64;
        plan.reference_spp = 16;
        plan.comparison_sizes = {64};
        plan.comparison_max_spp = 16;
        plan.further_view_frames = 3;
        for (const TransportMethod& m : transport_methods())
            if (m.quick_refine_tolerance > 0.0) plan.refined.push_back({m.id, {m.quick_refine_tolerance}});
        return plan;
    }
    plan.scenes.push_back("builtin:many-lights");
    plan.size_factors = {2.0, 1.4, 1.0, 0.7};
    plan.estimators = {{FormFactorMethod::hemisphere, 2048},
                       {FormFactorMethod::hemisphere, 1024},
                       {FormFactorMethod::hemisphere, 4096},
                       {FormFactorMethod::hemisphere, 16384},
                       {FormFactorMethod::analytic, 4}};
    plan.analytic_max_patches = 2600;
    plan.direct_max_patches = 2600;
    plan.reference_paths = 4'000'000;
    plan.image_size = 256;
    plan.reference_spp = 512;
    plan.comparison_sizes = {256, 1024};
    plan.comparison_max_spp = 1024;
    for (const TransportMethod& m : transport_methods())
        if (!m.refine_tolerances.empty())
            plan.refined.push_back({m.id, {m.refine_tolerances.begin(), m.refine_tolerances.end()}});
    return plan;
}

}  // namespace rad
