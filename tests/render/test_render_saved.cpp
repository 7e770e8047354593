// `render FILE.radiosity`: a saved solution draws exactly the image its scene does, with no form-factor
// pass; several cameras make several images from one solve; bad saved files and cameras files exit 2 with one
// line naming the file (and line), writing nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "rad/io/image_file.hpp"
#include "rad/io/saved_solution.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene_loader.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

using test::run_radiosity;

std::size_t lines(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

// Renders `scene` solved directly and from its saved solution, and expects the same pixels, bit for bit.
void expect_same_image_from_saved(const std::vector<std::string>& solve_options) {
    test::TempDir dir;
    const std::string saved = (dir.path() / "scene.radiosity").string();
    const std::string direct = (dir.path() / "direct.pfm").string();
    const std::string from_saved = (dir.path() / "saved.pfm").string();
    const std::vector<std::string> view = {"--width", "96", "--height", "80", "--exposure", "1"};

    std::vector<std::string> render = {"render", "builtin:cornell", "--out", direct};
    render.insert(render.end(), solve_options.begin(), solve_options.end());
    render.insert(render.end(), view.begin(), view.end());
    const auto rendered = run_radiosity(render);
    ASSERT_EQ(rendered.status, 0) << rendered.err;

    std::vector<std::string> solve = {"solve", "builtin:cornell", "--save", saved};
    solve.insert(solve.end(), solve_options.begin(), solve_options.end());
    const auto solved = run_radiosity(solve);
    ASSERT_EQ(solved.status, 0) << solved.err;
    EXPECT_NE(solved.out.find("wrote " + saved), std::string::npos) << solved.out;

    std::vector<std::string> again = {"render", saved, "--out", from_saved};
    again.insert(again.end(), view.begin(), view.end());
    const auto redrawn = run_radiosity(again);
    ASSERT_EQ(redrawn.status, 0) << redrawn.err;
    // No form factors, no solve: the line says where the solution came from, and no stage ran.
    EXPECT_NE(redrawn.out.find("saved solution of builtin:cornell"), std::string::npos) << redrawn.out;
    EXPECT_EQ(redrawn.out.find("form factors"), std::string::npos) << redrawn.out;
    EXPECT_EQ(redrawn.err.find("form factors"), std::string::npos) << redrawn.err;
    EXPECT_NE(rendered.out.find("form factors"), std::string::npos) << rendered.out;
    // The same patch count as the direct render reported.
    const std::string patches = rendered.out.substr(0, rendered.out.find(" patches"));
    EXPECT_EQ(redrawn.out.rfind(patches + " patches", 0), 0u) << redrawn.out;

    const Image a = read_image(direct);
    const Image b = read_image(from_saved);
    ASSERT_EQ(a.width, 96);
    ASSERT_EQ(b.width, 96);
    ASSERT_EQ(b.height, 80);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    std::size_t differing = 0;
    float brightest = 0.0f;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        if (a.pixels[i] != b.pixels[i]) ++differing;
        brightest = std::max(brightest, a.pixels[i].r);
    }
    EXPECT_EQ(differing, 0u);
    EXPECT_GT(brightest, 1.0f);  // the image shows the lit box, not black
}

TEST(RenderSaved, CornellBoxDefaultDrawsTheSameImageFromItsSavedSolution) {
    expect_same_image_from_saved({});
}

TEST(RenderSaved, HierarchicalCornellBoxDrawsTheSameImageFromItsSavedSolution) {
    expect_same_image_from_saved({"--subdivision", "hierarchical"});
}

TEST(RenderSaved, ClusteredCornellBoxDrawsTheSameImageFromItsSavedSolution) {
    expect_same_image_from_saved({"--subdivision", "clustered"});
}

