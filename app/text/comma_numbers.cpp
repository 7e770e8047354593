#include "text/comma_numbers.hpp"

#include <cmath>
#include <sstream>

#include "rad/util/error.hpp"

namespace rad {

std::vector<double> comma_numbers(const std::string& text, const std::string& where,
                                  const std::string& want) {
    std::vector<double> values;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        double value = 0.0;
        std::size_t used = 0;
        try {
            value = std::stod(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != item.size() || !std::isfinite(value))
            throw InputError(where + ": '" + item + "' is not a number (want " + want + ")");
        values.push_back(value);
    }
    return values;
}

}  // namespace rad
