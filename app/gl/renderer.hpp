#pragma once

#include <glad/gl.h>

#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include "gl/shader_program.hpp"
#include "rad/display/display_mesh.hpp"
#include "rad/display/false_colour.hpp"

namespace rad {

struct DrawOptions {
    float exposure_scale = 1.0f;  // 1 for linear output; 2^exposure for the window
    // Write the sRGB code of clamp(L · exposure_scale), for 8-bit framebuffers that do not encode (the
    // viewer's window, display targets); off for float targets, which take radiance.
    bool encode_srgb = false;
    bool outline = false;  // draw patch edges over the patches
    glm::vec3 outline_colour{0.0f};
    glm::vec3 background{0.0f};
    // Luminance in false colours over this scale instead of the radiance (rad/display/false_colour.hpp).
    std::optional<FalseColourScale> false_colour;
};

// The one OpenGL renderer, for the window and for headless images alike: it draws whatever framebuffer is
// bound. Geometry is uploaded once; after each solver step only the per-vertex colour buffer changes.
// Needs a current OpenGL 3.3 core context for its whole life.
class Renderer {
  public:
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Triangles over per-vertex positions, and patch edges as pairs of vertex indices.
    void upload_geometry(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangles,
                         std::span<const std::uint32_t> outline_lines);
    // Texel detail for the geometry last uploaded (which drops any earlier): texture coordinates per vertex
    // and the runs of triangles drawn with a texture, whose vertices' colours are irradiance / π (see
    // DisplayMesh). Each distinct texture is uploaded once, as an sRGB texture with mipmaps.
    void upload_textures(std::span<const glm::vec2> texcoords,
                         std::span<const DisplayMesh::TexturedRange> ranges);
    // Linear radiance per vertex (as many as the positions uploaded).
    void update_colours(std::span<const glm::vec3> radiance);
    void draw(const glm::mat4& view_projection, const DrawOptions& options) const;

    std::size_t geometry_uploads() const { return geometry_uploads_; }
    std::size_t colour_uploads() const { return colour_uploads_; }

  private:
    struct DrawnRange {
        std::size_t first_index = 0;
        std::size_t index_count = 0;
        GLuint texture = 0;  // 0: untextured
        glm::vec3 albedo_scale{1.0f};
        glm::vec3 emitted_radiance{0.0f};
    };
    GLuint texture_of(const std::shared_ptr<const Texture>& texture);
    void release_textures();
    void draw_patches() const;
    void set_false_colour(const std::optional<FalseColourScale>& scale) const;

    std::vector<DrawnRange> ranges_;  // covering every triangle, in order
    std::map<const Texture*, GLuint> textures_;
    ShaderProgram patch_program_;
    ShaderProgram outline_program_;
    GLuint vertex_array_ = 0;
    GLuint buffers_[5] = {};  // positions, colours, triangle indices, outline indices, texture coordinates
    std::size_t vertex_count_ = 0;
    std::size_t triangle_index_count_ = 0;
    std::size_t outline_index_count_ = 0;
    std::size_t geometry_uploads_ = 0;
    std::size_t colour_uploads_ = 0;
};

}  // namespace rad
