#pragma once

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace rad {

// Bad input from the user: a file, a line of it, or an option. The program reports the message on one line
// and exits with status 2; anything else that goes wrong exits with status 1.
class InputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// A setting of the library out of range or unsupported. The message names settings as {name} (for
// example "{patch_size} 0.5 would make 10^9 patches; use {patch_size} 2 or larger"): what() reads them as
// plain words ("patch size"), and a program words them its own way (a command line by its flags) through
// worded(). The library never knows how its settings are spelled on a command line.
class SettingError : public InputError {
  public:
    SettingError(std::string setting, std::string message);

    // The setting at fault, as the library names it ("patch_size", "solver", "tolerance", ...).
    const std::string& setting() const { return setting_; }
    // "{setting}: message", each {name} replaced by name_of(name).
    std::string worded(const std::function<std::string(std::string_view)>& name_of) const;

  private:
    std::string setting_;
    std::string message_;
};

// The form-factor pass would need more memory than its budget: the figures, for the program to word its
// advice (a coarser patch size, or a larger budget). The message states the need and the budget only.
class MemoryBudgetError : public SettingError {
  public:
    MemoryBudgetError(std::string message, std::size_t needed_bytes, std::size_t budget_bytes,
                      std::size_t patches, double coarser_patch_size)
        : SettingError("max_memory", std::move(message)),
          needed_bytes(needed_bytes),
          budget_bytes(budget_bytes),
          patches(patches),
          coarser_patch_size(coarser_patch_size) {}

    std::size_t needed_bytes;
    std::size_t budget_bytes;
    std::size_t patches;
    double coarser_patch_size;  // the smallest patch size whose pass would fit; 0 when none was found
};

}  // namespace rad
