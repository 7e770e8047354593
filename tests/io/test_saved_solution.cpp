// The saved-solution file: every field comes back as written, and a truncated, corrupt, foreign, future or
// forged file is refused with one InputError line that names the file.
#include <gtest/gtest.h>
#include <functional>

#include <bit>
#include <filesystem>
#include <fstream>

#include "rad/io/saved_solution.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/util/error.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

// The Cornell box at patch size 300, with a camera, and values that differ per element and channel, so a
// field read into the wrong place or the wrong channel shows.
SavedSolution example() {
    SavedSolution saved;
    // The Cornell box's blocks are surfaces of several faces, so the patches' faces differ.
    saved.scene = load_scene("builtin:cornell");
    saved.scene.warnings.clear();
    saved.scene.camera = Camera{{0.5, 0.5, 0.9}, {0.5, 0.4, 0.0}, {0.0, 1.0, 0.1}, 70.0};
    MeshingOptions meshing;
    meshing.patch_size = 300.0;
    PatchMesh elements = build_patches(saved.scene, meshing);
    // Outlines, as a hierarchical mesh has them: each patch's corners listed.
    elements.outline_begin.push_back(0);
    for (std::size_t p = 0; p < elements.size(); ++p) {
        for (int k = 0; k < elements.corner_count(p); ++k) elements.outline.push_back(elements.corners[p][k]);
        elements.outline_begin.push_back(static_cast<std::uint32_t>(elements.outline.size()));
    }
    Solution& solution = saved.solution;
    solution.elements = std::make_shared<const PatchMesh>(std::move(elements));
    SolutionSettings& s = solution.settings;
    s.scene_source = "builtin:cube";
    s.patch_size = 0.5;
    s.subdivision = "hierarchical";
    s.refine_tolerance = 0.03;
    s.min_patch_size = 0.01;
    s.form_factor_method = "analytic";
    s.rays = 33;
    s.seed = 0x123456789abcdefull;
    s.reciprocity = true;
    s.normalize_rows = false;
    s.solver = "gauss-seidel";
    s.tolerance = 1e-7;
    s.bounces = 77;
    s.initial = "direct";
    s.relaxation = 1.25;
    for (std::size_t i = 0; i < solution.size(); ++i) {
        const double x = double(i);
        solution.area.push_back(0.25 + x / 1000.0);
        solution.reflectance.push_back({0.1 + x / 100.0, 0.2, 0.3});
        solution.emission.push_back({x, 2.0 * x, 0.5});
        solution.radiosity.push_back({x + 0.125, x + 0.25, x + 1.0 / 3.0});
        solution.shown_radiosity.push_back({x + 0.5, x + 0.75, x + 1e-300});
        solution.direct.push_back({x / 4.0, 0.0, x + 2.0});
        solution.outside.push_back({x / 8.0, 0.375, x + 3.0});
    }
    saved.display_gather.row_begin = {0, 2, 2, 3};
    saved.display_gather.patch = {0, 5, static_cast<std::uint32_t>(solution.size() - 1)};
    saved.display_gather.weight = {0.25f, 0.5f, 1.0f};
    solution.report = {42, 3.5e-6, "iteration limit", "stopped at the step limit of 42"};
    return saved;
}

// The saved solution with its elements edited (they are shared, so edited as a copy).
SavedSolution with_elements(SavedSolution saved, const std::function<void(PatchMesh&)>& edit) {
    PatchMesh elements = *saved.solution.elements;
    edit(elements);
    saved.solution.elements = std::make_shared<const PatchMesh>(std::move(elements));
    return saved;
}

