#pragma once

#include <memory>
#include <string>

namespace rad {

class PlatformContext;

// Where a headless context comes from. `automatic` tries EGL, then OSMesa when EGL gives no context.
enum class HeadlessPlatform { automatic, egl, osmesa };

// An OpenGL 3.3 core context with no window, made current on the calling thread, with the OpenGL functions
// loaded for it. EGL tries its surfaceless platform (Mesa: llvmpipe or a GPU), then its device platform
// (NVIDIA), then its default display; OSMesa renders on the CPU. Rendering goes to framebuffer objects.
class HeadlessContext {
  public:
    // Throws std::runtime_error saying what each attempt answered when none gives a context.
    explicit HeadlessContext(HeadlessPlatform platform = HeadlessPlatform::automatic);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    // "EGL surfaceless: OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits)", say.
    const std::string& description() const { return description_; }

  private:
    std::unique_ptr<PlatformContext> platform_;
    std::string description_;
};

}  // namespace rad
