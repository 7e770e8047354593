// Writing through a temporary: the target appears whole or not at all, and no temporary is left behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "rad/io/atomic_file.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

std::size_t entries(const std::filesystem::path& folder) {
    std::size_t count = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) ++count;
    return count;
}

TEST(AtomicFile, TheTemporaryLiesBesideTheTargetAndKeepsItsExtension) {
    test::TempDir dir;
    const std::filesystem::path target = dir.path() / "scene.glb";
    std::filesystem::path seen;
    replace_file_atomically(target, [&](const std::filesystem::path& temporary) {
        seen = temporary;
        std::ofstream(temporary) << "new";
    });
    EXPECT_EQ(seen.parent_path(), dir.path());
    EXPECT_EQ(seen.extension(), ".glb");
    EXPECT_NE(seen.filename(), target.filename());
    EXPECT_EQ(test::read_file_text(target), "new");
    EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicFile, AFailedWriteLeavesTheOldFileAndNoTemporary) {
    test::TempDir dir;
    const std::filesystem::path target = dir.write("out.ply", "old");
    EXPECT_THROW(replace_file_atomically(target,
                                         [](const std::filesystem::path& temporary) {
                                             std::ofstream(temporary) << "half of it";
                                             throw std::runtime_error("disk full");
                                         }),
                 std::runtime_error);
    EXPECT_EQ(test::read_file_text(target), "old");
    EXPECT_EQ(entries(dir.path()), 1u);
    // A writer that makes no file at all: the rename fails, and still nothing is left.
    EXPECT_THROW(replace_file_atomically(dir.path() / "new.ply", [](const std::filesystem::path&) {}),
                 std::filesystem::filesystem_error);
    EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicFile, WriteFileAtomicallyWritesTheText) {
    test::TempDir dir;
    write_file_atomically(dir.path() / "a.json", "{}\n");
    EXPECT_EQ(test::read_file_text(dir.path() / "a.json"), "{}\n");
    EXPECT_EQ(entries(dir.path()), 1u);
}

}  // namespace
}  // namespace rad
