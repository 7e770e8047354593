#include "gl/scene_image_renderer.hpp"

#include "rad/camera/camera_view.hpp"
#include "rad/display/display_outline.hpp"

namespace rad {

SceneImageRenderer::SceneImageRenderer(const RadiosityPipeline& pipeline, bool outline)
    : pipeline_(pipeline), outline_(outline) {
    const DisplayMesh& display = pipeline.display();
    // glm::uvec3 is three packed uint32 indices, which is how OpenGL reads a triangle list.
    static_assert(sizeof(glm::uvec3) == 3 * sizeof(std::uint32_t));
    const std::span<const std::uint32_t> triangles(
        reinterpret_cast<const std::uint32_t*>(display.triangles.data()), display.triangles.size() * 3);
    renderer_.upload_geometry(display.positions, triangles,
                              outline ? patch_outline(display) : std::vector<std::uint32_t>{});
    renderer_.upload_textures(display.texcoords, display.textured);
    refresh_colours();
}

void SceneImageRenderer::refresh_colours() {
    renderer_.update_colours(pipeline_.vertex_radiance());
}

Image SceneImageRenderer::render(const Camera& camera, int width, int height) const {
    const OffscreenTarget target(width, height);
    draw(camera, target);
    return Image{width, height, target.read_pixels()};
}

void SceneImageRenderer::draw_frame(const Camera& camera, const OffscreenTarget& target) const {
    draw(camera, target);
    glFinish();
}

void SceneImageRenderer::draw(const Camera& camera, const OffscreenTarget& target) const {
    target.bind();
    DrawOptions options;
    options.outline = outline_;
    options.encode_srgb = target.format() == PixelFormat::display_srgb8;
    const double aspect = double(target.width()) / double(target.height());
    renderer_.draw(view_projection(camera, aspect, bounding_box(pipeline_.loaded().scene)), options);
}

}  // namespace rad
