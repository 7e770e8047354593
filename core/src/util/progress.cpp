#include "rad/util/progress.hpp"

#include <algorithm>

namespace rad {

double ProgressState::fraction() const {
    if (total == 0) return 0.0;
    return std::min(1.0, static_cast<double>(done) / static_cast<double>(total));
}

void Progress::begin(const std::string& stage, std::uint64_t total, ProgressTotal kind) {
    std::lock_guard lock(mutex_);
    stage_ = stage;
    ++stage_number_;
    kind_ = kind;
    done_ = 0;
    total_ = total;
}

void Progress::note(const std::string& text) {
    std::lock_guard lock(mutex_);
    notes_.push_back({stage_, text});
}

std::string Progress::stage() const {
    std::lock_guard lock(mutex_);
    return stage_;
}

double Progress::fraction() const {
    const std::uint64_t total = total_;
    return total == 0 ? 0.0 : static_cast<double>(done_.load()) / static_cast<double>(total);
}

ProgressState Progress::state() const {
    std::lock_guard lock(mutex_);
    ProgressState s;
    s.stage = stage_;
    s.stage_number = stage_number_;
    s.done = done_;
    s.total = total_;
    s.kind = kind_;
    s.notes = notes_.size();
    return s;
}

std::vector<ProgressNote> Progress::notes(std::size_t first) const {
    std::lock_guard lock(mutex_);
    if (first >= notes_.size()) return {};
    return {notes_.begin() + static_cast<std::ptrdiff_t>(first), notes_.end()};
}

}  // namespace rad
