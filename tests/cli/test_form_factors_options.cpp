// The command-line options of the form factors and the terminal progress bar.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <sstream>
#include <thread>

#include "cli/solving_options.hpp"
#include "pipeline/form_factor_options.hpp"
#include "text/progress_bar.hpp"

namespace rad {
namespace {

FormFactorOptions parse(std::vector<std::string> args) {
    CLI::App app;
    FormFactorOptions options;
    add_form_factor_options(app, options);
    std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last to first
    app.parse(args);
    return options;
}

TEST(FormFactorOptions, DefaultsAreTheLibrarysDefaults) {
    const FormFactorOptions options = parse({});
    const FormFactorOptions library;
    EXPECT_EQ(options.method, library.method);
    EXPECT_EQ(options.rays, library.rays);
    EXPECT_EQ(options.seed, library.seed);
    EXPECT_EQ(options.max_memory_bytes, library.max_memory_bytes);
    EXPECT_FALSE(options.enforce_reciprocity);
    EXPECT_FALSE(options.normalize_rows);
}

TEST(FormFactorOptions, EveryOptionReachesTheLibrary) {
    const FormFactorOptions options = parse({"--ff", "analytic", "--rays", "32", "--seed", "9",
                                             "--max-memory", "512M", "--reciprocity", "--normalize-rows"});
    EXPECT_EQ(options.method, FormFactorMethod::analytic);
    EXPECT_EQ(options.rays, 32);
    EXPECT_EQ(options.seed, 9u);
    EXPECT_EQ(options.max_memory_bytes, 512u << 20);
    EXPECT_TRUE(options.enforce_reciprocity);
    EXPECT_TRUE(options.normalize_rows);
    EXPECT_EQ(parse({"--max-memory", "4G"}).max_memory_bytes, std::size_t{4} << 30);
    EXPECT_EQ(parse({"--ff", "hemisphere"}).method, FormFactorMethod::hemisphere);
}

TEST(FormFactorOptions, BadValuesAreRejectedNamingTheOption) {
    for (const auto& args : std::vector<std::vector<std::string>>{{"--ff", "radiance"},
                                                                  {"--rays", "0"},
                                                                  {"--rays", "many"},
                                                                  {"--threads", "0"},
                                                                  {"--max-memory", "lots"},
                                                                  {"--max-memory", "0"}}) {
        try {
            parse(args);
            ADD_FAILURE() << args[0] << " " << args[1] << " was accepted";
        } catch (const CLI::ParseError& e) {
            EXPECT_NE(std::string(e.what()).find(args[0]), std::string::npos) << e.what();
        }
    }
}

TEST(FormFactorOptions, ThreadsLimitTbb) {
    parse({"--threads", "1"});
    EXPECT_EQ(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism), 1u);
}

TEST(ProgressBar, DrawsTheStageAndShareDoneThenErasesItself) {
    Progress progress;
    progress.begin("form factors", 10);
    progress.advance(5);
    std::ostringstream out;
    {
        const ProgressBar bar(progress, out, true, std::chrono::milliseconds(0),
                              std::chrono::milliseconds(5));
        std::this_thread::sleep_for(std::chrono::milliseconds(60));
    }
    const std::string text = out.str();
    EXPECT_NE(text.find("\rform factors [###############...............]  50%"), std::string::npos) << text;
    EXPECT_EQ(text.substr(text.size() - 4), "\r\x1b[K");
}

// Work shorter than the delay draws nothing, even on a terminal (tests/cli/test_progress_bar.cpp covers the
// lines printed off a terminal).
TEST(ProgressBar, StaysQuietForShortWork) {
    Progress progress;
    progress.begin("form factors", 10);
    std::ostringstream short_work;
    {
        const ProgressBar bar(progress, short_work, true, std::chrono::seconds(30),
                              std::chrono::milliseconds(5));
        std::this_thread::sleep_for(std::chrono::milliseconds(40));
    }
    EXPECT_EQ(short_work.str(), "");
}

TEST(ProgressBar, LineShowsTimeLeft) {
    EXPECT_EQ(progress_line("solve", 0.25, 10.0),
              "solve [#######.......................]  25%  10 s, about 30 s left");
    EXPECT_EQ(progress_line("solve", 1.0, 3.0), "solve [##############################] 100%  3 s");
}

}  // namespace
}  // namespace rad
