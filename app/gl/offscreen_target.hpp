#pragma once

#include <glad/gl.h>

#include <glm/vec3.hpp>
#include <vector>

namespace rad {

// A multisampled float framebuffer to draw into, resolved and read back as linear RGB. Float storage keeps
// radiance exact for the linear images (EXR, PFM); PNG encoding happens on the CPU afterwards.
class OffscreenTarget {
  public:
    OffscreenTarget(int width, int height, int samples = 4);
    ~OffscreenTarget();
    OffscreenTarget(const OffscreenTarget&) = delete;
    OffscreenTarget& operator=(const OffscreenTarget&) = delete;

    void bind() const;
    // Resolves the samples and returns width × height RGB values, top row first.
    std::vector<glm::vec3> read_pixels() const;

    int width() const { return width_; }
    int height() const { return height_; }

  private:
    int width_;
    int height_;
    GLuint multisampled_fbo_ = 0;
    GLuint resolved_fbo_ = 0;
    GLuint renderbuffers_[3] = {};  // multisampled colour, multisampled depth, resolved colour
};

}  // namespace rad
