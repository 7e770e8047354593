// Progress off the terminal (a log file, CI, a pipe): plain lines with the stage, the share done, the time
// and the time left, the notes once, the estimate of a long stage once, and nothing for short work. The
// printer is driven with made-up times; one run of the binary checks a real solve with stderr in a file.
#include <gtest/gtest.h>

#include <cstddef>
#include <sstream>
#include <string>

#include "test_support.hpp"
#include "text/progress_bar.hpp"

namespace rad {
namespace {

// The default timing off the terminal: the first output after 2 s, a line every 5 s, estimates of stages
// over 5 s.
constexpr ProgressTiming kLog{2.0, 5.0, 5.0};

std::size_t count(const std::string& text, const std::string& part) {
    std::size_t n = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size()))
        ++n;
    return n;
}

bool plain(const std::string& text) {
    return text.find('\r') == std::string::npos && text.find('\x1b') == std::string::npos;
}

TEST(ProgressLog, PrintsPlainLinesWithStageShareAndTimeLeft) {
    Progress progress;
    std::ostringstream out;
    ProgressPrinter printer(out, false, kLog);
    progress.begin("form factors", 100);
    printer.update(progress, 0.0);
    progress.advance(10);
    printer.update(progress, 1.0);
    EXPECT_EQ(out.str(), "");  // before the delay
    progress.advance(10);
    printer.update(progress, 2.0);  // 20 % in 2 s: 10 s in all, a long stage
    printer.update(progress, 4.0);  // not yet the next line
    progress.advance(50);
    printer.update(progress, 7.0);
    progress.advance(30);
    progress.begin("solving", 1000, ProgressTotal::at_most);
    printer.update(progress, 10.0);  // the stage changed: the last one was reported, so its end is
    progress.advance(30);
    printer.update(progress, 15.0);
    printer.finish(16.0);
    EXPECT_EQ(out.str(),
              "radiosity: form factors: estimated 10 s in all\n"
              "radiosity: form factors: 20 % after 2 s, about 8 s left\n"
              "radiosity: form factors: 70 % after 7 s, about 3 s left\n"
              "radiosity: form factors: done in 10 s\n"
              "radiosity: solving: 30 of at most 1000 after 5 s\n"
              "radiosity: solving: done in 6 s\n");
    EXPECT_TRUE(plain(out.str()));
}

TEST(ProgressLog, ShortWorkPrintsNothing) {
    Progress progress;
    std::ostringstream out;
    {
        ProgressPrinter printer(out, false, kLog);
        progress.begin("form factors", 10);
        progress.note("2516 patches × 2048 rays, about 11 MB");
        printer.update(progress, 0.0);
        progress.advance(5);
        printer.update(progress, 1.0);
        progress.begin("solving", 1000);
        progress.advance(1000);
        printer.update(progress, 1.9);
        printer.finish(1.95);
    }
    EXPECT_EQ(out.str(), "");
    // The same on a terminal with its shorter delay.
    ProgressPrinter bar(out, true, ProgressTiming{1.0, 0.2, 5.0});
    progress.begin("form factors", 10);
    bar.update(progress, 0.0);
    progress.advance(5);
    bar.update(progress, 0.9);
    bar.finish(0.95);
    EXPECT_EQ(out.str(), "");
}

TEST(ProgressLog, PrintsEachNoteOnceWhenTheWorkIsLong) {
    Progress progress;
    std::ostringstream out;
    ProgressPrinter printer(out, false, kLog);
    progress.begin("form factors", 100);
    progress.note("2516 patches × 2048 rays, about 11 MB");
    printer.update(progress, 0.5);
    EXPECT_EQ(out.str(), "");  // held back until the work has run past the delay
    for (double t = 2.0; t < 4.0; t += 0.2) printer.update(progress, t);
    progress.note("a second note");
    for (double t = 4.0; t < 6.0; t += 0.2) printer.update(progress, t);
    printer.finish(6.0);
    const std::string text = out.str();
    EXPECT_EQ(count(text, "radiosity: form factors: 2516 patches × 2048 rays, about 11 MB\n"), 1u) << text;
    EXPECT_EQ(count(text, "radiosity: form factors: a second note\n"), 1u) << text;
    EXPECT_LT(text.find("11 MB"), text.find("0 % after 2 s")) << text;  // the note comes first
    EXPECT_TRUE(plain(text));
}

TEST(ProgressLog, EstimatesOnlyLongStagesAndOnlyOnce) {
    Progress progress;
    std::ostringstream out;
    ProgressPrinter printer(out, false, kLog);
    progress.begin("form factors", 100);
    printer.update(progress, 0.0);
    progress.advance(50);
    printer.update(progress, 2.0);  // 4 s in all: short, no estimate
    progress.advance(49);
    printer.update(progress, 12.0);  // no estimate afterwards either: the first decides
    EXPECT_EQ(count(out.str(), "estimated"), 0u) << out.str();

    progress.begin("form factors", 1000);
    printer.update(progress, 20.0);
    progress.advance(10);
    printer.update(progress, 20.5);  // 1 % after half a second: not known yet
    progress.advance(10);
    printer.update(progress, 21.0);  // after a second: 50 s in all
    printer.update(progress, 22.0);
    EXPECT_EQ(count(out.str(), "radiosity: form factors: estimated 50 s in all\n"), 1u) << out.str();
}