// The file keeps the display patches' own gather, so opening it does not trace that again; the image is the
// one the gather traced anew gives (the same seed), bit for bit.
TEST(RenderSaved, AClusteredSolutionKeepsItsDisplayPatchesGather) {
    test::TempDir dir;
    const std::string kept = (dir.path() / "kept.radiosity").string();
    ASSERT_EQ(
        run_radiosity({"solve", "builtin:cornell", "--subdivision", "clustered", "--save", kept}).status, 0);
    SavedSolution saved = read_saved_solution(kept);
    const Scene scene = load_scene("builtin:cornell");
    const std::size_t display_patches =
        build_patches(scene, MeshingOptions{.patch_size = default_patch_size(scene)}).size();
    ASSERT_EQ(saved.display_gather.row_begin.size(), display_patches + 1);
    EXPECT_GT(saved.display_gather.patch.size(), 100 * display_patches);  // rows of many leaves each
    const std::string traced = (dir.path() / "traced.radiosity").string();
    saved.display_gather = {};
    write_saved_solution(traced, saved);

    std::vector<Image> images;
    for (const std::string& file : {kept, traced}) {
        const std::string out = file + ".pfm";
        const auto result = run_radiosity({"render", file, "--out", out, "--width", "96", "--height", "80"});
        ASSERT_EQ(result.status, 0) << result.err;
        images.push_back(read_image(out));
    }
    EXPECT_EQ(images[0].pixels, images[1].pixels);
}

TEST(RenderSaved, SeveralCamerasWriteSeveralImagesFromOneSolve) {
    test::TempDir dir;
    const std::string out = (dir.path() / "view.png").string();
    const std::string a = "278,273,-800,278,273,0";
    const std::string b = "100,450,-300,400,100,500";
    const auto result = run_radiosity({"render", "builtin:cornell", "--patch-size", "70", "--camera", a,
                                       "--camera", b, "--width", "64", "--height", "64", "--out", out});
    ASSERT_EQ(result.status, 0) << result.err;
    const std::string first = (dir.path() / "view-1.png").string();
    const std::string second = (dir.path() / "view-2.png").string();
    EXPECT_NE(result.out.find("wrote " + first), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("wrote " + second), std::string::npos) << result.out;
    EXPECT_FALSE(std::filesystem::exists(out));
    // One summary line: one solve for both images.
    EXPECT_EQ(lines(result.out), 3u) << result.out;
    const Image one = read_image(first);
    const Image two = read_image(second);
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < one.pixels.size(); ++i) differing += one.pixels[i] != two.pixels[i];
    EXPECT_GT(differing, one.pixels.size() / 4);

    // A cameras file with comments and blank lines gives the same two images.
    const std::string cameras =
        dir.write("cameras.txt", "# front, then from above\n\n" + a + "\n   " + b + "  # the second\n");
    const std::string listed = (dir.path() / "listed.png").string();
    const auto from_file = run_radiosity({"render", "builtin:cornell", "--patch-size", "70", "--cameras",
                                          cameras, "--width", "64", "--height", "64", "--out", listed});
    ASSERT_EQ(from_file.status, 0) << from_file.err;
    EXPECT_EQ(test::read_file_text(dir.path() / "listed-1.png"), test::read_file_text(first));
    EXPECT_EQ(test::read_file_text(dir.path() / "listed-2.png"), test::read_file_text(second));
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "listed-3.png"));
}

TEST(RenderSaved, OneCameraKeepsTheNameAsGiven) {
    test::TempDir dir;
    const std::string out = (dir.path() / "one.png").string();
    const auto result =
        run_radiosity({"render", "builtin:cube", "--patch-size", "0.5", "--camera", "0.5,0.5,0.9,0.5,0.4,0",
                       "--width", "16", "--height", "16", "--out", out});
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_TRUE(std::filesystem::exists(out));
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "one-1.png"));
}

