#include "gl/offscreen_target.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "gl/display_pixels.hpp"

namespace rad {

namespace {

void require_complete(const char* which) {
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        throw std::runtime_error(std::string("the ") + which + " framebuffer is incomplete (status " +
                                 std::to_string(status) + ")");
    }
}

}  // namespace

OffscreenTarget::OffscreenTarget(int width, int height, int samples, PixelFormat format)
    : width_(width), height_(height), format_(format) {
    GLint max_samples = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    samples = std::clamp(samples, 1, std::max(1, static_cast<int>(max_samples)));
    const bool radiance = format == PixelFormat::radiance;
    const GLenum colour = radiance ? GL_RGBA32F : GL_RGBA8;
    const GLenum depth = radiance ? GL_DEPTH_COMPONENT32F : GL_DEPTH_COMPONENT24;

    // One sample is asked for as plain storage: a multisampled buffer of one sample is still drawn as
    // multisampled by some drivers (llvmpipe: two to three times the time per frame).
    const auto storage = [samples, width, height](GLenum format) {
        if (samples > 1) {
            glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
        } else {
            glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
        }
    };
    glGenRenderbuffers(3, renderbuffers_);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
    storage(colour);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
    storage(depth);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[2]);
    glRenderbufferStorage(GL_RENDERBUFFER, colour, width, height);

    glGenFramebuffers(1, &multisampled_fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, multisampled_fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, renderbuffers_[1]);
    require_complete("multisampled");

    glGenFramebuffers(1, &resolved_fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, resolved_fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[2]);
    require_complete("resolve");
}

OffscreenTarget::~OffscreenTarget() {
    glDeleteFramebuffers(1, &multisampled_fbo_);
    glDeleteFramebuffers(1, &resolved_fbo_);
    glDeleteRenderbuffers(3, renderbuffers_);
}

void OffscreenTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, multisampled_fbo_);
    glViewport(0, 0, width_, height_);
    glDisable(GL_FRAMEBUFFER_SRGB);
}

std::vector<glm::vec3> OffscreenTarget::read_pixels() const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_fbo_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_fbo_);
    if (format_ == PixelFormat::display_srgb8) return read_display_pixels(width_, height_);
    std::vector<glm::vec3> bottom_up(static_cast<std::size_t>(width_) * height_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGB, GL_FLOAT, bottom_up.data());
    // OpenGL's rows run bottom to top; images run top to bottom.
    std::vector<glm::vec3> pixels(bottom_up.size());
    for (int y = 0; y < height_; ++y) {
        std::copy_n(bottom_up.begin() + static_cast<std::ptrdiff_t>(y) * width_, width_,
                    pixels.begin() + static_cast<std::ptrdiff_t>(height_ - 1 - y) * width_);
    }
    return pixels;
}

}  // namespace rad
