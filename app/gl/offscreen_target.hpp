#pragma once

#include <glad/gl.h>

#include <glm/vec3.hpp>
#include <vector>

namespace rad {

// What a target stores.
// radiance:      float RGBA and a float depth buffer: radiance exact for the linear images (EXR, PFM); PNG
//                encoding happens on the CPU afterwards. What `render` draws into.
// display_srgb8: 8-bit sRGB codes, written by the shader (DrawOptions::encode_srgb), and a 24-bit depth
//                buffer, as the viewer's window has: what a frame costs there.
enum class PixelFormat { radiance, display_srgb8 };

// A framebuffer to draw into (multisampled when samples > 1), resolved and read back as linear RGB.
class OffscreenTarget {
  public:
    OffscreenTarget(int width, int height, int samples = 4, PixelFormat format = PixelFormat::radiance);
    ~OffscreenTarget();
    OffscreenTarget(const OffscreenTarget&) = delete;
    OffscreenTarget& operator=(const OffscreenTarget&) = delete;

    // Binds it for drawing (the framebuffer's own sRGB encoding off: the shader encodes).
    void bind() const;
    PixelFormat format() const { return format_; }
    // Resolves the samples and returns width × height RGB values, top row first: radiance, or for the
    // display format the decoded display values (clamped to [0, 1]).
    std::vector<glm::vec3> read_pixels() const;

    int width() const { return width_; }
    int height() const { return height_; }

  private:
    int width_;
    int height_;
    PixelFormat format_;
    GLuint multisampled_fbo_ = 0;
    GLuint resolved_fbo_ = 0;
    GLuint renderbuffers_[3] = {};  // multisampled colour, multisampled depth, resolved colour
};

}  // namespace rad