TEST(RenderSaved, CamerasFileErrorsNameTheLine) {
    test::TempDir dir;
    const std::string out = (dir.path() / "x.png").string();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"# one good camera, then a short one\n0,0,-5,0,0,0\n\n1,2,3\n", ":4: 3 numbers"},
        {"0,0,-5,0,0,0\n0,0,-5,zero,0,0\n", ":2: 'zero' is not a number"},
        {"\n\n0,0,0,0,0,0\n", ":3: eye and target coincide"},
        {"# nothing but comments\n\n", ": no cameras"},
    };
    int k = 0;
    for (const auto& [text, words] : cases) {
        const std::string file = dir.write("cameras" + std::to_string(k++) + ".txt", text);
        const auto result = run_radiosity({"render", "builtin:cube", "--cameras", file, "--out", out});
        EXPECT_EQ(result.status, 2) << text;
        EXPECT_NE(result.err.find(file + words), std::string::npos) << result.err;
        EXPECT_EQ(lines(result.err), 1u) << result.err;
    }
    const auto missing = run_radiosity(
        {"render", "builtin:cube", "--cameras", (dir.path() / "none.txt").string(), "--out", out});
    EXPECT_EQ(missing.status, 2);
    EXPECT_NE(missing.err.find("none.txt: no such file"), std::string::npos) << missing.err;
    const auto both = run_radiosity({"render", "builtin:cube", "--camera", "0,0,-5,0,0,0", "--cameras",
                                     dir.write("c.txt", "0,0,-5,0,0,0\n"), "--out", out});
    EXPECT_EQ(both.status, 2);
    EXPECT_NE(both.err.find("not both"), std::string::npos) << both.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(RenderSaved, BadSavedFilesExitWith2OneLineAndWriteNothing) {
    test::TempDir dir;
    const std::string saved = (dir.path() / "cube.radiosity").string();
    ASSERT_EQ(run_radiosity({"solve", "builtin:cube", "--patch-size", "0.5", "--save", saved}).status, 0);
    const std::string good = test::read_file_text(saved);
    ASSERT_GT(good.size(), 100u);

    test::TempDir out_dir;
    const std::string out = (out_dir.path() / "x.png").string();
    const auto write = [&](const std::string& name, const std::string& bytes) {
        const std::string path = (dir.path() / name).string();
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    };
    std::string flipped = good;
    flipped[good.size() - 40] ^= 0x01;
    std::string future = good;
    future[8] = 9;
    const std::vector<std::pair<std::string, std::string>> cases = {
        {write("truncated.radiosity", good.substr(0, good.size() / 2)), "truncated"},
        {write("flipped.radiosity", flipped), "checksum mismatch"},
        {write("foreign.radiosity", "solid cube\nendsolid\n"), "wrong magic"},
        {write("future.radiosity", future), "format version 9"},
        {write("empty.radiosity", ""), "wrong magic"},
        {(dir.path() / "missing.radiosity").string(), "no such file"},
    };
    for (const auto& [path, words] : cases) {
        const auto result = run_radiosity({"render", path, "--out", out});
        EXPECT_EQ(result.status, 2) << path;
        EXPECT_NE(result.err.find(path + ": "), std::string::npos) << result.err;
        EXPECT_NE(result.err.find(words), std::string::npos) << result.err;
        EXPECT_EQ(lines(result.err), 1u) << result.err;
        EXPECT_EQ(result.out, "");
    }
    // Options that only steer solving are refused with a saved solution, naming the option.
    for (const std::vector<std::string>& extra : {std::vector<std::string>{"--patch-size", "0.25"},
                                                  {"--solver", "cg"},
                                                  {"--rays", "64"},
                                                  {"--subdivision", "hierarchical"}}) {
        std::vector<std::string> args = {"render", saved, "--out", out};
        args.insert(args.end(), extra.begin(), extra.end());
        const auto result = run_radiosity(args);
        EXPECT_EQ(result.status, 2) << extra[0];
        EXPECT_NE(result.err.find(extra[0] + ": only for solving a scene"), std::string::npos) << result.err;
        EXPECT_EQ(lines(result.err), 1u) << result.err;
    }
    EXPECT_TRUE(std::filesystem::is_empty(out_dir.path()));
    // And the good file still draws, with --flat and --outline.
    const auto drawn = run_radiosity(
        {"render", saved, "--flat", "--outline", "--width", "8", "--height", "8", "--out", out});
    EXPECT_EQ(drawn.status, 0) << drawn.err;
    EXPECT_TRUE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace rad
