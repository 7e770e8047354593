#pragma once

#include <string>
#include <string_view>

#include "rad/transport/transport_methods.hpp"

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

}  // namespace rad
