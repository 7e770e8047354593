#include <GL/osmesa.h>
#include <dlfcn.h>

#include <array>

#include "gl/platform_context.hpp"

namespace rad {

namespace {

// libOSMesa is opened at run time, not linked: it exports the whole OpenGL API under the standard names,
// which would otherwise stand in for libGL's in GLFW and Dear ImGui. It also leaves OSMesa optional.
struct OsMesaApi {
    decltype(&OSMesaCreateContextAttribs) create_context = nullptr;
    decltype(&OSMesaMakeCurrent) make_current = nullptr;
    decltype(&OSMesaDestroyContext) destroy_context = nullptr;
    decltype(&OSMesaGetProcAddress) proc_address = nullptr;
};

template <typename Function>
bool find_symbol(void* library, const char* name, Function& function) {
    function = reinterpret_cast<Function>(dlsym(library, name));
    return function != nullptr;
}

bool open_osmesa(OsMesaApi& api, std::string& why) {
    // Never closed: Mesa's worker threads may outlive the context.
    void* library = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
    if (library == nullptr) library = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
    if (library == nullptr) {
        why = "libOSMesa.so.8 not found";
        return false;
    }
    if (!find_symbol(library, "OSMesaCreateContextAttribs", api.create_context) ||
        !find_symbol(library, "OSMesaMakeCurrent", api.make_current) ||
        !find_symbol(library, "OSMesaDestroyContext", api.destroy_context) ||
        !find_symbol(library, "OSMesaGetProcAddress", api.proc_address)) {
        why = "libOSMesa lacks OSMesaCreateContextAttribs";
        return false;
    }
    return true;
}

class OsMesaContext final : public PlatformContext {
  public:
    OsMesaContext(const OsMesaApi& api, OSMesaContext context) : api_(api), context_(context) {}
    ~OsMesaContext() override {
        api_.make_current(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
        api_.destroy_context(context_);
    }
    OsMesaContext(const OsMesaContext&) = delete;
    OsMesaContext& operator=(const OsMesaContext&) = delete;

    // Rendering goes to framebuffer objects; OSMesa still wants a colour buffer to make a context current.
    bool make_current() { return api_.make_current(context_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1) != 0; }
    GlProc proc_address(const char* name) const override { return api_.proc_address(name); }
    const std::string& label() const override { return label_; }

  private:
    OsMesaApi api_;
    OSMesaContext context_;
    std::array<unsigned char, 4> pixel_{};
    std::string label_ = "OSMesa";
};

}  // namespace

std::unique_ptr<PlatformContext> make_osmesa_context(std::string& log) {
    std::string why;
    OsMesaApi api;
    if (!open_osmesa(api, why)) {
        log_attempt(log, "OSMesa: " + why);
        return nullptr;
    }
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    OSMesaContext context = api.create_context(attributes, nullptr);
    if (context == nullptr) {
        log_attempt(log, "OSMesa: no OpenGL 3.3 core context");
        return nullptr;
    }
    auto made = std::make_unique<OsMesaContext>(api, context);
    if (!made->make_current()) {
        log_attempt(log, "OSMesa: cannot make the context current");
        return nullptr;
    }
    return made;
}

}  // namespace rad
