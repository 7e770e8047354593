// `radiosity bench --leaks`: the leak suite's rooms seen from inside stay dark in the image, not only on the
// elements (tests/hard/test_hard_leaks.cpp), at the defaults a new user gets (auto) and with clustering,
// which auto picks for large scenes; a missing folder is refused before any work.
#include <gtest/gtest.h>

#include <string>

#include "bench/leak_sweep.hpp"
#include "gl/headless_context.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

LeakPlan source_plan() {
    LeakPlan plan;
    plan.folder = std::string(RAD_SOURCE_DIR) + "/assets/hard";
    plan.image_size = 64;
    return plan;
}

TEST(LeakBench, EveryRoomLooksDarkFromInside) {
    const HeadlessContext context;
    for (const LeakRoom& room : leak_rooms()) {
        for (Subdivision subdivision : {Subdivision::automatic, Subdivision::clustered}) {
            const LeakRow row = run_leak_room(source_plan(), room, subdivision);
            const std::string what = room.name + " " + row.subdivision;
            ASSERT_TRUE(row.failure.empty()) << what << ": " << row.failure;
            EXPECT_GT(row.inside, 0u) << what;
            EXPECT_LT(row.energy_error, 5e-3) << what;
            // Clustering's dark room beside a lit one is not closed yet (docs/hard-cases.md).
            const bool open = subdivision == Subdivision::clustered && room.name == "leak_two_rooms";
            EXPECT_LE(row.image_leak, open ? 1e-4 : 1e-6) << what;
            EXPECT_LE(row.element_leak, open ? 1e-3 : 1e-6) << what;
        }
    }
}

TEST(LeakBench, AFolderWithoutTheRoomsIsRefused) {
    test::TempDir dir;
    const test::CommandResult result = test::run_radiosity(
        {"bench", "--leaks", "--leak-dir", dir.path().string(), "--out-dir", (dir.path() / "out").string()});
    EXPECT_EQ(result.status, 2);
    EXPECT_NE(result.err.find("--leak-dir"), std::string::npos) << result.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out" / "bench.md"));
}

}  // namespace
}  // namespace rad