TEST(SavedSolution, RoundTripsEveryField) {
    const SavedSolution a = example();
    test::TempDir dir;
    const std::string path = (dir.path() / "cube.radiosity").string();
    write_saved_solution(path, a);
    const SavedSolution b = read_saved_solution(path);

    const SolutionSettings &sa = a.solution.settings, &sb = b.solution.settings;
    EXPECT_EQ(sb.scene_source, sa.scene_source);
    EXPECT_EQ(sb.patch_size, sa.patch_size);
    EXPECT_EQ(sb.subdivision, sa.subdivision);
    EXPECT_EQ(sb.refine_tolerance, sa.refine_tolerance);
    EXPECT_EQ(sb.min_patch_size, sa.min_patch_size);
    EXPECT_EQ(sb.form_factor_method, sa.form_factor_method);
    EXPECT_EQ(sb.rays, sa.rays);
    EXPECT_EQ(sb.seed, sa.seed);
    EXPECT_EQ(sb.reciprocity, sa.reciprocity);
    EXPECT_EQ(sb.normalize_rows, sa.normalize_rows);
    EXPECT_EQ(sb.solver, sa.solver);
    EXPECT_EQ(sb.tolerance, sa.tolerance);
    EXPECT_EQ(sb.bounces, sa.bounces);
    EXPECT_EQ(sb.initial, sa.initial);
    EXPECT_EQ(sb.relaxation, sa.relaxation);

    EXPECT_EQ(b.scene.source, "builtin:cube");
    ASSERT_TRUE(b.scene.camera.has_value());
    EXPECT_EQ(b.scene.camera->eye, a.scene.camera->eye);
    EXPECT_EQ(b.scene.camera->target, a.scene.camera->target);
    EXPECT_EQ(b.scene.camera->up, a.scene.camera->up);
    EXPECT_EQ(b.scene.camera->fov_degrees, 70.0);
    ASSERT_EQ(b.scene.surfaces.size(), a.scene.surfaces.size());
    for (std::size_t s = 0; s < a.scene.surfaces.size(); ++s) {
        const Surface &x = a.scene.surfaces[s], &y = b.scene.surfaces[s];
        EXPECT_EQ(y.name, x.name);
        EXPECT_EQ(y.material.name, x.material.name);
        EXPECT_EQ(y.material.reflectance, x.material.reflectance);
        EXPECT_EQ(y.material.emission, x.material.emission);
        ASSERT_EQ(y.mesh.n_vertices(), x.mesh.n_vertices());
        ASSERT_EQ(y.mesh.n_faces(), x.mesh.n_faces());
        for (auto v : x.mesh.vertices()) EXPECT_EQ(y.mesh.point(v), x.mesh.point(v));
        for (auto f : x.mesh.faces()) {
            std::vector<int> cx, cy;
            for (auto v : x.mesh.fv_range(f)) cx.push_back(v.idx());
            for (auto v : y.mesh.fv_range(SurfaceMesh::FaceHandle(f.idx()))) cy.push_back(v.idx());
            EXPECT_EQ(cy, cx) << "surface " << s << " face " << f.idx();
        }
    }
    // The scene made again meshes as the saved patches do.
    MeshingOptions meshing;
    meshing.patch_size = 300.0;
    EXPECT_EQ(build_patches(b.scene, meshing).points, a.solution.elements->points);

    const PatchMesh &pa = *a.solution.elements, &pb = *b.solution.elements;
    EXPECT_EQ(pb.points, pa.points);
    EXPECT_EQ(pb.positions, pa.positions);
    EXPECT_EQ(pb.corners, pa.corners);
    ASSERT_EQ(pb.patches.size(), pa.patches.size());
    std::uint32_t faces = 0;
    for (std::size_t p = 0; p < pa.size(); ++p) {
        EXPECT_EQ(pb.patches[p].surface, pa.patches[p].surface);
        EXPECT_EQ(pb.patches[p].face, pa.patches[p].face);
        faces = std::max(faces, pa.patches[p].face);
        EXPECT_EQ(pb.patches[p].area, pa.patches[p].area);
        EXPECT_EQ(pb.patches[p].centroid, pa.patches[p].centroid);
        EXPECT_EQ(pb.patches[p].normal, pa.patches[p].normal);
    }
    EXPECT_GT(faces, 0u);  // the check above saw faces other than the first
    EXPECT_EQ(b.display_gather.row_begin, a.display_gather.row_begin);
    EXPECT_EQ(b.display_gather.patch, a.display_gather.patch);
    EXPECT_EQ(b.display_gather.weight, a.display_gather.weight);
    EXPECT_EQ(pb.surface_begin, pa.surface_begin);
    EXPECT_EQ(pb.outline_begin, pa.outline_begin);
    EXPECT_EQ(pb.outline, pa.outline);
    EXPECT_FALSE(pb.outline.empty());

    const Solution &ya = a.solution, &yb = b.solution;
    EXPECT_EQ(yb.area, ya.area);
    EXPECT_EQ(yb.reflectance, ya.reflectance);
    EXPECT_EQ(yb.emission, ya.emission);
    EXPECT_EQ(yb.radiosity, ya.radiosity);
    EXPECT_EQ(yb.shown_radiosity, ya.shown_radiosity);
    EXPECT_EQ(yb.direct, ya.direct);
    EXPECT_EQ(yb.outside, ya.outside);
    EXPECT_FALSE(yb.outside.empty());
    EXPECT_EQ(yb.report.steps, 42u);
    EXPECT_EQ(yb.report.residual, 3.5e-6);
    EXPECT_EQ(yb.report.status, "iteration limit");
    EXPECT_EQ(yb.report.status_message, "stopped at the step limit of 42");
}

