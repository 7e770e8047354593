#include "gl/headless_context.hpp"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace rad {

struct HeadlessContext::Egl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
};

namespace {

std::string egl_error_text() {
    char text[32];
    std::snprintf(text, sizeof text, "EGL error 0x%04x", eglGetError());
    return text;
}

bool has_client_extension(const char* name) {
    const char* extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    return extensions != nullptr && epoxy_extension_in_string(extensions, name);
}

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
    EGLContext context =
        eglCreateContext(display, configs > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, context_attributes);
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


std::vector<EGLDisplay> device_displays() {
    std::vector<EGLDisplay> displays;
    if (!has_client_extension("EGL_EXT_device_enumeration") || !has_client_extension("EGL_EXT_platform_device")) {
        return displays;
    }
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

HeadlessContext::HeadlessContext() : egl_(std::make_unique<Egl>()) {
    std::string log;
    auto attempt = [&](EGLDisplay display, const char* label) {
        if (display == EGL_NO_DISPLAY) {
            log += std::string(log.empty() ? "" : "; ") + label + ": no display";
            return false;
        }
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display, &major, &minor)) {
            log += std::string(log.empty() ? "" : "; ") + label + ": " + egl_error_text();
            return false;
        }
        std::string why;
        const EGLContext context = make_core_context(display, why);
        if (context == EGL_NO_CONTEXT) {
            log += std::string(log.empty() ? "" : "; ") + label + ": " + why;
            eglTerminate(display);
            return false;
        }
        egl_->display = display;
        egl_->context = context;
        description_ = std::string(label) + ": OpenGL " + reinterpret_cast<const char*>(glGetString(GL_VERSION)) +
                       ", " + reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        return true;
    };

    if (has_client_extension("EGL_MESA_platform_surfaceless") &&
        attempt(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
                "EGL surfaceless")) {
        return;
    }
    for (EGLDisplay display : device_displays()) {
        if (attempt(display, "EGL device")) return;
    }
    if (attempt(eglGetDisplay(EGL_DEFAULT_DISPLAY), "EGL default display")) return;
    throw std::runtime_error("no headless OpenGL 3.3 context: " + (log.empty() ? "EGL offers no display" : log));
}

HeadlessContext::~HeadlessContext() {
    if (egl_->context != EGL_NO_CONTEXT) {
        eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(egl_->display, egl_->context);
        eglTerminate(egl_->display);
    }
}

}  // namespace rad
