#include <glad/egl.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "gl/platform_context.hpp"

namespace rad {

namespace {

std::string egl_error_text() {
    char text[32];
    std::snprintf(text, sizeof text, "EGL error 0x%04x", eglGetError());
    return text;
}

class EglContext final : public PlatformContext {
  public:
    EglContext(EGLDisplay display, EGLContext context, std::string label)
        : display_(display), context_(context), label_(std::move(label)) {}
    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    GlProc proc_address(const char* name) const override { return eglGetProcAddress(name); }
    const std::string& label() const override { return label_; }

  private:
    EGLDisplay display_;
    EGLContext context_;
    std::string label_;
};

// Creates an OpenGL 3.3 core context on an initialized display and makes it current without a surface.
EGLContext make_core_context(EGLDisplay display, std::string& why) {
    if (!eglBindAPI(EGL_OPENGL_API)) {
        why = "no desktop OpenGL (" + egl_error_text() + ")";
        return EGL_NO_CONTEXT;
    }
    const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    eglChooseConfig(display, config_attributes, &config, 1, &configs);
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         3,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         3,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
    // EGL_KHR_no_config_context lets a config-less context exist; otherwise use the config found.
    EGLContext context = eglCreateContext(display, configs > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT,
                                          context_attributes);
    if (context == EGL_NO_CONTEXT) {
        why = "no OpenGL 3.3 core context (" + egl_error_text() + ")";
        return EGL_NO_CONTEXT;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        why = "cannot make the context current without a surface (" + egl_error_text() + ")";
        eglDestroyContext(display, context);
        return EGL_NO_CONTEXT;
    }
    return context;
}

std::unique_ptr<PlatformContext> try_display(EGLDisplay display, const char* label, std::string& log) {
    if (display == EGL_NO_DISPLAY) {
        log_attempt(log, std::string(label) + ": no display");
        return nullptr;
    }
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) {
        log_attempt(log, std::string(label) + ": " + egl_error_text());
        return nullptr;
    }
    // The display's own version decides which core EGL functions exist beyond 1.0.
    if (gladLoaderLoadEGL(display) == 0) {
        log_attempt(log, std::string(label) + ": cannot load its EGL functions");
        eglTerminate(display);
        return nullptr;
    }
    std::string why;
    const EGLContext context = make_core_context(display, why);
    if (context == EGL_NO_CONTEXT) {
        log_attempt(log, std::string(label) + ": " + why);
        eglTerminate(display);
        return nullptr;
    }
    return std::make_unique<EglContext>(display, context, label);
}

std::vector<EGLDisplay> device_displays() {
    std::vector<EGLDisplay> displays;
    if (!GLAD_EGL_EXT_device_enumeration || !GLAD_EGL_EXT_platform_device) return displays;
    EGLint count = 0;
    eglQueryDevicesEXT(0, nullptr, &count);
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(std::max(count, 0)));
    if (count > 0) eglQueryDevicesEXT(count, devices.data(), &count);
    for (EGLDeviceEXT device : devices) {
        displays.push_back(eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr));
    }
    return displays;
}

}  // namespace

// Tries EGL's surfaceless platform (Mesa: llvmpipe or a GPU), then its device platform (NVIDIA), then its
// default display.
std::unique_ptr<PlatformContext> make_egl_context(std::string& log) {
    // Without a display this loads libEGL and the client extensions (platforms, devices).
    if (gladLoaderLoadEGL(EGL_NO_DISPLAY) == 0) {
        log_attempt(log, "EGL: libEGL.so.1 not found");
        return nullptr;
    }
    if (GLAD_EGL_MESA_platform_surfaceless && GLAD_EGL_EXT_platform_base) {
        auto display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (auto context = try_display(display, "EGL surfaceless", log)) return context;
    }
    for (EGLDisplay display : device_displays()) {
        if (auto context = try_display(display, "EGL device", log)) return context;
    }
    return try_display(eglGetDisplay(EGL_DEFAULT_DISPLAY), "EGL default display", log);
}

}  // namespace rad
