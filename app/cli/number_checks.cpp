#include "cli/number_checks.hpp"

#include <cmath>
#include <functional>
#include <string>

namespace rad {

namespace {

// A check that reads the option as a double and asks `accept` about it; `want` completes "must be ...".
CLI::Validator number_check(std::function<bool(double)> accept, const std::string& want,
                            const std::string& name) {
    return CLI::Validator(
        [accept = std::move(accept), want](std::string& text) -> std::string {
            double value = 0.0;
            if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || !accept(value)) {
                return "must be " + want + ", not '" + text + "'";
            }
            return {};
        },
        name);
}

std::string shown(double value) {
    std::string text = std::to_string(value);
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
    return text;
}

}  // namespace

CLI::Validator positive_number() {
    return number_check([](double v) { return v > 0.0; }, "a positive number", "POSITIVE");
}

CLI::Validator finite_number() {
    return number_check([](double) { return true; }, "a finite number", "NUMBER");
}

CLI::Validator finite_range(double min, double max) {
    return number_check([min, max](double v) { return v >= min && v <= max; },
                        "a number in [" + shown(min) + ", " + shown(max) + "]",
                        "[" + shown(min) + " - " + shown(max) + "]");
}

}  // namespace rad
