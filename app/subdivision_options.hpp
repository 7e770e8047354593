#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <string_view>

#include "rad/adaptive_subdivision.hpp"
#include "rad/hierarchical_radiosity.hpp"

namespace rad {

// How the scene is cut into patches:
//   uniform       one patch size everywhere, a form factor for every pair that sees each other;
//   adaptive      coarser uniform patches first, then split where the radiosity changes steeply between
//                 neighbours or a shadow edge crosses, form factors and solve repeated;
//   hierarchical  coarse base patches split into a quadtree as links between elements need it (HSA).
enum class Subdivision { uniform, adaptive, hierarchical };

std::string_view subdivision_name(Subdivision subdivision);

struct SubdivisionOptions {
    std::string method = "uniform";
    double tolerance = 0.0;       // --refine-tol; 0 picks the method's default
    double min_patch_size = 0.0;  // --min-patch-size; 0 picks the method's default
};

void add_subdivision_options(CLI::App& command, SubdivisionOptions& options);

// Throws InputError naming --subdivision for an unknown name.
Subdivision parse_subdivision(const std::string& name);

// The hierarchical solver's options from the command line's (and the form-factor seed and --rays).
HierarchicalOptions hierarchical_options(const SubdivisionOptions& options, int rays, std::uint64_t seed);

// Adaptive subdivision's options from the command line's (and the form-factor seed). Its default tolerance,
// 0.15, is where it matched or beat uniform meshes of as many patches in both absolute and relative error
// on the Cornell box (tests/test_adaptive_subdivision.cpp, RAD_ADAPTIVE_MEASURE=1).
AdaptiveOptions adaptive_options(const SubdivisionOptions& options, std::uint64_t seed);

// Adaptive subdivision starts from patches this many times the uniform default size.
inline constexpr double kAdaptiveBaseScale = 2.0;

// A base patch of hierarchical radiosity is this many times the uniform default size: every pair of base
// patches gets a link, so they are few, and the hierarchy refines them.
inline constexpr double kHierarchicalBaseScale = 4.0;

}  // namespace rad
