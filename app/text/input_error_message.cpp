#include "text/input_error_message.hpp"

#include <algorithm>
#include <array>
#include <sstream>
#include <utility>

namespace rad {

std::string flag_of(std::string_view setting) {
    static constexpr std::array<std::pair<std::string_view, std::string_view>, 17> flags = {{
        {"patch_size", "--patch-size"},
        {"solver", "--solver"},
        {"tolerance", "--tol"},
        {"relaxation", "--sor"},
        {"initial_guess", "--initial"},
        {"rays", "--rays"},
        {"visibility_rays", "--rays"},
        {"max_memory", "--max-memory"},
        {"refine_tolerance", "--refine-tol"},
        {"min_patch_size", "--min-patch-size"},
        {"subdivision", "--subdivision"},
        {"seed", "--seed"},
        {"image_path", "--out"},
        {"json_path", "--json"},
        {"save_path", "--save"},
        {"csv_path", "--out"},
        {"export_path", "--export"},
    }};
    for (const auto& [name, flag] : flags)
        if (name == setting) return std::string(flag);
    std::string words(setting);
    std::replace(words.begin(), words.end(), '_', ' ');
    return words;
}

std::string input_error_message(const InputError& error) {
    const auto* setting = dynamic_cast<const SettingError*>(&error);
    if (!setting) return error.what();
    std::string message = setting->worded(flag_of);
    if (const auto* budget = dynamic_cast<const MemoryBudgetError*>(setting)) {
        std::ostringstream advice;
        if (budget->coarser_patch_size > 0.0) {
            advice << "; use --patch-size " << budget->coarser_patch_size << " or larger";
        } else {
            advice << "; raise --max-memory";
        }
        message += advice.str();
    }
    return message;
}

}  // namespace rad
