#pragma once

#include <string>
#include <string_view>

#include "rad/transport/scene_transport.hpp"

namespace rad {

struct SubdivisionOptions {
    std::string method = "auto";
    double tolerance = 0.0;       // --refine-tol; 0 picks the method's default
    double min_patch_size = 0.0;  // --min-patch-size; 0 picks the method's default
};

// The subdivisions' names, joined by `separator`.
std::string subdivision_names(const std::string& separator);

// Throws InputError naming --subdivision for an unknown name.
Subdivision parse_subdivision(const std::string& name);

// Clustering's options from the command line's (and the form-factor seed and --rays).
ClusteredOptions clustered_options(const SubdivisionOptions& options, int rays, std::uint64_t seed);

// The hierarchical solver's options from the command line's (and the form-factor seed and --rays).
HierarchicalOptions hierarchical_options(const SubdivisionOptions& options, int rays, std::uint64_t seed);

// Adaptive subdivision's options from the command line's (and the form-factor seed). Its default tolerance,
// 0.15, is where it matched or beat uniform meshes of as many patches in both absolute and relative error
// on the Cornell box (tests/transport/test_adaptive_subdivision.cpp, RAD_ADAPTIVE_MEASURE=1).
AdaptiveOptions adaptive_options(const SubdivisionOptions& options, std::uint64_t seed);

}  // namespace rad
