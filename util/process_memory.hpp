#pragma once
// The process's peak resident memory (Linux VmHWM), resettable so each benchmark row reports
// its own peak rather than the run's so far: the memory figure of the CPU renderers.
#include <cstddef>

namespace lfd {

// Resets the peak to the current resident size (/proc/self/clear_refs, Linux >= 4.0); does
// nothing where that is not possible.
void reset_peak_rss();

// Peak resident bytes since the last reset (or since the start), from /proc/self/status, else
// getrusage's ru_maxrss (never reset).
size_t peak_rss_bytes();

}  // namespace lfd
