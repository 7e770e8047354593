#include "furnace_name.hpp"

#include <charconv>
#include <cstdint>
#include <string>

#include "rad/scene/builtin_scenes.hpp"
#include "rad/util/error.hpp"
#include "scene_limits.hpp"

namespace rad {

void check_furnace_faces(std::size_t faces, std::string_view spec) {
    if (faces < kFurnaceMinFaces || faces > kMaxSceneFaces) {
        throw InputError(std::string(spec) + ": " + std::to_string(faces) + " faces is outside " +
                         std::to_string(kFurnaceMinFaces) + " to " + std::to_string(kMaxSceneFaces) +
                         " (the scene limit)");
    }
}

std::size_t furnace_faces(std::string_view name) {
    const std::string spec = "builtin:" + std::string(name);
    constexpr std::string_view kPrefix = "furnace-";
    if (!name.starts_with(kPrefix)) throw InputError(spec + ": not a furnace-N name");
    std::string_view count = name.substr(kPrefix.size());
    std::size_t multiplier = 1;
    if (!count.empty() && (count.back() == 'k' || count.back() == 'm')) {
        multiplier = count.back() == 'k' ? 1'000 : 1'000'000;
        count.remove_suffix(1);
    }
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(count.data(), count.data() + count.size(), value);
    // from_chars takes no sign or space, so this leaves digits alone; a leading zero is refused so that
    // one count has one spelling.
    if (count.empty() || count.front() == '0' || error != std::errc() || end != count.data() + count.size()) {
        throw InputError(spec +
                         ": the face count must be a whole number with an optional k or m suffix "
                         "(builtin:furnace-100k, builtin:furnace-1m)");
    }
    // Above the limit before multiplying, so the product cannot overflow.
    const std::size_t faces = value > kMaxSceneFaces ? kMaxSceneFaces + 1 : value * multiplier;
    check_furnace_faces(faces, spec);
    return faces;
}

}  // namespace rad
