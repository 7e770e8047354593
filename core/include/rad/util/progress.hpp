#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace rad {

// What a stage's total counts: exactly the work to do, or a limit the work may stop well short of (a
// solver's step limit), which gives neither a share done nor an estimate of the time left.
enum class ProgressTotal { exact, at_most };

// A short note on a stage, set by the library as the stage begins: what the work is and what it will cost
// ("2516 patches × 2048 rays, about 11 MB"). `stage` is the stage current when it was set.
struct ProgressNote {
    std::string stage;
    std::string text;
};

// One consistent reading of a Progress.
struct ProgressState {
    std::string stage;
    std::uint64_t stage_number = 0;  // counts begin(), so a stage begun again under the same name is new
    std::uint64_t done = 0;
    std::uint64_t total = 0;  // 0: not known
    ProgressTotal kind = ProgressTotal::exact;
    std::size_t notes = 0;  // how many notes have been set so far

    bool share_known() const { return total > 0 && kind == ProgressTotal::exact; }
    double fraction() const;  // done / total, at most 1; 0 when the total is not known
};

// Progress of long work (meshing, form factors, solving): the worker writes it, any thread reads it (the
// terminal's progress bar, the viewer's panel) and may ask the worker to stop. Thread-safe.
class Progress {
  public:
    void begin(const std::string& stage, std::uint64_t total, ProgressTotal kind = ProgressTotal::exact);
    void advance(std::uint64_t amount = 1) { done_ += amount; }
    // Adds a note on the current stage; readers show each note once.
    void note(const std::string& text);

    std::string stage() const;
    double fraction() const;
    ProgressState state() const;
    std::vector<ProgressNote> notes(std::size_t first = 0) const;  // the notes from the `first` on

    void cancel() { cancelled_ = true; }
    bool cancelled() const { return cancelled_; }

  private:
    mutable std::mutex mutex_;
    std::string stage_;
    std::uint64_t stage_number_ = 0;
    ProgressTotal kind_ = ProgressTotal::exact;
    std::vector<ProgressNote> notes_;
    // Atomic so the workers advance without the lock.
    std::atomic<std::uint64_t> done_{0};
    std::atomic<std::uint64_t> total_{0};
    std::atomic<bool> cancelled_{false};
};

// Thrown by long work that saw Progress::cancelled().
struct Cancelled {};

}  // namespace rad
