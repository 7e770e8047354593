#include "gl/headless_context.hpp"

#include <glad/gl.h>

#include <stdexcept>

#include "gl/platform_context.hpp"

namespace rad {

namespace {

GLADapiproc load_function(void* platform, const char* name) {
    return static_cast<const PlatformContext*>(platform)->proc_address(name);
}

std::unique_ptr<PlatformContext> make_platform_context(HeadlessPlatform platform, std::string& log) {
    std::unique_ptr<PlatformContext> context;
    if (platform != HeadlessPlatform::osmesa) context = make_egl_context(log);
    if (!context && platform != HeadlessPlatform::egl) context = make_osmesa_context(log);
    return context;
}

std::string gl_string(GLenum name) {
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text != nullptr ? text : "?";
}

}  // namespace

HeadlessContext::HeadlessContext(HeadlessPlatform platform) {
    std::string log;
    platform_ = make_platform_context(platform, log);
    if (!platform_) throw std::runtime_error("no headless OpenGL 3.3 context: " + log);
    if (gladLoadGLUserPtr(load_function, platform_.get()) < GLAD_MAKE_VERSION(3, 3)) {
        throw std::runtime_error("no headless OpenGL 3.3 context: " + platform_->label() +
                                 " lacks OpenGL 3.3 core functions");
    }
    description_ = platform_->label() + ": OpenGL " + gl_string(GL_VERSION) + ", " + gl_string(GL_RENDERER);
}

HeadlessContext::~HeadlessContext() = default;

}  // namespace rad