TEST(ProgressLog, NewStageWaitsForAShareWorthPrinting) {
    Progress progress;
    std::ostringstream out;
    ProgressPrinter printer(out, false, kLog);
    progress.begin("meshing", 10);
    printer.update(progress, 0.0);
    progress.begin("form factors", 100);
    printer.update(progress, 1.5);  // meshing ended before the delay: nothing to say about it
    printer.update(progress, 2.0);  // a line is due, but the stage has only just begun
    EXPECT_EQ(out.str(), "");
    progress.advance(50);
    printer.update(progress, 3.5);
    EXPECT_EQ(out.str(), "radiosity: form factors: 50 % after 2 s, about 2 s left\n");
}

TEST(ProgressLog, StageWithoutTotalSaysHowLongItRuns) {
    Progress progress;
    std::ostringstream out;
    ProgressPrinter printer(out, false, kLog);
    progress.begin("linking elements, round 1", 0);
    printer.update(progress, 0.0);
    progress.advance(12345);
    printer.update(progress, 3.0);
    progress.begin("solving between rounds", 0);
    printer.update(progress, 4.0);
    printer.finish(4.5);  // short and not reported: no end line
    EXPECT_EQ(out.str(),
              "radiosity: linking elements, round 1: running for 3 s\n"
              "radiosity: linking elements, round 1: done in 4 s\n");
}

TEST(ProgressLog, LineWording) {
    ProgressState state;
    state.stage = "form factors";
    state.total = 1000;
    state.done = 420;
    EXPECT_EQ(progress_log_line(state, 12.0), "form factors: 42 % after 12 s, about 17 s left");
    state.done = 10;  // 1 % in half a second: too early to tell the time left
    EXPECT_EQ(progress_log_line(state, 0.4), "form factors: 1 % after 0 s");
    state.done = 1000;
    EXPECT_EQ(progress_log_line(state, 30.0), "form factors: 100 % after 30 s");
    state.kind = ProgressTotal::at_most;
    state.done = 30;
    EXPECT_EQ(progress_log_line(state, 9.0), "form factors: 30 of at most 1000 after 9 s");
    state.total = 0;
    EXPECT_EQ(progress_log_line(state, 9.0), "form factors: running for 9 s");
    EXPECT_FALSE(progress_estimate_known(0.02, 0.5));
    EXPECT_TRUE(progress_estimate_known(0.03, 0.5));
    EXPECT_TRUE(progress_estimate_known(0.001, 1.0));
    EXPECT_FALSE(progress_estimate_known(0.0, 10.0));
    EXPECT_FALSE(progress_estimate_known(1.0, 10.0));
}

TEST(ProgressBarTerminal, PrintsNotesAndEstimateAboveTheBar) {
    Progress progress;
    std::ostringstream out;
    ProgressPrinter printer(out, true, ProgressTiming{1.0, 0.2, 5.0});
    progress.begin("form factors", 100);
    printer.update(progress, 0.0);
    progress.advance(10);
    printer.update(progress, 1.0);  // 10 % after 1 s: 10 s in all
    progress.note("2516 patches × 2048 rays, about 11 MB");
    printer.update(progress, 1.2);
    printer.update(progress, 1.4);
    printer.finish(1.5);
    const std::string text = out.str();
    const std::string bar =
        "\rform factors [###" + std::string(27, '.') + "]  10%  1 s, about 9 s left\x1b[K";
    EXPECT_EQ(text.find("radiosity: form factors: estimated 10 s in all\n" + bar), 0u) << text;
    // The note takes the bar's line, then the bar is drawn again below it.
    EXPECT_EQ(
        count(text,
              "\r\x1b[Kradiosity: form factors: 2516 patches × 2048 rays, about 11 MB\n\rform factors ["),
        1u)
        << text;
    EXPECT_EQ(text.substr(text.size() - 4), "\r\x1b[K");  // the bar is erased at the end
}

TEST(Progress, StateCountsStagesAndKeepsNotesWithTheirStage) {
    Progress progress;
    EXPECT_EQ(progress.state().stage_number, 0u);
    progress.begin("form factors", 4);
    progress.note("first");
    progress.advance(8);
    ProgressState s = progress.state();
    EXPECT_EQ(s.stage_number, 1u);
    EXPECT_EQ(s.notes, 1u);
    EXPECT_DOUBLE_EQ(s.fraction(), 1.0);  // clamped
    progress.begin("form factors", 4);    // the same name again is a new stage
    progress.note("second");
    s = progress.state();
    EXPECT_EQ(s.stage_number, 2u);
    EXPECT_EQ(s.done, 0u);
    const std::vector<ProgressNote> notes = progress.notes(1);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0].stage, "form factors");
    EXPECT_EQ(notes[0].text, "second");
    EXPECT_TRUE(progress.notes(5).empty());
}

// A solve of several seconds with stderr in a file (not a terminal) says where it stands. One thread keeps
// the work the same on any machine: about 7 s here.
TEST(ProgressLog, SolveWithRedirectedStderrPrintsProgressLines) {
    test::TempDir dir;
    const std::string json = (dir.path() / "cornell.json").string();
    const auto result = test::run_radiosity({"solve", "--rays", "20000", "--threads", "1", "--json", json});
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.err.find("radiosity: form factors: 2516 patches × 20000 rays, about "),
              std::string::npos)
        << result.err;
    EXPECT_NE(result.err.find(" % after "), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("radiosity: form factors: done in "), std::string::npos) << result.err;
    EXPECT_TRUE(plain(result.err)) << result.err;
}

}  // namespace
}  // namespace rad
