#pragma once

#include <memory>
#include <string>

namespace rad {

// An OpenGL function as a platform's get-proc-address returns it, before it is cast to its real type.
using GlProc = void (*)();

// An OpenGL 3.3 core context made current on the calling thread by one headless platform (EGL, OSMesa).
// Destroying it releases and destroys the context.
class PlatformContext {
  public:
    virtual ~PlatformContext() = default;
    // The platform's address of an OpenGL function, or nullptr.
    virtual GlProc proc_address(const char* name) const = 0;
    // "EGL surfaceless", "EGL device", "OSMesa", ...
    virtual const std::string& label() const = 0;
};

// Adds one attempt's answer ("EGL device: EGL error 0x3001") to a log of attempts separated by "; ".
inline void log_attempt(std::string& log, const std::string& answer) {
    log += (log.empty() ? "" : "; ") + answer;
}

// Each returns nullptr, with what every attempt answered appended to `log`, when its platform gives no
// context.
std::unique_ptr<PlatformContext> make_egl_context(std::string& log);
std::unique_ptr<PlatformContext> make_osmesa_context(std::string& log);

}  // namespace rad
