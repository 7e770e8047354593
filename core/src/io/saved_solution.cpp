// The saved-solution file (`solve --save`). Payload, in order (u64 counts, f64 doubles, f32 floats, u8
// booleans, strings as u64 length + UTF-8 bytes, dvec3 as three f64):
//   u64 n, the element count (first, so a forged count is refused before anything else is read)
//   settings: scene_source, f64 patch_size, subdivision, f64 refine_tolerance, f64 min_patch_size,
//             form_factor_method, i64 rays, u64 seed, u8 reciprocity, u8 normalize_rows, solver,
//             f64 tolerance, u64 bounces, initial, f64 relaxation
//   scene:    u8 has_camera [dvec3 eye, target, up, f64 fov]; u64 surfaces; per surface: name, material
//             name, dvec3 ρ, dvec3 Le, u64 vertices, dvec3 each, u64 faces, per face u32 k and k u32 indices
//   patches:  u64 points, dvec3 each, then as many float3 positions; u64 patches (= n), u32×4 corners each;
//             per patch u32 surface, u32 face, f64 area, dvec3 centroid, dvec3 normal; u64 + u32
//             surface_begin; u64 + u32 outline_begin; u64 + u32 outline
//   elements: n f64 area, n dvec3 ρ, n dvec3 E, n dvec3 solution, n dvec3 display solution, n dvec3 ρH_d
//   display gather: u64 + u32 row offsets (none, or display patches + 1), u64 + u32 elements, as many f32
//             weights
//   report:   u64 steps, f64 residual, status, status_message
#include "rad/io/saved_solution.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <glm/geometric.hpp>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "rad/io/atomic_file.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/scene_transport.hpp"
#include "rad/util/error.hpp"
#include "rad/util/file_names.hpp"

