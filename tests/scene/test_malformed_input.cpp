// Malformed scene files (tests/malformed, listed with what each must say in expected.txt): truncated, wrong
// counts, binary junk, huge numbers, NaN text, paths that leave the scene's folder. Every command refuses
// each with exit status 2 and one line naming the file, and writes nothing.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "expect_input_error.hpp"
#include "rad/scene/scene_loader.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

namespace fs = std::filesystem;

const fs::path kFolder = fs::path(RAD_SOURCE_DIR) / "tests" / "malformed";

// File name -> what its one-line message must contain.
std::map<std::string, std::string> expected_messages() {
    std::map<std::string, std::string> expected;
    std::ifstream in(kFolder / "expected.txt");
    std::string line;
    while (std::getline(in, line)) {
        const auto tab = line.find('\t');
        if (line.empty() || line[0] == '#' || tab == std::string::npos) continue;
        expected[line.substr(0, tab)] = line.substr(tab + 1);
    }
    return expected;
}

bool is_scene(const fs::path& p) {
    return p.extension() == ".obj" || p.extension() == ".ply" || p.extension() == ".gltf" ||
           p.extension() == ".glb";
}

TEST(MalformedInput, EverySceneInTheCorpusIsListedWithItsMessage) {
    const auto expected = expected_messages();
    std::size_t scenes = 0;
    for (const auto& entry : fs::directory_iterator(kFolder)) {
        if (!is_scene(entry.path())) continue;
        ++scenes;
        EXPECT_TRUE(expected.contains(entry.path().filename().string())) << entry.path();
    }
    EXPECT_EQ(scenes, expected.size());
    EXPECT_GE(scenes, 30u);
}

TEST(MalformedInput, TheLoaderThrowsOneLineNamingTheFile) {
    for (const auto& [name, message] : expected_messages()) {
        SCOPED_TRACE(name);
        test::expect_input_error([](const std::string& p) { load_scene(p); }, (kFolder / name).string(),
                                 {message});
    }
}

// One line on stderr naming the file, status 2, and no output file, for a command that would write one.
void expect_refused(const std::vector<std::string>& args, const std::string& message,
                    const fs::path& output) {
    const auto result = test::run_radiosity(args);
    EXPECT_EQ(result.status, 2) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find(message), std::string::npos) << result.err;
    EXPECT_EQ(result.err.rfind("radiosity: error: ", 0), 0u) << result.err;
    if (!output.empty()) {
        EXPECT_TRUE(fs::is_empty(output.parent_path())) << "something was written";
    }
}

TEST(MalformedInput, EveryCommandExitsWithStatus2AndWritesNothing) {
    test::TempDir dir;
    for (const auto& [name, message] : expected_messages()) {
        SCOPED_TRACE(name);
        const std::string scene = (kFolder / name).string();
        expect_refused({"info", scene}, message, {});
        expect_refused({"solve", scene, "--json", (dir.path() / "out.json").string()}, message,
                       dir.path() / "out.json");
        expect_refused({"render", scene, "--out", (dir.path() / "out.png").string()}, message,
                       dir.path() / "out.png");
    }
}

TEST(MalformedInput, APathLongerThanTheSystemAllowsIsRefused) {
    std::string deep;
    for (int i = 0; i < 3000; ++i) deep += "deep/";
    const auto result = test::run_radiosity({"info", deep + "scene.obj"});
    EXPECT_EQ(result.status, 2) << result.err;
    EXPECT_NE(result.err.find("scene.obj: no such file"), std::string::npos) << result.err;
}

// The scene refers to its library through a link: refused even though the target is a good file.
TEST(MalformedInput, AMaterialLibraryReachedThroughALinkIsRefused) {
    test::TempDir dir;
    const std::string geometry = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n";
    dir.write("real.mtl", "newmtl x\nKd 0.5 0.5 0.5\n");
    fs::create_symlink(dir.path() / "real.mtl", dir.path() / "m.mtl");
    test::expect_input_error([](const std::string& p) { load_scene(p); }, dir.write("a.obj", geometry),
                             {"a.obj:1: material library 'm.mtl' is reached through a link"});

    fs::create_directory(dir.path() / "real");
    dir.write("real/n.mtl", "newmtl x\nKd 0.5 0.5 0.5\n");
    fs::create_directory_symlink(dir.path() / "real", dir.path() / "linked");
    test::expect_input_error([](const std::string& p) { load_scene(p); },
                             dir.write("b.obj", "mtllib linked/n.mtl\n" + geometry.substr(13)),
                             {"b.obj:1:", "through a link"});
    // The same library in a real subfolder loads.
    EXPECT_NO_THROW(load_scene(dir.write("c.obj", "mtllib real/n.mtl\n" + geometry.substr(13))));
}

TEST(MalformedInput, AMaterialLibraryThatIsNotAFileIsRefused) {
    test::TempDir dir;
    const std::string geometry = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n";
    fs::create_directory(dir.path() / "m.mtl");
    test::expect_input_error([](const std::string& p) { load_scene(p); }, dir.write("a.obj", geometry),
                             {"a.obj:1: material library 'm.mtl' is not a regular file"});
}

// A pipe named like a scene would block a reader forever.
TEST(MalformedInput, APipeIsRefusedWithoutWaiting) {
    test::TempDir dir;
    const fs::path pipe = dir.path() / "scene.obj";
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    test::expect_input_error([](const std::string& p) { load_scene(p); }, pipe.string(),
                             {"scene.obj: is not a regular file"});
}

// Root reads files whatever their permissions, so as root the program runs as nobody (setpriv).
TEST(MalformedInput, AnUnreadableMaterialLibraryIsRefused) {
    test::TempDir dir;
    fs::permissions(dir.path(), fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
    const std::string mtl = dir.write("m.mtl", "newmtl x\nKd 0.5 0.5 0.5\n");
    fs::permissions(mtl, fs::perms::none);
    const std::string obj =
        dir.write("a.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n");
    fs::permissions(obj, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    std::vector<std::string> args{"info", obj};
    test::CommandResult result;
    if (::geteuid() == 0) {
        const std::string setpriv = test::find_in_path("setpriv");
        const std::vector<std::string> as_nobody{"--reuid=65534", "--regid=65534", "--clear-groups"};
        auto reachable = as_nobody;
        reachable.insert(reachable.end(), {"test", "-x", RAD_BINARY});
        if (setpriv.empty() || test::run_program(setpriv, reachable).status != 0) {
            GTEST_SKIP() << "running as root, and nobody cannot run " << RAD_BINARY;
        }
        args.insert(args.begin(), RAD_BINARY);
        args.insert(args.begin(), as_nobody.begin(), as_nobody.end());
        result = test::run_program(setpriv, args);
    } else {
        result = test::run_radiosity(args);
    }
    EXPECT_EQ(result.status, 2) << result.err;
    EXPECT_NE(result.err.find("m.mtl: cannot be read: Permission denied"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace rad
