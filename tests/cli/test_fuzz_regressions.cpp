// Replays the fuzz targets' seed corpus and every crash the fuzzers found (tests/fuzz) through the same entry
// functions, without libFuzzer: nothing may escape but the expected outcomes, and a file named accepted-*
// must load (or parse), refused-* be refused (InputError, or CLI11's parse errors).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_inputs.hpp"

namespace rad {
namespace {

namespace fs = std::filesystem;

struct FuzzTarget {
    std::string name;  // the folder under corpus/ and regressions/
    fuzz::Outcome (*entry)(std::span<const std::uint8_t>);
};

std::ostream& operator<<(std::ostream& out, const FuzzTarget& target) {
    return out << target.name;
}

fs::path fuzz_folder(const std::string& kind, const FuzzTarget& target) {
    return fs::path(RAD_SOURCE_DIR) / "tests" / "fuzz" / kind / target.name;
}

std::vector<fs::path> files_in(const fs::path& folder) {
    std::vector<fs::path> files;
    if (!fs::is_directory(folder)) return files;
    for (const auto& entry : fs::directory_iterator(folder)) {
        if (entry.is_regular_file()) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<std::uint8_t> read_bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void replay(const FuzzTarget& target, const fs::path& file) {
    SCOPED_TRACE(file.string());
    const std::vector<std::uint8_t> bytes = read_bytes(file);
    fuzz::Outcome outcome = fuzz::Outcome::refused;
    EXPECT_NO_THROW(outcome = target.entry(bytes));
    const std::string name = file.filename().string();
    if (name.starts_with("accepted-")) {
        EXPECT_EQ(outcome, fuzz::Outcome::accepted);
    } else if (name.starts_with("refused-")) {
        EXPECT_EQ(outcome, fuzz::Outcome::refused);
    }
}

class FuzzReplay : public testing::TestWithParam<FuzzTarget> {};

TEST_P(FuzzReplay, SeedCorpusBehavesAsNamed) {
    const std::vector<fs::path> files = files_in(fuzz_folder("corpus", GetParam()));
    ASSERT_GE(files.size(), 5u) << "the seed corpus is missing";
    for (const fs::path& file : files) replay(GetParam(), file);
}

TEST_P(FuzzReplay, CrashesFoundAreHandled) {
    const std::vector<fs::path> files = files_in(fuzz_folder("regressions", GetParam()));
    if (files.empty()) GTEST_SKIP() << "no crash found for this target yet";
    for (const fs::path& file : files) replay(GetParam(), file);
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzReplay,
                         testing::Values(FuzzTarget{"obj", fuzz::load_obj_and_mtl},
                                         FuzzTarget{"ply", fuzz::load_ply},
                                         FuzzTarget{"gltf", fuzz::load_gltf_or_glb},
                                         FuzzTarget{"cli", fuzz::parse_command_line}),
                         [](const testing::TestParamInfo<FuzzTarget>& info) { return info.param.name; });

}  // namespace
}  // namespace rad
