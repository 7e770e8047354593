#include "rad/util/error.hpp"

#include <algorithm>

namespace rad {

namespace {

std::string plain_words(std::string_view setting) {
    std::string words(setting);
    std::replace(words.begin(), words.end(), '_', ' ');
    return words;
}

std::string replace_names(const std::string& text,
                          const std::function<std::string(std::string_view)>& name_of) {
    std::string out;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t open = text.find('{', at);
        const std::size_t close = open == std::string::npos ? open : text.find('}', open);
        if (close == std::string::npos) {
            out.append(text, at, std::string::npos);
            break;
        }
        out.append(text, at, open - at);
        out += name_of(std::string_view(text).substr(open + 1, close - open - 1));
        at = close + 1;
    }
    return out;
}

}  // namespace

SettingError::SettingError(std::string setting, std::string message)
    : InputError(replace_names("{" + setting + "}: " + message, plain_words)),
      setting_(std::move(setting)),
      message_(std::move(message)) {}

std::string SettingError::worded(const std::function<std::string(std::string_view)>& name_of) const {
    return replace_names("{" + setting_ + "}: " + message_, name_of);
}

}  // namespace rad
