#include "scene/texture_image.hpp"

#include <stb_image.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>
#include <utility>

#include "rad/util/srgb.hpp"
#include "scene/scene_limits.hpp"

namespace rad {

namespace {

using StbPixels = std::unique_ptr<unsigned char, decltype(&stbi_image_free)>;

glm::dvec3 mean_linear(const unsigned char* texels, std::size_t count) {
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < count; ++i) {
        for (int c = 0; c < 3; ++c) sum[c] += srgb_byte_to_linear(texels[3 * i + c]);
    }
    return sum / static_cast<double>(count);
}

// The image reduced by `factor` on each side (its last texels dropped where the side does not divide), each
// texel the linear mean of its factor × factor block; a side shorter than the factor is one block of it all.
void reduce(const unsigned char* texels, int width, int height, int factor, Texture& texture) {
    texture.srgb.resize(static_cast<std::size_t>(texture.width) * texture.height * 3);
    const int block_w = std::min(factor, width), block_h = std::min(factor, height);
    const double weight = 1.0 / (static_cast<double>(block_w) * block_h);
    for (int y = 0; y < texture.height; ++y) {
        for (int x = 0; x < texture.width; ++x) {
            glm::dvec3 sum(0.0);
            for (int dy = 0; dy < block_h; ++dy) {
                const unsigned char* row = texels + (static_cast<std::size_t>(y * block_h + dy) * width +
                                                     static_cast<std::size_t>(x) * block_w) *
                                                        3;
                for (int dx = 0; dx < 3 * block_w; ++dx) sum[dx % 3] += srgb_byte_to_linear(row[dx]);
            }
            for (int c = 0; c < 3; ++c) {
                texture.srgb[(static_cast<std::size_t>(y) * texture.width + x) * 3 + c] =
                    srgb_byte(static_cast<float>(sum[c] * weight));
            }
        }
    }
}

// Why the bytes are not an image worth handing to stb_image, or empty. Only PNG and JPEG are read (what the
// scene formats use). stb_image sizes a PNG's compressed data by the lengths its chunks claim, before it
// reads them, so a corrupt length of 2 GB in a file of a few bytes would be allocated: the chunks are walked
// here first, each within the file.
std::string image_problem(const unsigned char* bytes, std::size_t size) {
    static constexpr unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    const bool jpeg = size >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff;
    if (jpeg) return {};
    if (size < sizeof kPng || !std::equal(kPng, kPng + sizeof kPng, bytes))
        return "it is not a PNG or JPEG image";
    for (std::size_t at = sizeof kPng; at + 12 <= size;) {
        const std::size_t length = (std::size_t{bytes[at]} << 24) | (std::size_t{bytes[at + 1]} << 16) |
                                   (std::size_t{bytes[at + 2]} << 8) | std::size_t{bytes[at + 3]};
        if (length > size - at - 12) {
            return "a PNG chunk at byte " + std::to_string(at) + " claims " + std::to_string(length) +
                   " bytes, more than the file holds";
        }
        if (std::equal(bytes + at + 4, bytes + at + 8, "IEND")) break;
        at += 12 + length;
    }
    return {};
}

}  // namespace

std::shared_ptr<const Texture> decode_texture(const unsigned char* bytes, std::size_t size,
                                              const std::string& name, std::string& why) {
    if (size == 0 || size > INT_MAX) {
        why = "the image is empty or too large to decode";
        return nullptr;
    }
    if (std::string problem = image_problem(bytes, size); !problem.empty()) {
        why = std::move(problem);
        return nullptr;
    }
    int width = 0, height = 0, channels = 0;
    // The header first: the texel count decides whether decoding it is worth its memory.
    if (!stbi_info_from_memory(bytes, static_cast<int>(size), &width, &height, &channels)) {
        why = std::string("stb_image cannot decode it (") + stbi_failure_reason() + ")";
        return nullptr;
    }
    if (width <= 0 || height <= 0 ||
        static_cast<std::size_t>(width) * static_cast<std::size_t>(height) > kMaxTextureTexels) {
        why = "it has " + std::to_string(width) + " × " + std::to_string(height) +
              " texels, more than the limit of " + std::to_string(kMaxTextureTexels);
        return nullptr;
    }
    const StbPixels texels(
        stbi_load_from_memory(bytes, static_cast<int>(size), &width, &height, &channels, 3),
        &stbi_image_free);
    if (!texels) {
        why = std::string("stb_image cannot decode it (") + stbi_failure_reason() + ")";
        return nullptr;
    }
    auto texture = std::make_shared<Texture>();
    texture->name = name;
    texture->mean = mean_linear(texels.get(), static_cast<std::size_t>(width) * height);
    const int factor = (std::max(width, height) + kMaxDisplayTextureSide - 1) / kMaxDisplayTextureSide;
    texture->width = std::max(1, width / factor);
    texture->height = std::max(1, height / factor);
    if (factor == 1) {
        texture->srgb.assign(texels.get(), texels.get() + static_cast<std::size_t>(width) * height * 3);
    } else {
        reduce(texels.get(), width, height, factor, *texture);
    }
    return texture;
}

}  // namespace rad