namespace rad {

namespace {

class Writer {
  public:
    void u8(std::uint8_t v) { bytes_.push_back(static_cast<char>(v)); }
    void u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i) u8(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    void u64(std::uint64_t v) {
        for (int i = 0; i < 8; ++i) u8(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    void f64(double v) {
        if (!std::isfinite(v)) throw std::invalid_argument("saved solution: a value is not finite");
        u64(std::bit_cast<std::uint64_t>(v));
    }
    void f32(float v) {
        if (!std::isfinite(v)) throw std::invalid_argument("saved solution: a value is not finite");
        u32(std::bit_cast<std::uint32_t>(v));
    }
    void vec(const glm::dvec3& v) {
        f64(v.x);
        f64(v.y);
        f64(v.z);
    }
    void text(const std::string& s) {
        u64(s.size());
        bytes_ += s;
    }
    void count(std::size_t n) { u64(n); }
    void indices(const std::vector<std::uint32_t>& v) {
        count(v.size());
        for (std::uint32_t i : v) u32(i);
    }

    std::string& bytes() { return bytes_; }

  private:
    std::string bytes_;
};

// Reads the payload, refusing with InputError("NAME: ...") whatever does not fit.
class Reader {
  public:
    Reader(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

    [[noreturn]] void fail(const std::string& what) const { throw InputError(name_ + ": " + what); }

    std::size_t left() const { return bytes_.size() - at_; }
    void need(std::size_t n, const char* what) const {
        if (n > left()) {
            fail(std::string("truncated: ") + what + " needs " + std::to_string(n) + " bytes, " +
                 std::to_string(left()) + " are left");
        }
    }

    std::uint8_t u8(const char* what) {
        need(1, what);
        return static_cast<std::uint8_t>(bytes_[at_++]);
    }
    std::uint32_t u32(const char* what) {
        need(4, what);
        std::uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= std::uint32_t(static_cast<std::uint8_t>(bytes_[at_++])) << (8 * i);
        return v;
    }
    std::uint64_t u64(const char* what) {
        need(8, what);
        std::uint64_t v = 0;
        for (int i = 0; i < 8; ++i) v |= std::uint64_t(static_cast<std::uint8_t>(bytes_[at_++])) << (8 * i);
        return v;
    }
    bool flag(const char* what) {
        const std::uint8_t v = u8(what);
        if (v > 1) fail(std::string(what) + " is " + std::to_string(v) + ", not 0 or 1");
        return v == 1;
    }
    double f64(const char* what) {
        const double v = std::bit_cast<double>(u64(what));
        if (!std::isfinite(v)) fail(std::string(what) + " is not a finite number");
        return v;
    }
    float f32(const char* what) {
        const float v = std::bit_cast<float>(u32(what));
        if (!std::isfinite(v)) fail(std::string(what) + " is not a finite number");
        return v;
    }
    glm::dvec3 vec(const char* what) {
        const double x = f64(what);
        const double y = f64(what);
        return {x, y, f64(what)};
    }
    // A count of items of at least item_bytes each, checked against the bytes left before anyone allocates.
    std::size_t count(const char* what, std::size_t item_bytes) {
        const std::uint64_t n = u64(what);
        if (n > left() / item_bytes) {
            fail(std::string(what) + " " + std::to_string(n) + " does not fit the file (" +
                 std::to_string(left()) + " bytes left)");
        }
        return static_cast<std::size_t>(n);
    }
    std::string text(const char* what) {
        const std::size_t n = count(what, 1);
        std::string s(bytes_.substr(at_, n));
        at_ += n;
        return s;
    }
    // Indices below `bound`.
    std::vector<std::uint32_t> indices(const char* what, std::size_t bound) {
        std::vector<std::uint32_t> v(count(what, 4));
        for (std::uint32_t& i : v) {
            i = u32(what);
            if (i >= bound) fail(std::string(what) + " " + std::to_string(i) + " is out of range");
        }
        return v;
    }

  private:
    std::string_view bytes_;
    const std::string& name_;
    std::size_t at_ = 0;
};

void write_settings(Writer& w, const SolutionSettings& s) {
    w.text(s.scene_source);
    w.f64(s.patch_size);
    w.text(s.subdivision);
    w.f64(s.refine_tolerance);
    w.f64(s.min_patch_size);
    w.text(s.form_factor_method);
    w.u64(static_cast<std::uint64_t>(s.rays));
    w.u64(s.seed);
    w.u8(s.reciprocity);
    w.u8(s.normalize_rows);
    w.text(s.solver);
    w.f64(s.tolerance);
    w.u64(s.bounces);
    w.text(s.initial);
    w.f64(s.relaxation);
}

template <typename Names>
void check_name(const Reader& r, const char* what, const std::string& name, const Names& names) {
    std::string list;
    for (const auto& n : names) {
        if (name == n) return;
        list += (list.empty() ? "" : ", ") + std::string(n);
    }
    r.fail(std::string(what) + " '" + name + "' is none of " + list);
}

SolutionSettings read_settings(Reader& r) {
    SolutionSettings s;
    s.scene_source = r.text("scene source");
    s.patch_size = r.f64("patch size");
    if (s.patch_size <= 0.0) r.fail("patch size must be positive");
    s.subdivision = r.text("subdivision");
    std::vector<std::string_view> subdivisions;
    for (Subdivision d : all_subdivisions()) subdivisions.push_back(subdivision_name(d));
    check_name(r, "subdivision", s.subdivision, subdivisions);
    s.refine_tolerance = r.f64("refinement tolerance");
    s.min_patch_size = r.f64("smallest patch size");
    if (s.refine_tolerance < 0.0 || s.min_patch_size < 0.0) r.fail("a refinement setting is negative");
    s.form_factor_method = r.text("form-factor method");
    check_name(r, "form-factor method", s.form_factor_method,
               std::vector<std::string_view>{"hemisphere", "analytic"});
    const std::uint64_t rays = r.u64("rays");
    if (rays > std::uint64_t(std::numeric_limits<int>::max()))
        r.fail("rays " + std::to_string(rays) + " is out of range");
    s.rays = static_cast<std::int64_t>(rays);
    s.seed = r.u64("seed");
    s.reciprocity = r.flag("reciprocity");
    s.normalize_rows = r.flag("row normalization");
    s.solver = r.text("solver");
    std::vector<std::string_view> solvers;
    for (SolverMethod m : all_solver_methods()) solvers.push_back(solver_method_name(m));
    check_name(r, "solver", s.solver, solvers);
    s.tolerance = r.f64("tolerance");
    if (s.tolerance < 0.0) r.fail("tolerance is negative");
    s.bounces = r.u64("step limit");
    s.initial = r.text("initial guess");
    check_name(r, "initial guess", s.initial, std::vector<std::string_view>{"emission", "direct"});
    s.relaxation = r.f64("relaxation");
    if (s.relaxation <= 0.0 || s.relaxation >= 2.0) r.fail("relaxation must lie in (0, 2)");
    return s;
}

void write_scene(Writer& w, const Scene& scene) {
    w.u8(scene.camera.has_value());
    if (scene.camera) {
        w.vec(scene.camera->eye);
        w.vec(scene.camera->target);
        w.vec(scene.camera->up);
        w.f64(scene.camera->fov_degrees);
    }
    w.u32(static_cast<std::uint32_t>(scene.sky.kind));
    w.vec(scene.sky.radiance);
    w.vec(scene.sun.direction);
    w.vec(scene.sun.irradiance);
    w.count(scene.surfaces.size());
    for (const Surface& surface : scene.surfaces) {
        w.text(surface.name);
        w.text(surface.material.name);
        w.vec(surface.material.reflectance);
        w.vec(surface.material.emission);
        w.u8(surface.material.two_sided);
        w.u8(surface.back_to_back);
        const SurfaceMesh& mesh = surface.mesh;
        // Compact indices, in case the mesh has deleted vertices.
        std::vector<std::uint32_t> index(mesh.n_vertices(), 0);
        std::uint32_t next = 0;
        for (auto v : mesh.vertices()) index[v.idx()] = next++;
        w.count(next);
        for (auto v : mesh.vertices()) w.vec(to_glm(mesh.point(v)));
        w.count(std::distance(mesh.faces().begin(), mesh.faces().end()));
        for (auto f : mesh.faces()) {
            // A face's vertices in OpenMesh's order, which add_face keeps: the mesh is made again as it was.
            std::vector<std::uint32_t> corners;
            for (auto v : mesh.fv_range(f)) corners.push_back(index[v.idx()]);
            w.u32(static_cast<std::uint32_t>(corners.size()));
            for (std::uint32_t c : corners) w.u32(c);
        }
    }
}

void read_outside_light(Reader& r, Scene& scene) {
    const std::uint32_t kind = r.u32("sky kind");
    if (kind > static_cast<std::uint32_t>(Sky::Kind::overcast)) r.fail("sky kind " + std::to_string(kind));
    scene.sky.kind = static_cast<Sky::Kind>(kind);
    scene.sky.radiance = r.vec("sky radiance");
    scene.sun.direction = r.vec("sun direction");
    scene.sun.irradiance = r.vec("sun irradiance");
    const auto non_negative = [](const glm::dvec3& c) { return c.x >= 0.0 && c.y >= 0.0 && c.z >= 0.0; };
    if (!non_negative(scene.sky.radiance) || !non_negative(scene.sun.irradiance))
        r.fail("a negative sky radiance or sun irradiance");
    if (std::abs(glm::length(scene.sun.direction) - 1.0) > 1e-9)
        r.fail("the sun's direction is not a unit vector");
}

Scene read_scene(Reader& r) {
    Scene scene;
    if (r.flag("camera flag")) {
        Camera camera;
        camera.eye = r.vec("camera eye");
        camera.target = r.vec("camera target");
        camera.up = r.vec("camera up");
        camera.fov_degrees = r.f64("camera field of view");
        if (camera.fov_degrees <= 0.0 || camera.fov_degrees >= 180.0)
            r.fail("camera field of view out of range");
        scene.camera = camera;
    }
    read_outside_light(r, scene);
    // The smallest surface: two empty strings, two colours, two flags and two counts.
    const std::size_t surfaces = r.count("surface count", 16 + 48 + 2 + 16);
    scene.surfaces.resize(surfaces);
    for (std::size_t s = 0; s < surfaces; ++s) {
        Surface& surface = scene.surfaces[s];
        surface.name = r.text("surface name");
        surface.material.name = r.text("material name");
        surface.material.reflectance = r.vec("reflectance");
        surface.material.emission = r.vec("emission");
        surface.material.two_sided = r.flag("two-sided flag");
        surface.back_to_back = r.flag("back-to-back flag");
        try {
            validate_material(surface.material, "surface " + std::to_string(s));
        } catch (const InputError& e) {
            r.fail(e.what());
        }
        const std::size_t vertices = r.count("vertex count", 24);
        std::vector<SurfaceMesh::VertexHandle> handles(vertices);
        for (auto& h : handles) {
            const glm::dvec3 p = r.vec("vertex");
            h = surface.mesh.add_vertex(SurfaceMesh::Point(p.x, p.y, p.z));
        }
        const std::size_t faces = r.count("face count", 4 + 3 * 4);
        std::vector<SurfaceMesh::VertexHandle> corners;
        for (std::size_t f = 0; f < faces; ++f) {
            const std::uint32_t k = r.u32("face corner count");
            if (k < 3 || k > r.left() / 4) {
                r.fail("surface " + std::to_string(s) + " face " + std::to_string(f) + ": corner count " +
                       std::to_string(k) + " is out of range");
            }
            corners.clear();
            for (std::uint32_t c = 0; c < k; ++c) {
                const std::uint32_t i = r.u32("face corner");
                if (i >= vertices) {
                    r.fail("surface " + std::to_string(s) + " face " + std::to_string(f) + ": corner " +
                           std::to_string(i) + " is out of range");
                }
                corners.push_back(handles[i]);
            }
            if (!surface.mesh.add_face(corners).is_valid()) {
                r.fail("surface " + std::to_string(s) + " face " + std::to_string(f) + " is not manifold");
            }
        }
    }
    return scene;
}

void write_patches(Writer& w, const PatchMesh& m) {
    if (m.positions.size() != m.points.size())
        throw std::invalid_argument("saved solution: positions differ");
    w.count(m.points.size());
    for (const glm::dvec3& p : m.points) w.vec(p);
    for (const glm::vec3& p : m.positions) {
        w.f32(p.x);
        w.f32(p.y);
        w.f32(p.z);
    }
    w.count(m.corners.size());
    for (const glm::uvec4& c : m.corners)
        for (int k = 0; k < 4; ++k) w.u32(c[k]);
    for (const Patch& p : m.patches) {
        w.u32(p.surface);
        w.u32(p.face);
        w.f64(p.area);
        w.vec(p.centroid);
        w.vec(p.normal);
    }
    w.indices(m.surface_begin);
    w.indices(m.outline_begin);
    w.indices(m.outline);
}

PatchMesh read_patches(Reader& r, std::size_t elements, const Scene& scene) {
    const std::size_t surfaces = scene.surfaces.size();
    PatchMesh m;
    // A point is its double corner and its float copy: 36 bytes.
    const std::size_t points = r.count("point count", 36);
    m.points.resize(points);
    for (glm::dvec3& p : m.points) p = r.vec("point");
    m.positions.resize(points);
    for (glm::vec3& p : m.positions) {
        const float x = r.f32("position");
        const float y = r.f32("position");
        p = {x, y, r.f32("position")};
    }
    // A patch is 16 bytes of corners and 8 + 56 of its measures.
    const std::size_t patches = r.count("patch count", 80);
    if (patches != elements) {
        r.fail("patch count " + std::to_string(patches) + " differs from the element count " +
               std::to_string(elements));
    }
    m.corners.resize(patches);
    for (glm::uvec4& c : m.corners) {
        for (int k = 0; k < 4; ++k) {
            c[k] = r.u32("patch corner");
            if (c[k] >= points) r.fail("patch corner " + std::to_string(c[k]) + " is out of range");
        }
    }
    m.patches.resize(patches);
    for (Patch& p : m.patches) {
        p.surface = r.u32("patch surface");
        if (p.surface >= surfaces) r.fail("patch surface " + std::to_string(p.surface) + " is out of range");
        p.face = r.u32("patch face");
        if (p.face >= scene.surfaces[p.surface].mesh.n_faces())
            r.fail("patch face " + std::to_string(p.face) + " is out of range");
        p.area = r.f64("patch area");
        if (p.area < 0.0) r.fail("a patch area is negative");
        p.centroid = r.vec("patch centroid");
        p.normal = r.vec("patch normal");
    }
    const auto offsets = [&](const char* what, std::size_t expected_size, std::size_t last) {
        std::vector<std::uint32_t> v = r.indices(what, last + 1);
        if (v.size() != expected_size || v.front() != 0 || v.back() != last ||
            !std::is_sorted(v.begin(), v.end())) {
            r.fail(std::string(what) + " are not " + std::to_string(expected_size) +
                   " ascending offsets from 0 to " + std::to_string(last));
        }
        return v;
    };
    m.surface_begin = offsets("surface offsets", surfaces + 1, patches);
    // A conforming mesh has no outlines: both lists empty.
    m.outline_begin = r.indices("outline offsets", std::numeric_limits<std::uint32_t>::max());
    m.outline = r.indices("outline corner", points);
    if (m.outline_begin.empty()) {
        if (!m.outline.empty()) r.fail("outline corners without outline offsets");
    } else if (m.outline_begin.size() != patches + 1 || m.outline_begin.front() != 0 ||
               m.outline_begin.back() != m.outline.size() ||
               !std::is_sorted(m.outline_begin.begin(), m.outline_begin.end())) {
        r.fail("outline offsets are not " + std::to_string(patches + 1) +
               " ascending offsets from 0 to the outline's length");
    }
    return m;
}

GatherTable read_display_gather(Reader& r, std::size_t elements) {
    GatherTable g;
    g.row_begin = r.indices("display gather offset", std::numeric_limits<std::uint32_t>::max());
    g.patch = r.indices("display gather element", elements);
    const bool ascending = g.row_begin.empty()
                               ? g.patch.empty()
                               : g.row_begin.front() == 0 && g.row_begin.back() == g.patch.size() &&
                                     std::is_sorted(g.row_begin.begin(), g.row_begin.end());
    if (!ascending) r.fail("the display gather's offsets are not ascending from 0 to its entries");
    g.weight.resize(g.patch.size());
    for (float& x : g.weight) {
        x = r.f32("display gather weight");
        if (x < 0.0f) r.fail("a display gather weight is negative");
    }
    return g;
}

}  // namespace

bool is_saved_solution_path(const std::filesystem::path& path) {
    return lowercase_extension(path.string()) == ".radiosity";
}

std::uint64_t saved_solution_checksum(std::string_view payload) {
    std::uint64_t hash = 0xcbf29ce484222325ull;
    for (char c : payload) {
        hash ^= static_cast<std::uint8_t>(c);
        hash *= 0x100000001b3ull;
    }
    return hash;
}

std::string encode_saved_solution(const SavedSolution& saved) {
    const Solution& solution = saved.solution;
    if (!solution.elements) throw std::invalid_argument("saved solution: no elements");
    const std::size_t n = solution.size();
    if (solution.area.size() != n || solution.reflectance.size() != n || solution.emission.size() != n ||
        solution.radiosity.size() != n || solution.shown_radiosity.size() != n ||
        solution.direct.size() != n || (!solution.outside.empty() && solution.outside.size() != n)) {
        throw std::invalid_argument("saved solution: per-element arrays differ from the patch count");
    }
    const GatherTable& gather = saved.display_gather;
    if (gather.patch.size() != gather.weight.size() ||
        (!gather.empty() && gather.row_begin.back() != gather.patch.size())) {
        throw std::invalid_argument("saved solution: the display gather's table is inconsistent");
    }
    Writer w;
    w.count(n);
    write_settings(w, solution.settings);
    write_scene(w, saved.scene);
    write_patches(w, *solution.elements);
    for (double a : solution.area) w.f64(a);
    for (const auto* values : {&solution.reflectance, &solution.emission, &solution.radiosity,
                               &solution.shown_radiosity, &solution.direct})
        for (const glm::dvec3& v : *values) w.vec(v);
    w.u8(solution.outside.empty() ? 0 : 1);
    for (const glm::dvec3& v : solution.outside) w.vec(v);
    const GatherTable& g = saved.display_gather;
    w.indices(g.row_begin);
    w.indices(g.patch);
    for (float x : g.weight) w.f32(x);
    w.u64(solution.report.steps);
    w.f64(solution.report.residual);
    w.text(solution.report.status);
    w.text(solution.report.status_message);

    Writer header;
    header.bytes() = std::string(kSavedSolutionMagic);
    header.u32(kSavedSolutionVersion);
    header.u32(0);
    header.u64(w.bytes().size());
    header.u64(saved_solution_checksum(w.bytes()));
    return header.bytes() + w.bytes();
}

SavedSolution decode_saved_solution(std::string_view bytes, const std::string& name) {
    Reader head(bytes.substr(0, std::min(bytes.size(), kSavedSolutionHeaderBytes)), name);
    if (bytes.size() < kSavedSolutionMagic.size() ||
        bytes.substr(0, kSavedSolutionMagic.size()) != kSavedSolutionMagic) {
        head.fail("not a saved radiosity solution (wrong magic)");
    }
    if (bytes.size() < kSavedSolutionHeaderBytes) head.fail("truncated: the header is incomplete");
    for (std::size_t i = 0; i < kSavedSolutionMagic.size(); ++i) head.u8("magic");
    const std::uint32_t version = head.u32("version");
    if (version != kSavedSolutionVersion) {
        head.fail("format version " + std::to_string(version) + "; this program reads version " +
                  std::to_string(kSavedSolutionVersion));
    }
    if (head.u32("reserved") != 0) head.fail("the header's reserved word is not 0");
    const std::uint64_t size = head.u64("payload size");
    const std::uint64_t checksum = head.u64("checksum");
    const std::string_view payload = bytes.substr(kSavedSolutionHeaderBytes);
    if (size != payload.size()) {
        head.fail((size > payload.size() ? "truncated: " : "") + std::string("the header says ") +
                  std::to_string(size) + " payload bytes, the file holds " + std::to_string(payload.size()));
    }
    if (saved_solution_checksum(payload) != checksum) head.fail("checksum mismatch: the file is corrupt");

    Reader r(payload, name);
    SavedSolution saved;
    Solution& solution = saved.solution;
    // The smallest element is 80 bytes of patch and 128 of values.
    const std::size_t n = r.count("element count", 80 + 128);
    solution.settings = read_settings(r);
    saved.scene = read_scene(r);
    saved.scene.source = solution.settings.scene_source;
    PatchMesh elements = read_patches(r, n, saved.scene);
    elements.back_to_back = back_to_back_surfaces(saved.scene);
    solution.elements = std::make_shared<const PatchMesh>(std::move(elements));
    solution.area.resize(n);
    for (double& a : solution.area) {
        a = r.f64("element area");
        if (a < 0.0) r.fail("an element area is negative");
    }
    const auto values = [&](std::vector<glm::dvec3>& v, const char* what) {
        v.resize(n);
        for (glm::dvec3& x : v) x = r.vec(what);
    };
    values(solution.reflectance, "element reflectance");
    values(solution.emission, "element emission");
    values(solution.radiosity, "solution");
    values(solution.shown_radiosity, "display solution");
    values(solution.direct, "element direct light");
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            if (solution.reflectance[i][c] < 0.0 || solution.reflectance[i][c] > 1.0) {
                r.fail("element " + std::to_string(i) + ": reflectance outside [0, 1]");
            }
            if (solution.emission[i][c] < 0.0) r.fail("element " + std::to_string(i) + ": negative emission");
            if (solution.direct[i][c] < 0.0)
                r.fail("element " + std::to_string(i) + ": negative direct light");
        }
    }
    const std::uint8_t has_outside = r.u8("outside flag");
    if (has_outside > 1) r.fail("the outside flag is neither 0 nor 1");
    if (has_outside == 1) {
        values(solution.outside, "element outside irradiance");
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c)
                if (solution.outside[i][c] < 0.0)
                    r.fail("element " + std::to_string(i) + ": negative outside irradiance");
    }
    saved.display_gather = read_display_gather(r, n);
    SolutionReport& report = solution.report;
    report.steps = r.u64("step count");
    report.residual = r.f64("residual");
    if (report.residual < 0.0) r.fail("the residual is negative");
    report.status = r.text("solver status");
    std::vector<std::string_view> statuses;
    for (SolverStatus s : {SolverStatus::running, SolverStatus::converged, SolverStatus::iteration_limit,
                           SolverStatus::diverged, SolverStatus::not_converging}) {
        statuses.push_back(solver_status_name(s));
    }
    check_name(r, "solver status", report.status, statuses);
    report.status_message = r.text("status message");
    if (r.left() != 0) r.fail(std::to_string(r.left()) + " bytes follow the payload's end");
    return saved;
}

void write_saved_solution(const std::filesystem::path& path, const SavedSolution& saved) {
    write_file_atomically(path, encode_saved_solution(saved));
}

SavedSolution read_saved_solution(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (error || !std::filesystem::exists(status)) throw InputError(name + ": no such file");
    if (!std::filesystem::is_regular_file(status)) throw InputError(name + ": not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name + ": cannot be read");
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError(name + ": cannot be read");
    return decode_saved_solution(bytes, name);
}

}  // namespace rad
