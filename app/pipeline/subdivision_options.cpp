#include "pipeline/subdivision_options.hpp"

#include <string>
#include <vector>

#include "pipeline/scene_options.hpp"
#include "rad/util/error.hpp"

namespace rad {

std::string subdivision_names(const std::string& separator) {
    std::string names;
    for (Subdivision s : all_subdivisions())
        names += (names.empty() ? "" : separator) + std::string(subdivision_name(s));
    return names;
}

Subdivision parse_subdivision(const std::string& name) {
    for (Subdivision s : all_subdivisions())
        if (name == subdivision_name(s)) return s;
    throw InputError("--subdivision: unknown method '" + name + "' (" + subdivision_names(", ") + ")");
}

}  // namespace rad
