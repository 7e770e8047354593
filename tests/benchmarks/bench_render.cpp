// Frame time of the renderer on a headless context: one draw of N triangles into a 1024 × 1024 multisampled
// float target, finished on the GPU (glFinish), and the colour-buffer upload after a solver step.
#include <benchmark/benchmark.h>
#include <glad/gl.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "gl/headless_context.hpp"
#include "gl/offscreen_target.hpp"
#include "gl/renderer.hpp"

namespace {

// A square grid of quads (two triangles each) filling the view, about `triangles` triangles.
struct Grid {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> triangles;
    std::vector<glm::vec3> colours;
};

Grid make_grid(std::int64_t triangles) {
    const auto side = static_cast<std::uint32_t>(std::sqrt(double(triangles) / 2.0));
    Grid g;
    for (std::uint32_t y = 0; y <= side; ++y) {
        for (std::uint32_t x = 0; x <= side; ++x) {
            g.positions.emplace_back(2.0f * x / side - 1.0f, 2.0f * y / side - 1.0f, 0.0f);
            g.colours.emplace_back(float(x) / side, float(y) / side, 0.5f);
        }
    }
    for (std::uint32_t y = 0; y < side; ++y) {
        for (std::uint32_t x = 0; x < side; ++x) {
            const std::uint32_t a = y * (side + 1) + x, b = a + 1, c = a + side + 2, d = a + side + 1;
            g.triangles.insert(g.triangles.end(), {a, b, c, a, c, d});
        }
    }
    return g;
}

void BM_Frame(benchmark::State& state) {
    const rad::HeadlessContext context;
    rad::Renderer renderer;
    const Grid grid = make_grid(state.range(0));
    renderer.upload_geometry(grid.positions, grid.triangles, {});
    renderer.update_colours(grid.colours);
    rad::OffscreenTarget target(1024, 1024);
    target.bind();
    const glm::mat4 view = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, -1.0f, 1.0f);
    for (auto _ : state) {
        renderer.draw(view, {});
        glFinish();
    }
    state.counters["triangles"] = double(grid.triangles.size() / 3);
    state.SetLabel(context.description());
}
BENCHMARK(BM_Frame)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ColourUpload(benchmark::State& state) {
    const rad::HeadlessContext context;
    rad::Renderer renderer;
    const Grid grid = make_grid(state.range(0));
    renderer.upload_geometry(grid.positions, grid.triangles, {});
    for (auto _ : state) {
        renderer.update_colours(grid.colours);
        glFinish();
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) *
                            std::int64_t(grid.colours.size() * sizeof(glm::vec3)));
}
BENCHMARK(BM_ColourUpload)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
