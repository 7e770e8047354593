#include "gl/renderer.hpp"

#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <vector>

namespace rad {

namespace {

enum Buffer { kPositions = 0, kColours = 1, kTriangles = 2, kOutline = 3, kTexcoords = 4 };
constexpr int kBufferCount = 5;

}  // namespace

Renderer::Renderer()
    : patch_program_("patch.vert", "patch.frag"), outline_program_("outline.vert", "outline.frag") {
    glGenVertexArrays(1, &vertex_array_);
    glGenBuffers(kBufferCount, buffers_);
    glBindVertexArray(vertex_array_);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[kPositions]);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[kColours]);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(1);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[kTexcoords]);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2), nullptr);
    glBindVertexArray(0);
}

Renderer::~Renderer() {
    release_textures();
    glDeleteBuffers(kBufferCount, buffers_);
    glDeleteVertexArrays(1, &vertex_array_);
}

void Renderer::upload_geometry(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangles,
                               std::span<const std::uint32_t> outline_lines) {
    glBindVertexArray(vertex_array_);  // element buffer bindings belong to the vertex array
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[kPositions]);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(positions.size_bytes()), positions.data(),
                 GL_STATIC_DRAW);
    // Black until the first colours arrive.
    const std::vector<glm::vec3> black(positions.size(), glm::vec3(0.0f));
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[kColours]);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(black.size() * sizeof(glm::vec3)), black.data(),
                 GL_DYNAMIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[kTriangles]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(triangles.size_bytes()), triangles.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[kOutline]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(outline_lines.size_bytes()),
                 outline_lines.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    vertex_count_ = positions.size();
    triangle_index_count_ = triangles.size();
    outline_index_count_ = outline_lines.size();
    ranges_.assign(1, DrawnRange{0, triangle_index_count_, 0, glm::vec3(1.0f), glm::vec3(0.0f)});
    release_textures();
    glBindVertexArray(vertex_array_);
    glDisableVertexAttribArray(2);
    glBindVertexArray(0);
    ++geometry_uploads_;
}

void Renderer::upload_textures(std::span<const glm::vec2> texcoords,
                               std::span<const DisplayMesh::TexturedRange> ranges) {
    release_textures();
    ranges_.clear();
    glBindVertexArray(vertex_array_);
    if (ranges.empty() || texcoords.size() != vertex_count_) {
        glDisableVertexAttribArray(2);
        glBindVertexArray(0);
        ranges_.push_back({0, triangle_index_count_, 0, glm::vec3(1.0f), glm::vec3(0.0f)});
        return;
    }
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[kTexcoords]);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(texcoords.size_bytes()), texcoords.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(2);
    glBindVertexArray(0);
    std::size_t next = 0;  // the first index not yet in a range
    for (const DisplayMesh::TexturedRange& r : ranges) {
        const std::size_t first = 3 * std::size_t{r.first_triangle};
        const std::size_t count = 3 * std::size_t{r.triangle_count};
        if (first < next || first + count > triangle_index_count_)
            throw std::logic_error(
                "Renderer::upload_textures: textured ranges overlap or exceed the triangles");
        if (first > next) ranges_.push_back({next, first - next, 0, glm::vec3(1.0f), glm::vec3(0.0f)});
        ranges_.push_back({first, count, texture_of(r.texture), r.albedo_scale, r.emitted_radiance});
        next = first + count;
    }
    if (next < triangle_index_count_)
        ranges_.push_back({next, triangle_index_count_ - next, 0, glm::vec3(1.0f), glm::vec3(0.0f)});
}

GLuint Renderer::texture_of(const std::shared_ptr<const Texture>& texture) {
    if (!texture || texture->width <= 0 || texture->height <= 0 ||
        texture->srgb.size() != std::size_t{3} * texture->width * texture->height)
        throw std::logic_error("Renderer::upload_textures: a range without a whole texture");
    if (const auto it = textures_.find(texture.get()); it != textures_.end()) return it->second;
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows of 3-byte texels are not 4-byte aligned
    // Row 0 is the image's top, which is where texture coordinate v = 0 samples (glTF's convention).
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8, texture->width, texture->height, 0, GL_RGB, GL_UNSIGNED_BYTE,
                 texture->srgb.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
    textures_.emplace(texture.get(), name);
    return name;
}

void Renderer::release_textures() {
    for (const auto& [texture, name] : textures_) glDeleteTextures(1, &name);
    textures_.clear();
}

void Renderer::update_colours(std::span<const glm::vec3> radiance) {
    if (radiance.size() != vertex_count_) {
        throw std::logic_error("Renderer::update_colours: " + std::to_string(radiance.size()) +
                               " colours for " + std::to_string(vertex_count_) + " vertices");
    }
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[kColours]);
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(radiance.size_bytes()), radiance.data());
    ++colour_uploads_;
}

void Renderer::draw(const glm::mat4& view_projection, const DrawOptions& options) const {
    glClearColor(options.background.r, options.background.g, options.background.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    // Surfaces are one-sided: a back face is not lit, so it is not drawn either.
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glBindVertexArray(vertex_array_);

    patch_program_.use();
    glUniformMatrix4fv(patch_program_.uniform("view_projection"), 1, GL_FALSE,
                       glm::value_ptr(view_projection));
    glUniform1f(patch_program_.uniform("exposure_scale"), options.exposure_scale);
    glUniform1i(patch_program_.uniform("encode_srgb"), options.encode_srgb ? 1 : 0);
    set_false_colour(options.false_colour);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[kTriangles]);
    // Push the patches back a little so their outline wins the depth test.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    draw_patches();
    glDisable(GL_POLYGON_OFFSET_FILL);

    if (options.outline && outline_index_count_ > 0) {
        outline_program_.use();
        glUniformMatrix4fv(outline_program_.uniform("view_projection"), 1, GL_FALSE,
                           glm::value_ptr(view_projection));
        glUniform3fv(outline_program_.uniform("line_colour"), 1, glm::value_ptr(options.outline_colour));
        glUniform1i(outline_program_.uniform("encode_srgb"), options.encode_srgb ? 1 : 0);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[kOutline]);
        glDrawElements(GL_LINES, static_cast<GLsizei>(outline_index_count_), GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
}

void Renderer::set_false_colour(const std::optional<FalseColourScale>& scale) const {
    glUniform1i(patch_program_.uniform("false_colour"), scale ? 1 : 0);
    if (!scale) return;
    glUniform1f(patch_program_.uniform("false_efficacy"), static_cast<float>(kLuminousEfficacy));
    glUniform1f(patch_program_.uniform("false_low"), static_cast<float>(scale->log10_low));
    glUniform1f(patch_program_.uniform("false_high"), static_cast<float>(scale->log10_high));
    glUniform3fv(patch_program_.uniform("false_stops"), kFalseColourStops,
                 glm::value_ptr(false_colour_stops().front()));
}

void Renderer::draw_patches() const {
    glUniform1i(patch_program_.uniform("albedo_texture"), 0);
    glActiveTexture(GL_TEXTURE0);
    for (const DrawnRange& r : ranges_) {
        if (r.index_count == 0) continue;
        glUniform1i(patch_program_.uniform("textured"), r.texture != 0 ? 1 : 0);
        glUniform3fv(patch_program_.uniform("albedo_scale"), 1, glm::value_ptr(r.albedo_scale));
        glUniform3fv(patch_program_.uniform("emitted_radiance"), 1, glm::value_ptr(r.emitted_radiance));
        glBindTexture(GL_TEXTURE_2D, r.texture);
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(r.index_count), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(r.first_index * sizeof(std::uint32_t)));
    }
    glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace rad
