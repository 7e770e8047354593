#pragma once

#include <memory>
#include <string>

namespace rad {

// An OpenGL 3.3 core context with no window, made current on the calling thread. Tries EGL's surfaceless
// platform (Mesa: llvmpipe or a GPU), then EGL's device platform (NVIDIA), then EGL's default display.
// Rendering goes to framebuffer objects; there is no default framebuffer.
class HeadlessContext {
public:
    // Throws std::runtime_error saying what each attempt answered when none gives a context.
    HeadlessContext();
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    // "EGL surfaceless: OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits)", say.
    const std::string& description() const { return description_; }

private:
    struct Egl;
    std::unique_ptr<Egl> egl_;
    std::string description_;
};

}  // namespace rad