TEST(SavedSolution, ASceneWithoutCameraOutlinesOrOutsideLightRoundTrips) {
    SavedSolution a = with_elements(example(), [](PatchMesh& m) {
        m.outline_begin.clear();
        m.outline.clear();
    });
    a.scene.camera.reset();
    a.solution.outside.clear();  // no sky or sun
    const SavedSolution b = decode_saved_solution(encode_saved_solution(a), "x.radiosity");
    EXPECT_FALSE(b.scene.camera.has_value());
    EXPECT_TRUE(b.solution.outside.empty());
    EXPECT_TRUE(b.solution.elements->outline_begin.empty());
    EXPECT_EQ(b.solution.radiosity, a.solution.radiosity);
}

// The message decode gives, or "" when it accepts the bytes.
std::string refusal(const std::string& bytes) {
    try {
        decode_saved_solution(bytes, "some/dir/bad.radiosity");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

void write_u64(std::string& bytes, std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) bytes[at + i] = static_cast<char>(v >> (8 * i));
}

// After editing the payload, the checksum made right again, so the check behind it is what refuses.
void reseal(std::string& bytes) {
    write_u64(bytes, 24, saved_solution_checksum(std::string_view(bytes).substr(kSavedSolutionHeaderBytes)));
}

void expect_refused(const std::string& bytes, const std::string& words) {
    const std::string message = refusal(bytes);
    ASSERT_FALSE(message.empty()) << words;
    EXPECT_EQ(message.rfind("some/dir/bad.radiosity: ", 0), 0u) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(SavedSolution, RefusesTruncatedCorruptForeignFutureAndForgedFiles) {
    const std::string good = encode_saved_solution(example());
    ASSERT_EQ(refusal(good), "");
    EXPECT_EQ(good.substr(0, 8), std::string(kSavedSolutionMagic));

    expect_refused(good.substr(0, good.size() - 1), "truncated");
    expect_refused(good.substr(0, 20), "truncated");
    expect_refused(good.substr(0, kSavedSolutionHeaderBytes), "truncated");
    expect_refused("", "wrong magic");
    expect_refused(good + "x", "the file holds");

    std::string flipped = good;
    flipped[good.size() / 2] ^= 0x10;
    expect_refused(flipped, "checksum mismatch");

    std::string foreign = good;
    foreign[1] = 'X';
    expect_refused(foreign, "wrong magic");
    expect_refused("ply\nformat ascii 1.0\n", "wrong magic");

    std::string future = good;
    future[8] = static_cast<char>(kSavedSolutionVersion + 1);
    expect_refused(future, "format version " + std::to_string(kSavedSolutionVersion + 1));

    // A forged element count, sealed with a right checksum: refused before it is allocated for.
    std::string forged = good;
    write_u64(forged, kSavedSolutionHeaderBytes, std::uint64_t(1) << 40);
    reseal(forged);
    expect_refused(forged, "element count 1099511627776 does not fit the file");
    // A count one higher fits the bytes but not the patches.
    std::string off_by_one = good;
    write_u64(off_by_one, kSavedSolutionHeaderBytes, example().solution.size() + 1);
    reseal(off_by_one);
    expect_refused(off_by_one, "differs from the element count");
}

TEST(SavedSolution, RefusesNonFiniteValuesAndIndicesOutOfRange) {
    // Values written in range, then edited in the bytes: find the solution's first value by its bits.
    SavedSolution a = example();
    a.solution.radiosity[3].y = 1234.5678;
    const std::string good = encode_saved_solution(a);
    const auto bits = std::bit_cast<std::uint64_t>(1234.5678);
    std::string needle(8, '\0');
    for (int i = 0; i < 8; ++i) needle[i] = static_cast<char>(bits >> (8 * i));
    const std::size_t at = good.find(needle);
    ASSERT_NE(at, std::string::npos);
    std::string nan = good;
    write_u64(nan, at, std::bit_cast<std::uint64_t>(std::numeric_limits<double>::quiet_NaN()));
    reseal(nan);
    expect_refused(nan, "solution is not a finite number");

    // A patch corner beyond the points: write a mesh whose corner is out of range, which encode does not
    // check, and expect decode to refuse it.
    const SavedSolution bad_corner = with_elements(
        example(), [](PatchMesh& m) { m.corners[5][1] = static_cast<std::uint32_t>(m.points.size()); });
    expect_refused(encode_saved_solution(bad_corner), "patch corner");
    const SavedSolution bad_surface =
        with_elements(example(), [](PatchMesh& m) { m.patches[2].surface = 99; });
    expect_refused(encode_saved_solution(bad_surface), "patch surface 99 is out of range");
    const SavedSolution bad_face =
        with_elements(example(), [](PatchMesh& m) { m.patches[2].face = 1'000'000; });
    expect_refused(encode_saved_solution(bad_face), "patch face 1000000 is out of range");
    SavedSolution bad_element = example();
    bad_element.display_gather.patch[1] = static_cast<std::uint32_t>(bad_element.solution.size());
    expect_refused(encode_saved_solution(bad_element), "display gather element");
    SavedSolution bad_offsets = example();
    bad_offsets.display_gather.row_begin = {0, 3, 2, 3};
    expect_refused(encode_saved_solution(bad_offsets), "the display gather's offsets are not ascending");
    SavedSolution bad_weight = example();
    bad_weight.display_gather.weight[2] = -1.0f;
    expect_refused(encode_saved_solution(bad_weight), "a display gather weight is negative");
    SavedSolution bad_reflectance = example();
    bad_reflectance.scene.surfaces[0].material.reflectance.x = 1.0;
    expect_refused(encode_saved_solution(bad_reflectance), "reflectance");
    SavedSolution bad_direct = example();
    bad_direct.solution.direct[4].z = -1.0;
    expect_refused(encode_saved_solution(bad_direct), "element 4: negative direct light");
    SavedSolution bad_solver = example();
    bad_solver.solution.settings.solver = "magic";
    expect_refused(encode_saved_solution(bad_solver), "solver 'magic'");
}

TEST(SavedSolution, RefusesMissingAndNonRegularFilesNamingThem) {
    test::TempDir dir;
    const std::string missing = (dir.path() / "none.radiosity").string();
    try {
        read_saved_solution(missing);
        FAIL() << "accepted a missing file";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), missing + ": no such file");
    }
    try {
        read_saved_solution(dir.path());
        FAIL() << "accepted a folder";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), dir.path().string() + ": not a regular file");
    }
}

TEST(SavedSolution, WritesNothingWhenAValueIsNotFinite) {
    SavedSolution a = example();
    a.solution.shown_radiosity[0].x = std::numeric_limits<double>::infinity();
    test::TempDir dir;
    EXPECT_THROW(write_saved_solution(dir.path() / "x.radiosity", a), std::invalid_argument);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace rad
