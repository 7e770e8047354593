#pragma once

#include <cstddef>

namespace rad {

// Starts a new measurement of the process's peak resident memory (Linux resets it when "5" is written to
// /proc/self/clear_refs), so that one process can measure runs one after another. False where it cannot;
// then peak_resident_bytes is the peak since the process started.
bool reset_peak_resident();

// The peak resident memory since the last reset (VmHWM), or since the start (getrusage) where the kernel
// does not report VmHWM.
std::size_t peak_resident_bytes();

}  // namespace rad
