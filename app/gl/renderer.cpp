#include "gl/renderer.hpp"

#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <vector>

namespace rad {

namespace {

enum Buffer { kPositions = 0, kColours = 1, kTriangles = 2, kOutline = 3 };

}  // namespace

Renderer::Renderer()
    : patch_program_("patch.vert", "patch.frag"), outline_program_("outline.vert", "outline.frag") {
    glGenVertexArrays(1, &vertex_array_);
    glGenBuffers(4, buffers_);
    glBindVertexArray(vertex_array_);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[kPositions]);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[kColours]);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(1);
    glBindVertexArray(0);
}

Renderer::~Renderer() {
    glDeleteBuffers(4, buffers_);
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
    ++geometry_uploads_;
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
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[kTriangles]);
    // Push the patches back a little so their outline wins the depth test.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(triangle_index_count_), GL_UNSIGNED_INT, nullptr);
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

}  // namespace rad
