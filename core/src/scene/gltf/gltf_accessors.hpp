#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <string>
#include <vector>

#include "scene/gltf/gltf_file.hpp"

namespace rad {

// The bytes of a buffer view, checked against its buffer. tinygltf checks neither, so every read from a
// buffer goes through here (or checked_accessor) first. `where` names the element that uses the view.
std::span<const unsigned char> checked_buffer_view(const GltfFile& file, int view, const std::string& where);

// An accessor's elements, checked against its buffer view: element i starts at data + i * stride and has
// `element_size` bytes inside the view.
struct AccessorBytes {
    const unsigned char* data = nullptr;
    std::size_t count = 0;
    std::size_t stride = 0;
    std::size_t element_size = 0;
};

// Refuses (InputError naming accessors[N]) a missing accessor, a sparse one, one without a buffer view, a
// type or component type other than those given, and elements outside the view, all before reading.
AccessorBytes checked_accessor(const GltfFile& file, int accessor, int type,
                               std::span<const int> component_types, const std::string& where);

// A POSITION accessor (float VEC3) with at most `max_count` elements, each finite.
std::vector<glm::dvec3> read_positions(const GltfFile& file, int accessor, std::size_t max_count,
                                       const std::string& where);

// A TEXCOORD_n accessor (float, or normalized unsigned byte or short, VEC2) of exactly `vertex_count`
// elements, each finite.
std::vector<glm::dvec2> read_texcoords(const GltfFile& file, int accessor, std::size_t vertex_count,
                                       const std::string& where);

// An index accessor (unsigned byte, short or int scalars) with at most `max_count` elements, each below
// `vertex_count`.
std::vector<std::uint32_t> read_indices(const GltfFile& file, int accessor, std::size_t vertex_count,
                                        std::size_t max_count, const std::string& where);

}  // namespace rad
